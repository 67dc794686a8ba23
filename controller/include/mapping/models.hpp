#pragma once
// Inverse sensor models that turn one lidar scan into log-odds updates (DESIGN §6).
//
//   cell  the classroom sub-cell model (default). Only the robot's own cell is updated.
//         The beams nearest to world N, E, S, W decide, per side, wall or opening:
//           wall     band middle and the band's two corners  p_occ,
//                    sub-cells strictly between centre and band middle  p_free
//           opening  band middle and the sub-cells between centre and it  p_free
//         The centre is always free. A side whose beam reading is invalid is not updated.
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
#include <string_view>
#include <vector>

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/scan.hpp"
#include "mapping/sensor_model.hpp"

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

// mark_scan, then update.apply(grid, model). Returns how many sub-cells were updated.
std::size_t integrate_scan(const MappingOptions &options, OccupancyGrid &grid,
                           const LidarScan &scan, Cell robot_cell, const SensorModel &model,
                           ScanUpdate &update);

// Exact grid traversal (Amanatides & Woo, 1987). Calls visit(SubCell s, double exit_m) for
// every sub-cell the ray from `from` along the unit direction (dir_x, dir_y) passes through,
// in order, starting with the sub-cell containing `from`; exit_m is the path length (m) at
// which the ray leaves s. Stops when visit returns false or the ray leaves the grid; does
// nothing when `from` is outside the grid. A ray through a sub-cell corner exactly steps
// diagonally: the two sub-cells beside the corner are touched in a point, not crossed.
template <typename Visit>
void trace_ray(const GridGeometry &g, Point from, double dir_x, double dir_y, Visit &&visit) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double size = g.subcell_size_m();
  const double px = (from.x_m - g.origin.x_m) / size;
  const double py = (from.y_m - g.origin.y_m) / size;
  const int width = g.width_subcells();
  const int height = g.height_subcells();
  if (!(px >= 0.0 && py >= 0.0 && px < width && py < height)) return;
  int x = static_cast<int>(px);
  int y = static_cast<int>(py);
  const int step_x = dir_x > 0.0 ? 1 : (dir_x < 0.0 ? -1 : 0);
  const int step_y = dir_y > 0.0 ? 1 : (dir_y < 0.0 ? -1 : 0);
  const double delta_x = step_x != 0 ? size / std::abs(dir_x) : inf;
  const double delta_y = step_y != 0 ? size / std::abs(dir_y) : inf;
  double next_x = step_x > 0 ? (x + 1 - px) * delta_x : (step_x < 0 ? (px - x) * delta_x : inf);
  double next_y = step_y > 0 ? (y + 1 - py) * delta_y : (step_y < 0 ? (py - y) * delta_y : inf);
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
