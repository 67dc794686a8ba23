#include "maze/world/truth_raster.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include <fmt/format.h>

#include "common/cell_clearance.hpp"
#include "common/error.hpp"

namespace maze {

namespace {

// The projection of a convex polygon's corners on the axis (ax, ay): [lo, hi].
template <std::size_t N>
std::pair<double, double> project(const std::array<ArenaPoint, N> &corners, double ax, double ay) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const ArenaPoint &p : corners) {
    const double d = p.x_m * ax + p.y_m * ay;
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return {lo, hi};
}

// Whether the obstacle and the box [x0, x1] x [y0, y1] share an area (separating axes: the
// box's two and the obstacle's two; intervals that only touch do not overlap).
bool overlaps(const Obstacle &o, const std::array<ArenaPoint, 4> &corners, double x0, double y0, double x1,
              double y1) {
  const auto b = o.bounds();
  if (!(std::max(b[0], x0) < std::min(b[2], x1)) || !(std::max(b[1], y0) < std::min(b[3], y1))) return false;
  if (o.axis_aligned()) return true;
  const std::array<ArenaPoint, 4> box{ArenaPoint{x0, y0}, ArenaPoint{x1, y0}, ArenaPoint{x1, y1}, ArenaPoint{x0, y1}};
  const double c = std::cos(o.angle_rad);
  const double s = std::sin(o.angle_rad);
  for (const ArenaPoint axis : {ArenaPoint{c, s}, ArenaPoint{-s, c}}) {
    const auto [olo, ohi] = project(corners, axis.x_m, axis.y_m);
    const auto [blo, bhi] = project(box, axis.x_m, axis.y_m);
    if (!(std::max(olo, blo) < std::min(ohi, bhi))) return false;
  }
  return true;
}

struct CellRange {
  int x_lo, x_hi, y_lo, y_hi;  // inclusive; empty when lo > hi
};

}  // namespace

int cells_along(double side_m, double cell_m) {
  return std::max(1, static_cast<int>(std::lround(side_m / cell_m)));
}

namespace {

// The grid over the arena's boundary, nothing marked yet. Throws common::InputError for a
// grid of no cells or over kMaxTruthCells.
TruthRaster empty_truth(const Arena &arena, int cells_x, int cells_y) {
  if (cells_x < 1 || cells_y < 1 ||
      static_cast<double>(cells_x) * static_cast<double>(cells_y) > static_cast<double>(kMaxTruthCells)) {
    throw common::InputError(fmt::format("a grid of {} x {} cells is too fine: at most {} cells", cells_x, cells_y,
                                         kMaxTruthCells));
  }
  TruthRaster t;
  t.cells_x = cells_x;
  t.cells_y = cells_y;
  t.x_min_m = arena.x_min_m;
  t.y_min_m = arena.y_min_m;
  t.cell_x_m = arena.width_m() / cells_x;
  t.cell_y_m = arena.height_m() / cells_y;
  const std::size_t n = static_cast<std::size_t>(cells_x) * static_cast<std::size_t>(cells_y);
  t.occupied.assign(n, 0);
  t.reachable.assign(n, 0);
  return t;
}

// Marks the occupied cells (and counts them and the free ones); returns the cells the
// robot's centre cannot stand in (occupied, or within its radius of an obstacle or of the
// boundary).
std::vector<std::uint8_t> mark_obstacles(const Arena &arena, TruthRaster &t, double robot_radius_m) {
  const int cells_x = t.cells_x;
  const int cells_y = t.cells_y;
  const std::size_t n = t.occupied.size();
  std::vector<std::uint8_t> blocked(n, 0);  // not traversable by the robot's centre
  const auto range_of = [&](double x0, double y0, double x1, double y1) {
    const auto clamp_x = [&](double v) { return std::clamp(static_cast<int>(std::floor(v)), 0, cells_x - 1); };
    const auto clamp_y = [&](double v) { return std::clamp(static_cast<int>(std::floor(v)), 0, cells_y - 1); };
    if (x1 < arena.x_min_m || y1 < arena.y_min_m || x0 > arena.x_max_m || y0 > arena.y_max_m) {
      return CellRange{0, -1, 0, -1};
    }
    return CellRange{clamp_x((x0 - t.x_min_m) / t.cell_x_m), clamp_x((x1 - t.x_min_m) / t.cell_x_m),
                     clamp_y((y0 - t.y_min_m) / t.cell_y_m), clamp_y((y1 - t.y_min_m) / t.cell_y_m)};
  };
  const auto centre_x = [&](int x) { return t.x_min_m + (x + 0.5) * t.cell_x_m; };
  const auto centre_y = [&](int y) { return t.y_min_m + (y + 0.5) * t.cell_y_m; };
  for (const Obstacle &o : arena.obstacles) {
    const auto b = o.bounds();
    const auto corners = o.corners();
    const CellRange r = range_of(b[0], b[1], b[2], b[3]);
    for (int y = r.y_lo; y <= r.y_hi; ++y) {
      for (int x = r.x_lo; x <= r.x_hi; ++x) {
        const double x0 = t.x_min_m + x * t.cell_x_m;
        const double y0 = t.y_min_m + y * t.cell_y_m;
        if (overlaps(o, corners, x0, y0, x0 + t.cell_x_m, y0 + t.cell_y_m)) t.occupied[t.index(x, y)] = 1;
      }
    }
    const CellRange near = range_of(b[0] - robot_radius_m, b[1] - robot_radius_m, b[2] + robot_radius_m,
                                    b[3] + robot_radius_m);
    for (int y = near.y_lo; y <= near.y_hi; ++y) {
      for (int x = near.x_lo; x <= near.x_hi; ++x) {
        if (o.contains(centre_x(x), centre_y(y)) || o.distance_m(centre_x(x), centre_y(y)) < robot_radius_m) {
          blocked[t.index(x, y)] = 1;
        }
      }
    }
  }
  for (const ArenaDisc &d : arena.discs) {
    const double reach = d.radius_m + robot_radius_m;
    const CellRange r = range_of(d.centre_x_m - reach, d.centre_y_m - reach, d.centre_x_m + reach, d.centre_y_m + reach);
    for (int y = r.y_lo; y <= r.y_hi; ++y) {
      for (int x = r.x_lo; x <= r.x_hi; ++x) {
        const double x0 = t.x_min_m + x * t.cell_x_m;
        const double y0 = t.y_min_m + y * t.cell_y_m;
        // The cell's point nearest the axis strictly inside the disc: an overlap of positive area.
        const double dx = std::max({x0 - d.centre_x_m, 0.0, d.centre_x_m - (x0 + t.cell_x_m)});
        const double dy = std::max({y0 - d.centre_y_m, 0.0, d.centre_y_m - (y0 + t.cell_y_m)});
        if (std::hypot(dx, dy) < d.radius_m) t.occupied[t.index(x, y)] = 1;
        if (std::hypot(centre_x(x) - d.centre_x_m, centre_y(y) - d.centre_y_m) < reach) blocked[t.index(x, y)] = 1;
      }
    }
  }
  for (int y = 0; y < cells_y; ++y) {
    for (int x = 0; x < cells_x; ++x) {
      const std::size_t i = t.index(x, y);
      const double cx = centre_x(x);
      const double cy = centre_y(y);
      const double to_edge = std::min({cx - arena.x_min_m, arena.x_max_m - cx, cy - arena.y_min_m, arena.y_max_m - cy});
      if (t.occupied[i] != 0 || to_edge < robot_radius_m) blocked[i] = 1;
      (t.occupied[i] != 0 ? t.occupied_count : t.free_count) += 1;
    }
  }
  return blocked;
}

// The cells the robot's centre reaches from the start's cell, 4-connected over unblocked cells.
std::vector<std::uint8_t> reachable_centres(const Arena &arena, const TruthRaster &t,
                                            const std::vector<std::uint8_t> &blocked) {
  const int cells_x = t.cells_x;
  const int cells_y = t.cells_y;
  const std::size_t n = t.occupied.size();
  // The robot's centre: a flood over traversable cells from the start's cell.
  const ArenaPose start = arena.start();
  const int sx = std::clamp(static_cast<int>(std::floor((start.x_m - t.x_min_m) / t.cell_x_m)), 0, cells_x - 1);
  const int sy = std::clamp(static_cast<int>(std::floor((start.y_m - t.y_min_m) / t.cell_y_m)), 0, cells_y - 1);
  std::vector<std::uint8_t> centres(n, 0);
  std::deque<std::pair<int, int>> queue{{sx, sy}};
  centres[t.index(sx, sy)] = 1;
  while (!queue.empty()) {
    const auto [x, y] = queue.front();
    queue.pop_front();
    constexpr int kDx[] = {1, -1, 0, 0};
    constexpr int kDy[] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int nx = x + kDx[k];
      const int ny = y + kDy[k];
      if (nx < 0 || ny < 0 || nx >= cells_x || ny >= cells_y) continue;
      const std::size_t j = t.index(nx, ny);
      if (centres[j] != 0 || blocked[j] != 0) continue;
      centres[j] = 1;
      queue.emplace_back(nx, ny);
    }
  }
  return centres;
}

// Marks reachable the free cells the robot's body covers from the centres it reaches.
void mark_reachable_body(TruthRaster &t, const std::vector<std::uint8_t> &centres, double robot_radius_m) {
  const int cells_x = t.cells_x;
  const int cells_y = t.cells_y;
  const std::size_t n = t.occupied.size();
  // The body: from each centre the robot reaches, the free cells within the reach (the
  // radius and half a cell's diagonal) found by a walk over free cells (so not through a wall).
  const double reach = robot_radius_m + 0.5 * std::hypot(t.cell_x_m, t.cell_y_m);
  const auto within = [&](int dx, int dy) { return std::hypot(dx * t.cell_x_m, dy * t.cell_y_m) <= reach; };
  const auto mark = [&](std::size_t j) {
    if (t.occupied[j] == 0 && t.reachable[j] == 0) {
      t.reachable[j] = 1;
      ++t.reachable_count;
    }
  };
  std::vector<std::uint32_t> seen(n, 0);
  std::uint32_t stamp = 0;
  std::vector<std::pair<int, int>> walk;
  constexpr int kDx[] = {1, -1, 0, 0};
  constexpr int kDy[] = {0, 0, 1, -1};
  for (int y = 0; y < cells_y; ++y) {
    for (int x = 0; x < cells_x; ++x) {
      if (centres[t.index(x, y)] == 0) continue;
      mark(t.index(x, y));
      bool edge = false;
      for (int k = 0; k < 4 && !edge; ++k) {
        const int nx = x + kDx[k];
        const int ny = y + kDy[k];
        edge = nx >= 0 && ny >= 0 && nx < cells_x && ny < cells_y && centres[t.index(nx, ny)] == 0;
      }
      if (!edge) continue;
      ++stamp;
      walk.assign(1, {x, y});
      seen[t.index(x, y)] = stamp;
      while (!walk.empty()) {
        const auto [wx, wy] = walk.back();
        walk.pop_back();
        for (int k = 0; k < 4; ++k) {
          const int nx = wx + kDx[k];
          const int ny = wy + kDy[k];
          if (nx < 0 || ny < 0 || nx >= cells_x || ny >= cells_y || !within(nx - x, ny - y)) continue;
          const std::size_t j = t.index(nx, ny);
          if (seen[j] == stamp || t.occupied[j] != 0) continue;
          seen[j] = stamp;
          mark(j);
          walk.emplace_back(nx, ny);
        }
      }
    }
  }
}

}  // namespace

TruthRaster rasterise_truth(const Arena &arena, int cells_x, int cells_y, double robot_radius_m,
                           TruthClearance clearance) {
  TruthRaster t = empty_truth(arena, cells_x, cells_y);
  std::vector<std::uint8_t> blocked = mark_obstacles(arena, t, robot_radius_m);
  if (clearance == TruthClearance::to_occupied_cells) {
    blocked = common::cells_without_clearance(cells_x, cells_y, t.cell_x_m, robot_radius_m,
                                              [&t](std::size_t n) { return t.occupied[n] != 0; });
  }
  mark_reachable_body(t, reachable_centres(arena, t, blocked), robot_radius_m);
  return t;
}

}  // namespace maze
