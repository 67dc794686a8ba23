#pragma once
// The room map: a plain numCells grid of log-odds over a boundary in metres, for a robot in
// an arena (no maze lattice, no sub-cells), and the marks each set-up makes on it in a scan.
//
//   cells_x x cells_y square cells of cell_m; cell (i, j) covers
//   [x_start + i cell_m, x_start + (i + 1) cell_m) x [y_start + j cell_m, ...); row 0 the south
//   row; stored at j * cells_x + i (a LogOddsGrid, sensing/bump_depth_marks.hpp).
//
// A scan gathers marks (MetricMarks) and then applies them: each marked cell gets exactly one
// update l <- l + l(p) - l(prior), the strongest level winning (occupied over free), clamped
// when the sensor model clamps. The set-ups' marks:
//
//   lidar  every beam traced through the cells (Amanatides & Woo, mapping/traversal.hpp): the
//          cells before the hit free (p_free), the hit's cell occupied (p_occ); a beam with no
//          return frees up to max range; an invalid one marks nothing.
//   pie    each IR reading's slices (sensing/pie_slice.hpp, as `demo pie` draws them): a cell
//          whose corners or centre fall in the contact slice only is occupied (0.7), else in
//          the clear slice free (0.4). A reading within two of its errors of max range
//          (is_no_return) is clear, not a contact: the noise near max range would otherwise
//          draw phantom walls at 1.5 m all round.
//   cone   IR or sonar: the cone's cells (sensing/cone_cells.hpp, the lecture's sweep) of the arc
//          d (1 - eps) ... d (1 + eps) occupied (p_occ), the same sweep of the cone inside,
//          0 ... d (1 - eps) - INC, free (p_free). Nothing seen: an IR frees the cone up to
//          kConeNoReturnReach of max range; a sonar (its echo may be lost at a slant) marks
//          nothing.
//   bump, depth  the homework's numbers exactly: apply_bump_depth_marks
//          (sensing/bump_depth_marks.hpp) on this grid (base 10: +5 / -0.368 / -0.176), as
//          `map-log` marks a pose log, so `map-log` on a run's trace gives the run's grid.
//
// The body: for a set-up whose nothing-seen marks nothing (the sonar cone), a cell the
// robot's body has covered is observed free, as the bump homework's robot cell is (the robot
// stood there): the first step the body covers it, one free update (observe_by_body); a
// touch or a wedge, one occupied update of the cell ahead of the body (observe_contact).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "sensing/bump_depth_marks.hpp"
#include "sensing/range_models.hpp"
#include "sensing/scan.hpp"

namespace sensing {

struct MetricBoundary {
  double x_start_m = 0.0, x_end_m = 0.0, y_start_m = 0.0, y_end_m = 0.0;
  double width_m() const { return x_end_m - x_start_m; }
  double height_m() const { return y_end_m - y_start_m; }
};

struct MetricGridSpec {
  MetricBoundary boundary;  // the grid's extent: exactly cells_x * cell_m by cells_y * cell_m
  int cells_x = 0;
  int cells_y = 0;
  double cell_m = 0.0;
};

inline constexpr int kMaxMetricCellsPerSide = 20000;
inline constexpr std::uint64_t kMaxMetricMapBytes = std::uint64_t{1} << 30;  // 1 GiB

// --cells X,Y over a boundary: the cells must be square (within 1e-9 relative), else an
// error naming both sizes and the --cells or --resolution that would fit.
MetricGridSpec metric_grid_from_cells(const MetricBoundary &boundary, int cells_x, int cells_y);
// --resolution M: ceil(width / M) x ceil(height / M) cells from the boundary's south-west
// corner (the grid may reach past the east and north edges by less than a cell).
MetricGridSpec metric_grid_from_resolution(const MetricBoundary &boundary, double cell_m);
// Throws common::InputError: a boundary not finite or of no width or height, cells outside
// 1 ... kMaxMetricCellsPerSide a side, a cell size not positive, or a map (its values and a scan's
// marks) above max_bytes, saying how much it would take.
void validate(const MetricGridSpec &spec, std::uint64_t max_bytes = kMaxMetricMapBytes);
// Bytes the map of this spec takes.
std::uint64_t metric_map_bytes(const MetricGridSpec &spec);

struct MetricCell {
  int i = 0;
  int j = 0;
  friend constexpr bool operator==(const MetricCell &, const MetricCell &) = default;
};

class MetricMap {
 public:
  // Validates both (common::InputError) before allocating.
  MetricMap(const MetricGridSpec &spec, const mapping::SensorModel &model);

  const MetricGridSpec &spec() const { return spec_; }
  const mapping::SensorModel &model() const { return model_; }
  int cells_x() const { return spec_.cells_x; }
  int cells_y() const { return spec_.cells_y; }
  double cell_m() const { return spec_.cell_m; }
  std::size_t size() const { return grid_.log_odds.size(); }

  bool contains(MetricCell c) const { return c.i >= 0 && c.j >= 0 && c.i < spec_.cells_x && c.j < spec_.cells_y; }
  std::size_t index(MetricCell c) const {
    return static_cast<std::size_t>(c.j) * static_cast<std::size_t>(spec_.cells_x) + static_cast<std::size_t>(c.i);
  }
  MetricCell cell_of_index(std::size_t flat) const {
    return {static_cast<int>(flat % static_cast<std::size_t>(spec_.cells_x)),
            static_cast<int>(flat / static_cast<std::size_t>(spec_.cells_x))};
  }
  // The cell holding a point, or nothing outside the grid.
  std::optional<MetricCell> cell_at(mapping::Point p) const;
  mapping::Point centre_of(MetricCell c) const;

  double log_odds(MetricCell c) const { return grid_.log_odds[index(c)]; }
  double log_odds_at(std::size_t flat) const { return grid_.log_odds[flat]; }
  double probability_at(std::size_t flat) const { return model_.probability_of(grid_.log_odds[flat]); }
  // Never updated: still exactly l(prior).
  bool unobserved_at(std::size_t flat) const { return grid_.log_odds[flat] == model_.prior_log_odds(); }

  // The body has covered this cell for the first time: one free update l <- l + l(p_free) -
  // l(prior) (clamped when the model clamps). Counts the cells no reading had observed.
  void observe_by_body(std::size_t flat);
  // The body touched something in this cell: one occupied update (l(p_occ) - l(prior)).
  void observe_contact(std::size_t flat);
  // A scan's marks (MetricMarks::apply) or a touch (observe_contact) have marked this cell
  // occupied at least once: a beam ended in it, a cone's arc or a contact lay on it. It holds
  // a surface, whatever its log-odds say now (a cell the face of an obstacle crosses is hit by
  // the beams that meet the face and crossed by those that graze it).
  bool marked_occupied_at(std::size_t flat) const { return marked_occupied_[flat]; }
  // Cells whose first observation was the body's.
  std::size_t body_observed() const { return body_observed_; }
  // Updates (apply, observe_by_body, observe_contact) that left an observed cell exactly at
  // l(prior) again, evidence for and against cancelling out: unobserved_at says it again.
  std::size_t back_to_prior() const { return back_to_prior_; }

  // The grid of log-odds, and the bump and depth options with this grid's boundary, cells
  // and prior in base 10 (the bump and depth set-ups' homework numbers).
  const LogOddsGrid &log_grid() const { return grid_; }
  LogOddsGrid &log_grid() { return grid_; }
  BumpDepthOptions bump_depth_options() const;
  // The grid as a 1 x 1 sub-cell geometry (the traversal's).
  const mapping::GridGeometry &geometry() const { return geometry_; }

 private:
  MetricGridSpec spec_;
  const mapping::SensorModel &model_;
  mapping::GridGeometry geometry_;
  LogOddsGrid grid_;
  std::vector<bool> marked_occupied_;
  std::size_t body_observed_ = 0;
  std::size_t back_to_prior_ = 0;
  // Sets a cell's log-odds, counting a return to l(prior).
  void set_log_odds(std::size_t flat, double value);
  friend class MetricMarks;
};

// One scan's marks: per cell the strongest level (0 strongest). apply() gives each marked
// cell one update l <- clamp(l + l(p of its level) - l(prior)) and returns how many.
class MetricMarks {
 public:
  // Levels 0 occupied (p_occ), 1 free (p_free).
  MetricMarks(double p_occupied, double p_free) : level_p_{p_occupied, p_free} {}
  void mark(const MetricMap &map, MetricCell c, int level);
  void mark(const MetricMap &map, mapping::Point p, int level);
  std::size_t apply(MetricMap &map);
  bool empty() const { return marked_.empty(); }
  // This scan's marked cells and their levels (the tests').
  int level_of(const MetricMap &map, MetricCell c) const;

 private:
  double level_p_[2];
  std::vector<std::uint8_t> level_;   // per cell, kUnmarked between scans
  std::vector<std::size_t> marked_;
  static constexpr std::uint8_t kUnmarked = 255;
};

inline constexpr int kMetricOccupied = 0;
inline constexpr int kMetricFree = 1;

// Marks one lidar scan (origin and yaw of the sensor, the Webots beam order).
void mark_metric_lidar(const MetricMap &map, const LidarScan &scan, MetricMarks &marks);
// Marks one reading of every IR sensor with the pie slices: beta and alpha from `options`
// (pie_half_angle_rad, pie_contact_m). Use MetricMarks(kPieOccupiedP, kPieFreeP).
void mark_metric_pie(const MetricMap &map, const RangeModelOptions &options, std::span<const RangeReading> readings,
                   MetricMarks &marks);
// Marks one reading of every IR or sonar sensor with the cone sweep (`options` unused: the
// cone's own width is each sensor's aperture).
void mark_metric_cone(const MetricMap &map, const RangeModelOptions &options, std::span<const RangeReading> readings,
                      MetricMarks &marks);

}  // namespace sensing
