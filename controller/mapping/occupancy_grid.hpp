#pragma once
// The occupancy grid: a 4D array of log-odds, H rows x W columns of cells x K x K sub-cells.
//
// Storage: cell (x, y) at row-major cell index y * W + x; the K * K sub-cells of one cell are
// contiguous, row i (from the north) then column j (from the west). So one cell's matrix is
// a K x K row-major block that prints north-up as it is stored.
//
// Values are log-odds in the sensor model's base, starting at l(prior).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "mapping/grid_types.hpp"

namespace mapping {

// Where the grid lies in the world and how it is cut.
struct GridGeometry {
  int width_cells = 0;   // W, 1 ... 4096
  int height_cells = 0;  // H, 1 ... 4096
  int subcells = 3;      // K, odd, 3 ... 9
  double cell_size_m = 1.0;
  Point origin;          // world position of the south-west corner of cell (0, 0)

  double subcell_size_m() const { return cell_size_m / subcells; }
  int width_subcells() const { return width_cells * subcells; }
  int height_subcells() const { return height_cells * subcells; }
};

inline constexpr int kMinSubcells = 3;
inline constexpr int kMaxSubcells = 9;
inline constexpr int kMaxCellsPerSide = 4096;

// Bytes the grid of this geometry takes (values, and the per-scan update marker its
// ScanUpdate keeps).
std::uint64_t grid_bytes(const GridGeometry &geometry);

// Throws common::InputError when the geometry is unusable: K even or outside 3 ... 9, a side
// outside 1 ... 4096 cells, a cell size that is not a positive finite number, or a grid that
// would take more than max_bytes (the message says how much it would take).
void validate(const GridGeometry &geometry, std::uint64_t max_bytes);

inline constexpr std::uint64_t kDefaultMaxGridBytes = std::uint64_t{4} << 30;  // 4 GiB

using CellMatrix = Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;

class OccupancyGrid {
 public:
  // Validates the geometry (throws common::InputError) before allocating anything.
  OccupancyGrid(const GridGeometry &geometry, float initial_log_odds,
                std::uint64_t max_bytes = kDefaultMaxGridBytes);

  const GridGeometry &geometry() const { return geometry_; }
  int width() const { return geometry_.width_cells; }
  int height() const { return geometry_.height_cells; }
  int k() const { return geometry_.subcells; }

  bool contains(Cell c) const {
    return c.x >= 0 && c.y >= 0 && c.x < geometry_.width_cells && c.y < geometry_.height_cells;
  }
  bool contains(SubCell s) const {
    return s.x >= 0 && s.y >= 0 && s.x < geometry_.width_subcells() &&
           s.y < geometry_.height_subcells();
  }

  // Flat index of a sub-cell in the 4D array; the argument must be inside the grid.
  std::size_t index(Cell c, LocalSubCell s) const {
    const auto k = static_cast<std::size_t>(geometry_.subcells);
    const auto cell = static_cast<std::size_t>(c.y) * static_cast<std::size_t>(geometry_.width_cells) +
                      static_cast<std::size_t>(c.x);
    return (cell * k + static_cast<std::size_t>(s.i)) * k + static_cast<std::size_t>(s.j);
  }
  std::size_t index(SubCell s) const { return index(cell_of(s, k()), local_of(s, k())); }

  float at(Cell c, LocalSubCell s) const { return values_[index(c, s)]; }
  float at(SubCell s) const { return values_[index(s)]; }
  float &at(Cell c, LocalSubCell s) { return values_[noted(index(c, s))]; }
  float &at(SubCell s) { return values_[noted(index(s))]; }
  float at_index(std::size_t flat) const { return values_[flat]; }
  float &at_index(std::size_t flat) { return values_[noted(flat)]; }

  // The change log, for an observer that must know what each step changed without comparing
  // the whole grid (a run's history for its replay): while set, every sub-cell written through
  // the non-const accessors or a ScanUpdate is appended to *log as its flat index (repeats,
  // and writes that changed nothing, included). The log's owner reads and empties it; the
  // grid only appends. Null (the default): nothing is logged.
  // A copy or a moved-to grid logs nothing (the log belongs to the grid it was set on).
  void set_change_log(std::vector<std::uint32_t> *log) { change_log_.log = log; }

  // One cell's K x K log-odds, row 0 = north band, column 0 = west band.
  CellMatrix cell_matrix(Cell c) const;

  // The sub-cell containing a world point, or nothing when the point is outside the grid.
  std::optional<SubCell> subcell_at(Point p) const;
  // The world position of a sub-cell's centre.
  Point centre_of(SubCell s) const;
  Point centre_of(Cell c) const;

  std::span<const float> values() const { return values_; }
  std::size_t size() const { return values_.size(); }

 private:
  friend class ScanUpdate;
  std::size_t noted(std::size_t flat) {
    if (change_log_.log != nullptr) change_log_.log->push_back(static_cast<std::uint32_t>(flat));
    return flat;
  }
  // Not carried by a copy or a move.
  struct ChangeLog {
    std::vector<std::uint32_t> *log = nullptr;
    ChangeLog() = default;
    ChangeLog(const ChangeLog &) {}
    ChangeLog &operator=(const ChangeLog &) {
      log = nullptr;
      return *this;
    }
  };
  GridGeometry geometry_;
  std::vector<float> values_;
  ChangeLog change_log_;
};

class SensorModel;

// Gather, then apply (ARCHITECTURE.md, Conventions): a scan marks the sub-cells it saw free and the ones it
// saw occupied; occupied wins; apply() then gives each marked sub-cell exactly one update.
// Marks outside the grid are ignored. One ScanUpdate serves many scans; apply() clears it.
//
// Two ways to mark, mixable within a scan: mark_free/mark_occupied take any index, and
// apply() drops duplicates; unique_marks(grid) hands a hot loop the per-scan marker, so it
// lists each sub-cell once while marking (the ray model, where all beams of a scan cross the
// sub-cells near the robot).
class ScanUpdate {
 public:
  void mark_free(std::size_t flat_index) { free_.push_back(flat_index); }
  void mark_occupied(std::size_t flat_index) { occupied_.push_back(flat_index); }

  // Marking without duplicates, for one grid and the scan under way. Flat indices must be
  // inside the grid. Room for `more` marks of a kind is made by reserve_free/reserve_occupied,
  // which return where the next mark goes; the caller writes through that pointer with
  // mark_free/mark_occupied below and hands the end back with commit_free/commit_occupied.
  class UniqueMarks {
   public:
    std::uint32_t *reserve_free(std::size_t more) { return owner_->free_once_.reserve(more); }
    std::uint32_t *reserve_occupied(std::size_t more) { return owner_->occupied_once_.reserve(more); }
    void commit_free(const std::uint32_t *end) { owner_->free_once_.commit(end); }
    void commit_occupied(const std::uint32_t *end) { owner_->occupied_once_.commit(end); }

    // When `wanted`, lists sub-cell i at *out unless this scan already listed it; returns
    // the next slot. Branch-free: the slot is written either way, kept only when i is new.
    std::uint32_t *mark_free(std::uint32_t *out, std::uint32_t i, bool wanted = true) const {
      return mark_free_if(out, i, 0u - static_cast<std::uint32_t>(wanted));
    }
    // mark_free with `wanted` as a mask: all ones to mark, zero not to.
    std::uint32_t *mark_free_if(std::uint32_t *out, std::uint32_t i, std::uint32_t wanted_mask) const {
      const std::uint32_t seen = tags_[i];
      // Tags only grow within a scan: an older tag becomes free_tag_, while free_tag_ and
      // occupied_tag_ (free_tag_ + 1) stay; not wanted, the tag stays whatever it is. So the
      // new tag is max(seen, free_tag_ & wanted_mask), written as a select of two values the
      // compiler makes a conditional move (std::max became a jump, and whether a sub-cell is
      // new is a coin toss a branch predictor loses).
      const std::uint32_t want = free_tag_ & wanted_mask;
      const bool fresh = seen < want;
      *out = i;
      tags_[i] = fresh ? want : seen;
      return out + (fresh ? 1 : 0);
    }
    // Stamping, for a loop that marks so many sub-cells twice or more that listing each as it
    // goes would cost more than looking for them after: stamp_free_if marks sub-cell i free
    // (when wanted_mask is all ones) without listing it; list_stamped then lists, from *out
    // on, the sub-cells of flat indices [first, last) stamped and not yet listed this scan,
    // as mark_free would have, writing up to kStampSlack slots past the last it lists. Every
    // stamp of a scan must be listed before apply(). On x86 it needs AVX2 (the stamping kernel
    // runs only there).
    void stamp_free_if(std::uint32_t i, std::uint32_t wanted_mask) const {
      const std::uint32_t seen = tags_[i];
      const std::uint32_t want = stamp_tag_ & wanted_mask;  // the stamp is below this scan's other tags
      tags_[i] = seen < want ? want : seen;
    }
    std::uint32_t *list_stamped(std::uint32_t *out, std::uint32_t first, std::uint32_t last) const;
    // When no sub-cell is tagged yet this scan (no marks through UniqueMarks before these),
    // and until the first mark_free or mark_occupied, a stamp may be a plain store: stamp(i)
    // stamps sub-cell i, and stamp(spare()) nothing (a slot past the grid's tags).
    bool first_of_scan() const { return first_; }
    void stamp(std::uint32_t i) const { tags_[i] = stamp_tag_; }
    std::uint32_t spare() const { return spare_; }
    static constexpr std::size_t kStampSlack = 8;
    // Occupied wins: a sub-cell already listed free is listed again here, and apply() skips
    // its free listing.
    std::uint32_t *mark_occupied(std::uint32_t *out, std::uint32_t i) const {
      const bool fresh = tags_[i] != occupied_tag_;
      *out = i;
      tags_[i] = occupied_tag_;
      return out + (fresh ? 1 : 0);
    }

   private:
    friend class ScanUpdate;
    ScanUpdate *owner_ = nullptr;
    std::uint32_t *tags_ = nullptr;
    std::uint32_t free_tag_ = 0;
    std::uint32_t occupied_tag_ = 0;
    std::uint32_t stamp_tag_ = 0;
    std::uint32_t spare_ = 0;
    bool first_ = false;
  };
  UniqueMarks unique_marks(const OccupancyGrid &grid);

  // Applies every mark once and returns how many sub-cells were updated.
  std::size_t apply(OccupancyGrid &grid, const SensorModel &model);

  // Applies custom increments (models with their own p's): occupied wins over free.
  std::size_t apply(OccupancyGrid &grid, const SensorModel &model, double free_increment,
                    double occupied_increment);

  bool empty() const {
    return free_.empty() && occupied_.empty() && free_once_.empty() && occupied_once_.empty();
  }
  // Drops this scan's marks unapplied.
  void clear();

 private:
  // A list of flat indices a hot loop writes through a raw pointer (no per-mark capacity
  // check, no zero-filling on growth).
  class IndexList {
   public:
    std::uint32_t *reserve(std::size_t more);
    void commit(const std::uint32_t *end) { size_ = static_cast<std::size_t>(end - data_.get()); }
    std::span<const std::uint32_t> view() const { return {data_.get(), size_}; }
    bool empty() const { return size_ == 0; }
    void clear() { size_ = 0; }

   private:
    std::unique_ptr<std::uint32_t[]> data_;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;
  };

  void open_scan(std::size_t grid_size);
  // Appends every sub-cell this scan marked inside the grid to a grid's change log.
  void log_marks(std::vector<std::uint32_t> &log, std::size_t grid_size) const;

  std::vector<std::size_t> free_;      // mark_free, duplicates allowed
  std::vector<std::size_t> occupied_;  // mark_occupied, duplicates allowed
  IndexList free_once_;                // UniqueMarks, each sub-cell once
  IndexList occupied_once_;
  // The per-scan update marker: per sub-cell, the tag of the last scan that listed it.
  // A scan's tags are free_tag_ - 1 (stamped), free_tag_ and free_tag_ + 1 (occupied); every
  // older tag is smaller.
  std::vector<std::uint32_t> tags_;
  std::uint32_t free_tag_ = 0;
  bool open_ = false;  // free_tag_ belongs to the scan under way
};

}  // namespace mapping
