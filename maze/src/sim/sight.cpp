// Heights along a line (maze/sim/sight.hpp).

#include "maze/sim/sight.hpp"

#include "maze/world/world_files.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace maze::sim {

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// The parameter interval [t_in, t_out] of the line (ox, oy) + t (dx, dy) inside the closed
// interval [lo, hi] of one axis, narrowing [t_in, t_out] to it; false when that is empty.
bool clip_axis(double o, double d, double lo, double hi, double &t_in, double &t_out) {
  if (d == 0.0) return o >= lo && o <= hi;
  double a = (lo - o) / d;
  double b = (hi - o) / d;
  if (a > b) std::swap(a, b);
  t_in = std::max(t_in, a);
  t_out = std::min(t_out, b);
  return t_in <= t_out;
}

// Where the line from (ox, oy) along the unit (dx, dy) is inside the obstacle: [in, out].
std::optional<std::pair<double, double>> span_of(const Obstacle &o, double ox, double oy, double dx, double dy) {
  const double c = std::cos(o.angle_rad);
  const double s = std::sin(o.angle_rad);
  const double px = ox - o.centre_x_m;
  const double py = oy - o.centre_y_m;
  double t_in = -kUnbounded;
  double t_out = kUnbounded;
  if (!clip_axis(c * px + s * py, c * dx + s * dy, -o.half_length_m, o.half_length_m, t_in, t_out)) return {};
  if (!clip_axis(-s * px + c * py, -s * dx + c * dy, -o.half_width_m, o.half_width_m, t_in, t_out)) return {};
  return std::pair{t_in, t_out};
}

std::optional<std::pair<double, double>> span_of(const ArenaDisc &d, double ox, double oy, double dx, double dy) {
  const double px = ox - d.centre_x_m;
  const double py = oy - d.centre_y_m;
  const double b = px * dx + py * dy;
  const double disc = b * b - (px * px + py * py - d.radius_m * d.radius_m);
  if (disc < 0.0) return {};
  const double root = std::sqrt(disc);
  return std::pair{-b - root, -b + root};
}

// Calls visit(span, top, disc index) for every solid the line from (ox, oy) along (dx, dy) meets.
template <typename Visit>
void for_each_span(const Arena &arena, double ox, double oy, double dx, double dy, Visit &&visit) {
  for (const Obstacle &o : arena.obstacles) {
    if (const auto span = span_of(o, ox, oy, dx, dy)) visit(*span, o.height_m, -1);
  }
  for (std::size_t i = 0; i < arena.discs.size(); ++i) {
    if (const auto span = span_of(arena.discs[i], ox, oy, dx, dy)) {
      visit(*span, arena.discs[i].top_m(), static_cast<int>(i));
    }
  }
}

}  // namespace

std::vector<SolidHit> hits_along(const Arena &arena, double x_m, double y_m, double angle_rad, double max_range_m) {
  const double dx = std::cos(angle_rad);
  const double dy = std::sin(angle_rad);
  std::vector<SolidHit> hits;
  for_each_span(arena, x_m, y_m, dx, dy, [&](std::pair<double, double> span, double top_m, int disc) {
    if (span.second < 0.0 || span.first > max_range_m) return;
    hits.push_back({std::max(span.first, 0.0), top_m, disc});
  });
  if (arena.boundary_walled && arena.inside_boundary(x_m, y_m)) {
    double t_in = -kUnbounded;
    double t_out = kUnbounded;
    clip_axis(x_m, dx, arena.x_min_m, arena.x_max_m, t_in, t_out);
    clip_axis(y_m, dy, arena.y_min_m, arena.y_max_m, t_in, t_out);
    if (t_out <= max_range_m) hits.push_back({t_out, kTallerThanEverySensor_m, -1});
  }
  std::sort(hits.begin(), hits.end(), [](const SolidHit &a, const SolidHit &b) { return a.distance_m < b.distance_m; });
  return hits;
}

bool sight_blocked(const Arena &arena, const Point3 &from, const Point3 &to, double half_depth_m, int target_disc) {
  const double run_m = std::hypot(to.x_m - from.x_m, to.y_m - from.y_m);
  if (run_m == 0.0) return false;
  const double length_m = std::hypot(run_m, to.z_m - from.z_m);
  const double dx = (to.x_m - from.x_m) / run_m;
  const double dy = (to.y_m - from.y_m) / run_m;
  const double rise = (to.z_m - from.z_m) / run_m;  // height gained a metre of run
  double farthest_m = -kUnbounded;                    // the largest entry's distance to `to`
  for_each_span(arena, from.x_m, from.y_m, dx, dy, [&](std::pair<double, double> span, double top_m, int disc) {
    if (disc >= 0 && disc == target_disc) return;
    double t_in = std::max(span.first, 0.0);
    double t_out = std::min(span.second, run_m);
    // Where the segment is between the floor and the solid's top: z(t) = from.z + rise t.
    if (!clip_axis(from.z_m, rise, 0.0, top_m, t_in, t_out)) return;
    farthest_m = std::max(farthest_m, length_m - t_in * length_m / run_m);
  });
  return farthest_m > half_depth_m;
}

void LidarPlanes::place(const Arena *geometry, const Maze *lattice, const RobotProfile &profile, double robot_z_m) {
  planes_.assign(profile.lidars.size(), std::nullopt);
  for (std::size_t i = 0; i < profile.lidars.size(); ++i) {
    const double z_m = robot_z_m + profile.lidars[i].height_m;
    if (geometry != nullptr) {
      if (!every_solid_above(*geometry, z_m)) planes_[i].emplace(solids_above(*geometry, z_m));
    } else if (lattice != nullptr && !(lattice->wall_height_m() > z_m)) {
      planes_[i].emplace(solids_above(arena_from_maze(*lattice), z_m));
    }
  }
}

}  // namespace maze::sim
