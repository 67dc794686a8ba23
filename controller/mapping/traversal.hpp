#pragma once
// Exact grid traversal (Amanatides & Woo, 1987) over the sub-cells of a GridGeometry: the
// reference walk the ray model's kernel (sensing/ray_kernel.hpp) reproduces bit for bit, and
// the one the depth model and tools use.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"

namespace mapping {

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
