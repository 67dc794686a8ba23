#include "mapping/occupancy_grid.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>

#include <fmt/format.h>

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

double yaw_rad(Heading h) {
  switch (h) {
    case Heading::east: return 0.0;
    case Heading::north: return std::numbers::pi / 2;
    case Heading::west: return std::numbers::pi;
    case Heading::south: return -std::numbers::pi / 2;
  }
  return 0.0;
}

char to_char(Heading h) {
  switch (h) {
    case Heading::north: return 'N';
    case Heading::east: return 'E';
    case Heading::south: return 'S';
    case Heading::west: return 'W';
  }
  return '?';
}

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

std::size_t ScanUpdate::apply(OccupancyGrid &grid, const SensorModel &model) {
  return apply(grid, model, model.free_increment(), model.occupied_increment());
}

namespace {

// Gives each listed sub-cell not yet marked this scan one update l <- clamp(l + delta)
// (the arithmetic of mapping::apply, inlined), marking it `mark`; `skip` is a second mark
// that also means "already updated" (the occupied mark when applying the free list).
template <bool kClamp>
std::size_t apply_list(std::span<const std::size_t> list, float *values, std::uint32_t *marks,
                       std::size_t size, std::uint32_t mark, std::uint32_t skip, double delta,
                       double lo, double hi) {
  std::size_t updated = 0;
  for (const std::size_t i : list) {
    if (i >= size) continue;
    const std::uint32_t m = marks[i];
    if (m == mark || m == skip) continue;
    marks[i] = mark;
    const double sum = static_cast<double>(values[i]) + delta;
    values[i] = static_cast<float>(kClamp ? std::clamp(sum, lo, hi) : sum);
    ++updated;
  }
  return updated;
}

std::size_t apply_list(std::span<const std::size_t> list, float *values, std::uint32_t *marks,
                       std::size_t size, std::uint32_t mark, std::uint32_t skip, double delta,
                       const std::optional<Clamp> &clamp) {
  if (clamp) {
    return apply_list<true>(list, values, marks, size, mark, skip, delta, clamp->min, clamp->max);
  }
  return apply_list<false>(list, values, marks, size, mark, skip, delta, 0.0, 0.0);
}

}  // namespace

std::size_t ScanUpdate::apply(OccupancyGrid &grid, const SensorModel &model,
                              double free_increment, double occupied_increment) {
  if (grid.marks_.size() != grid.values_.size()) grid.marks_.assign(grid.values_.size(), 0);
  if (grid.epoch_ >= std::numeric_limits<std::uint32_t>::max() - 2) {
    std::fill(grid.marks_.begin(), grid.marks_.end(), 0);
    grid.epoch_ = 0;
  }
  const std::uint32_t occupied_mark = ++grid.epoch_;
  const std::uint32_t free_mark = ++grid.epoch_;
  const auto &clamp = model.options().clamp;
  float *values = grid.values_.data();
  std::uint32_t *marks = grid.marks_.data();
  const std::size_t size = grid.values_.size();
  std::size_t updated = apply_list(occupied_, values, marks, size, occupied_mark, occupied_mark,
                                   occupied_increment, clamp);
  updated += apply_list(free_, values, marks, size, free_mark, occupied_mark, free_increment, clamp);
  clear();
  return updated;
}

}  // namespace mapping
