#include "mapping/occupancy_grid.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <cassert>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <span>

#include <fmt/format.h>

#include "common/angles.hpp"
#include "common/error.hpp"
#include "mapping/sensor_model.hpp"

namespace mapping {
namespace {

constexpr std::uint64_t kBytesPerSubcell = sizeof(float) + sizeof(std::uint32_t);

std::string human_bytes(std::uint64_t bytes) {
  const double b = static_cast<double>(bytes);
  if (b >= 1024.0 * 1024 * 1024) return fmt::format("{:.1f} GiB", b / (1024.0 * 1024 * 1024));
  if (b >= 1024.0 * 1024) return fmt::format("{:.1f} MiB", b / (1024.0 * 1024));
  return fmt::format("{:.1f} KiB", b / 1024.0);
}

}  // namespace

std::uint64_t grid_bytes(const GridGeometry &g) {
  return static_cast<std::uint64_t>(g.width_cells) * static_cast<std::uint64_t>(g.height_cells) *
         static_cast<std::uint64_t>(g.subcells) * static_cast<std::uint64_t>(g.subcells) *
         kBytesPerSubcell;
}

void validate(const GridGeometry &g, std::uint64_t max_bytes) {
  if (g.subcells < kMinSubcells || g.subcells > kMaxSubcells || g.subcells % 2 == 0) {
    throw common::InputError(
        fmt::format("--subcells must be odd and between {} and {} (got {})", kMinSubcells,
                    kMaxSubcells, g.subcells));
  }
  if (g.width_cells < 1 || g.height_cells < 1 || g.width_cells > kMaxCellsPerSide ||
      g.height_cells > kMaxCellsPerSide) {
    throw common::InputError(fmt::format("grid size must be 1 to {} cells each way (got {}x{})",
                                         kMaxCellsPerSide, g.width_cells, g.height_cells));
  }
  if (!std::isfinite(g.cell_size_m) || g.cell_size_m <= 0.0) {
    throw common::InputError(
        fmt::format("cell size must be a positive number of metres (got {})", g.cell_size_m));
  }
  if (!std::isfinite(g.origin.x_m) || !std::isfinite(g.origin.y_m)) {
    throw common::InputError("grid origin must be finite");
  }
  const std::uint64_t bytes = grid_bytes(g);
  if (bytes > max_bytes) {
    throw common::InputError(fmt::format(
        "a {}x{} grid with {}x{} sub-cells per cell needs {} of memory (limit {})",
        g.width_cells, g.height_cells, g.subcells, g.subcells, human_bytes(bytes),
        human_bytes(max_bytes)));
  }
}

OccupancyGrid::OccupancyGrid(const GridGeometry &geometry, float initial_log_odds,
                             std::uint64_t max_bytes)
    : geometry_(geometry) {
  validate(geometry_, max_bytes);
  const auto count = static_cast<std::size_t>(geometry_.width_subcells()) *
                     static_cast<std::size_t>(geometry_.height_subcells());
  values_.assign(count, initial_log_odds);
}

CellMatrix OccupancyGrid::cell_matrix(Cell c) const {
  assert(contains(c));
  return CellMatrix(values_.data() + index(c, LocalSubCell{0, 0}), k(), k());
}

std::optional<SubCell> OccupancyGrid::subcell_at(Point p) const {
  const double size = geometry_.subcell_size_m();
  const double fx = std::floor((p.x_m - geometry_.origin.x_m) / size);
  const double fy = std::floor((p.y_m - geometry_.origin.y_m) / size);
  if (!(fx >= 0.0 && fy >= 0.0 && fx < geometry_.width_subcells() &&
        fy < geometry_.height_subcells())) {
    return std::nullopt;  // also rejects NaN
  }
  return SubCell{static_cast<int>(fx), static_cast<int>(fy)};
}

Point OccupancyGrid::centre_of(SubCell s) const {
  const double size = geometry_.subcell_size_m();
  return {geometry_.origin.x_m + (s.x + 0.5) * size, geometry_.origin.y_m + (s.y + 0.5) * size};
}

Point OccupancyGrid::centre_of(Cell c) const {
  const double size = geometry_.cell_size_m;
  return {geometry_.origin.x_m + (c.x + 0.5) * size, geometry_.origin.y_m + (c.y + 0.5) * size};
}

// Flat indices fit the per-scan lists' 32 bits.
static_assert(std::uint64_t{kMaxCellsPerSide} * kMaxCellsPerSide * kMaxSubcells * kMaxSubcells <
              std::numeric_limits<std::uint32_t>::max());

std::uint32_t *ScanUpdate::IndexList::reserve(std::size_t more) {
  if (capacity_ - size_ < more) {
    const std::size_t capacity = std::max(size_ + more, 2 * capacity_);
    auto data = std::make_unique_for_overwrite<std::uint32_t[]>(capacity);
    std::copy(data_.get(), data_.get() + size_, data.get());
    data_ = std::move(data);
    capacity_ = capacity;
  }
  return data_.get() + size_;
}

void ScanUpdate::open_scan(std::size_t grid_size) {
  if (tags_.size() < grid_size + 1) tags_.resize(grid_size + 1, 0);  // and UniqueMarks::spare()
  if (open_) return;
  if (free_tag_ >= std::numeric_limits<std::uint32_t>::max() - 3) {
    std::fill(tags_.begin(), tags_.end(), 0);
    free_tag_ = 0;
  }
  free_tag_ += 3;  // this scan: free_tag_ - 1 ... free_tag_ + 1; the last one's are below
  open_ = true;
}

ScanUpdate::UniqueMarks ScanUpdate::unique_marks(const OccupancyGrid &grid) {
  UniqueMarks marks;
  marks.first_ = !open_;
  open_scan(grid.size());
  marks.spare_ = static_cast<std::uint32_t>(grid.size());
  marks.owner_ = this;
  marks.tags_ = tags_.data();
  marks.free_tag_ = free_tag_;
  marks.occupied_tag_ = free_tag_ + 1;
  marks.stamp_tag_ = free_tag_ - 1;
  return marks;
}

#if defined(__x86_64__) || defined(__i386__)
namespace {

// For each mask of 8 lanes, the lanes set, in order, a byte each: AVX2's left-packing.
constexpr std::array<std::uint64_t, 256> kPackedLanes = [] {
  std::array<std::uint64_t, 256> table{};
  for (unsigned mask = 0; mask < 256; ++mask) {
    unsigned n = 0;
    for (unsigned lane = 0; lane < 8; ++lane) {
      if ((mask >> lane & 1u) != 0) table[mask] |= std::uint64_t{lane} << (8 * n++);
    }
  }
  return table;
}();

}  // namespace

// Eight tags a compare; the stamped ones' indices packed to the front and stored whole.
[[gnu::target("avx2")]] std::uint32_t *ScanUpdate::UniqueMarks::list_stamped(std::uint32_t *out, std::uint32_t first,
                                                                             std::uint32_t last) const {
  std::uint32_t i = first;
  const __m256i stamp = _mm256_set1_epi32(static_cast<int>(stamp_tag_));
  const __m256i listed = _mm256_set1_epi32(static_cast<int>(free_tag_));
  const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  for (; last - i >= 8; i += 8) {
    __m256i tags;
    std::memcpy(&tags, tags_ + i, sizeof tags);
    const __m256i hit = _mm256_cmpeq_epi32(tags, stamp);
    const auto bits = static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(hit)));
    const __m256i now = _mm256_blendv_epi8(tags, listed, hit);
    std::memcpy(tags_ + i, &now, sizeof now);
    const __m256i order = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(kPackedLanes[bits])));
    const __m256i packed = _mm256_permutevar8x32_epi32(
        _mm256_add_epi32(lanes, _mm256_set1_epi32(static_cast<int>(i))), order);
    std::memcpy(out, &packed, sizeof packed);
    out += std::popcount(bits);
  }
  for (; i < last; ++i) {
    const bool stamped = tags_[i] == stamp_tag_;
    *out = i;
    out += stamped ? 1 : 0;
    tags_[i] = stamped ? free_tag_ : tags_[i];
  }
  return out;
}
#else
std::uint32_t *ScanUpdate::UniqueMarks::list_stamped(std::uint32_t *out, std::uint32_t first,
                                                     std::uint32_t last) const {
  for (std::uint32_t i = first; i < last; ++i) {
    const bool stamped = tags_[i] == stamp_tag_;
    *out = i;
    out += stamped ? 1 : 0;
    tags_[i] = stamped ? free_tag_ : tags_[i];
  }
  return out;
}
#endif

void ScanUpdate::clear() {
  free_.clear();
  occupied_.clear();
  free_once_.clear();
  occupied_once_.clear();
  open_ = false;
}

std::size_t ScanUpdate::apply(OccupancyGrid &grid, const SensorModel &model) {
  return apply(grid, model, model.free_increment(), model.occupied_increment());
}

namespace {

// One update l <- clamp(l + delta), the arithmetic of mapping::apply inlined.
template <bool kClamp>
struct Update {
  double delta, lo, hi;
  void operator()(float &value) const {
    const double sum = static_cast<double>(value) + delta;
    value = static_cast<float>(kClamp ? std::clamp(sum, lo, hi) : sum);
  }
};

// The order below makes occupied win and gives each sub-cell one update: occupied listings
// first, each re-tagging its sub-cell occupied; then free listings, skipping sub-cells tagged
// occupied (and, for the lists with duplicates, those already tagged free this scan).
template <bool kClamp>
std::size_t apply_lists(std::span<const std::uint32_t> occupied_once,
                        std::span<const std::size_t> occupied, std::span<const std::uint32_t> free_once,
                        std::span<const std::size_t> free, float *values, std::uint32_t *tags,
                        std::size_t size, std::uint32_t free_tag, Update<kClamp> occupied_update,
                        Update<kClamp> free_update) {
  const std::uint32_t occupied_tag = free_tag + 1;
  std::size_t updated = occupied_once.size();
  for (const std::uint32_t i : occupied_once) occupied_update(values[i]);  // tagged when marked
  for (const std::size_t i : occupied) {
    if (i >= size || tags[i] == occupied_tag) continue;
    tags[i] = occupied_tag;
    occupied_update(values[i]);
    ++updated;
  }
  for (const std::uint32_t i : free_once) {
    if (tags[i] != free_tag) continue;  // occupied since it was listed
    free_update(values[i]);
    ++updated;
  }
  for (const std::size_t i : free) {
    if (i >= size || tags[i] >= free_tag) continue;
    tags[i] = free_tag;
    free_update(values[i]);
    ++updated;
  }
  return updated;
}

}  // namespace

void ScanUpdate::log_marks(std::vector<std::uint32_t> &log, std::size_t grid_size) const {
  log.insert(log.end(), occupied_once_.view().begin(), occupied_once_.view().end());
  log.insert(log.end(), free_once_.view().begin(), free_once_.view().end());
  for (const std::vector<std::size_t> *list : {&occupied_, &free_}) {
    for (const std::size_t i : *list) {
      if (i < grid_size) log.push_back(static_cast<std::uint32_t>(i));
    }
  }
}

std::size_t ScanUpdate::apply(OccupancyGrid &grid, const SensorModel &model,
                              double free_increment, double occupied_increment) {
  open_scan(grid.size());
  const auto &clamp = model.options().clamp;
  float *values = grid.values_.data();
  std::uint32_t *tags = tags_.data();
  const std::size_t size = grid.size();
  std::size_t updated = 0;
  if (clamp) {
    updated = apply_lists<true>(occupied_once_.view(), occupied_, free_once_.view(), free_, values,
                                tags, size, free_tag_, {occupied_increment, clamp->min, clamp->max},
                                {free_increment, clamp->min, clamp->max});
  } else {
    updated = apply_lists<false>(occupied_once_.view(), occupied_, free_once_.view(), free_, values,
                                 tags, size, free_tag_, {occupied_increment, 0.0, 0.0},
                                 {free_increment, 0.0, 0.0});
  }
  if (grid.change_log_.log != nullptr) log_marks(*grid.change_log_.log, size);
  clear();
  return updated;
}

}  // namespace mapping
