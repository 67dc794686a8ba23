#pragma once
// Inverse sensor models that turn one lidar scan into log-odds updates (DESIGN §6).
//
//   cell  the classroom sub-cell model (default). Only the robot's own cell is updated.
//         The beams nearest to world N, E, S, W decide, per side, wall or opening:
//           wall     band middle and the band's two corners  p_occ,
//                    sub-cells strictly between centre and band middle  p_free
//           opening  band middle and the sub-cells between centre and it  p_free
//         The centre is always free. A side whose beams are invalid, or split evenly
//         between wall and opening, is not updated.
//         K = 3, walls N and W, openings E and S, defaults (l(0.6) = 0.41, l(0.3) = -0.85):
//             +0.41 +0.41 +0.41
//             +0.41 -0.85 -0.85
//             +0.41 -0.85 +0.00
//   ray   every beam traced through the sub-cells it crosses (Amanatides-Woo): p_occ at
//         the hit sub-cell and hit_depth sub-cells behind it, nothing beyond; before the hit,
//         p_free for the interior sub-cells it crosses and, where it crosses a cell side, for
//         the two band sub-cells beside the crossing. A band stands for its cell side, and a
//         beam says a side is open only by crossing it: one running along a band without
//         crossing the side leaves the band alone (a 12 mm wall fills 4 % of a 1/3 m
//         sub-cell; freeing bands along corridors would erase the walls). A beam with no
//         return frees the same way up to max range (unless ignore_no_return). Beams stop
//         where they leave the grid; leaving it crosses the outer side.
//
// Both gather marks in a ScanUpdate (occupied wins, one update per sub-cell per scan) and
// apply them with the SensorModel's increments, so every sensor option holds.

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/scan.hpp"
#include "mapping/sensor_model.hpp"
#include "mapping/walls.hpp"

namespace mapping {

// bump, depth, pie and cone read bumpers or range sensors (mapping/range_models.hpp).
enum class ModelKind { cell, ray, bump, depth, pie, cone };

// True for the models that read a lidar scan (cell, ray).
constexpr bool uses_lidar(ModelKind kind) { return kind == ModelKind::cell || kind == ModelKind::ray; }

std::string_view to_string(ModelKind kind);
// "cell", "ray", "bump", "depth", "pie" or "cone"; throws common::InputError naming --model and the choices otherwise.
ModelKind parse_model(std::string_view name);

struct MappingOptions {
  ModelKind kind = ModelKind::cell;
  // cell: a side is a wall when its beam returns closer than the distance from the sensor
  // to that side plus wall_margin * cell size (0.5 + 0.25 cells from a centred robot).
  double wall_margin = 0.25;
  // ray: sub-cells behind the hit sub-cell also marked occupied (--hit-depth), 0 ... 8.
  int hit_depth = 0;
  // ray: beams with no return update nothing instead of freeing up to max range.
  bool ignore_no_return = false;
};

// Throws common::InputError when an option is out of range (wall_margin in [0, 0.5)).
void validate(const MappingOptions &options);

// Gathers the scan's marks into `update` (nothing applied). robot_cell is the cell the robot
// stands in (used by the cell model; must be inside the grid).
void mark_scan(const MappingOptions &options, const OccupancyGrid &grid, const LidarScan &scan,
               Cell robot_cell, ScanUpdate &update);

// The cell model's reading of side h of cell c from a scan taken in c (the median of the
// beams within 2.5 degrees of the side's direction): wall when it returns closer than the
// side plus wall_margin cells, open when further or no return, unknown without a valid
// beam or when an even count of readings splits evenly between the two. The cell model marks by it; the controller checks a side its grid calls open
// against it before driving through (a wall seen from half a cell beats a band freed by a
// faulty beam from afar).
SideState read_cell_side(const MappingOptions &options, const OccupancyGrid &grid, const LidarScan &scan,
                         Cell c, Heading h);

// mark_scan, then update.apply(grid, model). Returns how many sub-cells were updated.
std::size_t integrate_scan(const MappingOptions &options, OccupancyGrid &grid,
                           const LidarScan &scan, Cell robot_cell, const SensorModel &model,
                           ScanUpdate &update);

// Where an Amanatides-Woo traversal starts: the sub-cell holding `from`, the step
// direction on each axis, the path length (m) across one sub-cell on each axis, and the
// path length to the first sub-cell boundary on each axis (infinity on an axis the ray
// does not move along). Nothing when `from` is outside the grid.
struct TraversalStart {
  int x, y;
  int step_x, step_y;
  double delta_x, delta_y;
  double next_x, next_y;
};

// The first half of start_traversal, the same for every direction from one point: `from`
// in sub-cell units from the grid's origin, and the sub-cell holding it. Nothing when `from`
// is outside the grid.
struct TraversalOrigin {
  double px, py;
  int x, y;
};

inline std::optional<TraversalOrigin> traversal_origin(const GridGeometry &g, Point from) {
  const double size = g.subcell_size_m();
  const double px = (from.x_m - g.origin.x_m) / size;
  const double py = (from.y_m - g.origin.y_m) / size;
  if (!(px >= 0.0 && py >= 0.0 && px < g.width_subcells() && py < g.height_subcells())) {
    return std::nullopt;
  }
  return TraversalOrigin{px, py, static_cast<int>(px), static_cast<int>(py)};
}

inline TraversalStart start_traversal(const GridGeometry &g, const TraversalOrigin &o,
                                      double dir_x, double dir_y) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double size = g.subcell_size_m();
  const double px = o.px;
  const double py = o.py;
  TraversalStart t;
  t.x = o.x;
  t.y = o.y;
  t.step_x = dir_x > 0.0 ? 1 : (dir_x < 0.0 ? -1 : 0);
  t.step_y = dir_y > 0.0 ? 1 : (dir_y < 0.0 ? -1 : 0);
  t.delta_x = t.step_x != 0 ? size / std::abs(dir_x) : inf;
  t.delta_y = t.step_y != 0 ? size / std::abs(dir_y) : inf;
  t.next_x = t.step_x > 0 ? (t.x + 1 - px) * t.delta_x : (t.step_x < 0 ? (px - t.x) * t.delta_x : inf);
  t.next_y = t.step_y > 0 ? (t.y + 1 - py) * t.delta_y : (t.step_y < 0 ? (py - t.y) * t.delta_y : inf);
  return t;
}

inline std::optional<TraversalStart> start_traversal(const GridGeometry &g, Point from,
                                                     double dir_x, double dir_y) {
  const auto origin = traversal_origin(g, from);
  if (!origin) return std::nullopt;
  return start_traversal(g, *origin, dir_x, dir_y);
}

// Exact grid traversal (Amanatides & Woo, 1987). Calls visit(SubCell s, double exit_m) for
// every sub-cell the ray from `from` along the unit direction (dir_x, dir_y) passes through,
// in order, starting with the sub-cell containing `from`; exit_m is the path length (m) at
// which the ray leaves s. Stops when visit returns false or the ray leaves the grid; does
// nothing when `from` is outside the grid. A ray through a sub-cell corner exactly steps
// diagonally: the two sub-cells beside the corner are touched in a point, not crossed.
template <typename Visit>
void trace_ray(const GridGeometry &g, Point from, double dir_x, double dir_y, Visit &&visit) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const auto start = start_traversal(g, from, dir_x, dir_y);
  if (!start) return;
  const int width = g.width_subcells();
  const int height = g.height_subcells();
  auto [x, y, step_x, step_y, delta_x, delta_y, next_x, next_y] = *start;
  for (;;) {
    const double exit_m = std::min(next_x, next_y);
    if (!visit(SubCell{x, y}, exit_m) || exit_m == inf) return;
    if (next_x <= next_y) {
      x += step_x;
      next_x += delta_x;
    }
    if (next_y <= exit_m) {
      y += step_y;
      next_y += delta_y;
    }
    if (x < 0 || y < 0 || x >= width || y >= height) return;
  }
}

// The sub-cells the segment from `from` to `to` crosses, in order (tests and tools; the
// models use trace_ray without allocating).
std::vector<SubCell> subcells_on_segment(const GridGeometry &g, Point from, Point to);

}  // namespace mapping
