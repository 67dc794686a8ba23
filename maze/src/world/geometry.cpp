#include "maze/world/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace maze {

namespace {

// The point in the obstacle's own frame: u along its axis, v across.
struct Local {
  double u, v;
};

// cos and sin of the angle, exact for a quarter turn (cos(pi/2) is 6e-17 in doubles).
ArenaPoint unit_of(double angle_rad) {
  const double quarter = std::numbers::pi / 2.0;
  const double q = std::round(angle_rad / quarter);
  if (std::abs(angle_rad - q * quarter) <= 1e-12) {
    constexpr ArenaPoint kQuarters[] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
    return kQuarters[((static_cast<long long>(q) % 4) + 4) % 4];
  }
  return {std::cos(angle_rad), std::sin(angle_rad)};
}

Local to_local(const Obstacle &o, double x_m, double y_m) {
  const ArenaPoint axis = unit_of(o.angle_rad);
  const double c = axis.x_m;
  const double s = axis.y_m;
  const double dx = x_m - o.centre_x_m;
  const double dy = y_m - o.centre_y_m;
  return {c * dx + s * dy, -s * dx + c * dy};
}

ArenaPoint to_world(const Obstacle &o, double u, double v) {
  const ArenaPoint axis = unit_of(o.angle_rad);
  const double c = axis.x_m;
  const double s = axis.y_m;
  return {o.centre_x_m + c * u - s * v, o.centre_y_m + s * u + c * v};
}

std::string located_line(const common::SourceLocation &where) {
  return where.line > 0 ? fmt::format(" at line {}", where.line) : std::string();
}

std::string boundary_text(const Arena &a) {
  return fmt::format("x {} to {} m, y {} to {} m", a.x_min_m, a.x_max_m, a.y_min_m, a.y_max_m);
}

common::SourceLocation or_file(const common::SourceLocation &where, const Arena &a) {
  if (!where.file.empty()) return where;
  return common::SourceLocation{a.source, 0, 0};
}

common::InputError error_at(const common::SourceLocation &where, const Arena &a, std::string message) {
  const common::SourceLocation at = or_file(where, a);
  if (at.file.empty()) return common::InputError(std::move(message));
  return common::InputError(at, std::move(message));
}

bool finite(double v) { return std::isfinite(v); }

}  // namespace

Obstacle Obstacle::from_box(double x0_m, double y0_m, double x1_m, double y1_m) {
  Obstacle o;
  o.centre_x_m = (x0_m + x1_m) / 2.0;
  o.centre_y_m = (y0_m + y1_m) / 2.0;
  o.half_length_m = std::abs(x1_m - x0_m) / 2.0;
  o.half_width_m = std::abs(y1_m - y0_m) / 2.0;
  o.angle_rad = 0.0;
  o.box = std::array<double, 4>{std::min(x0_m, x1_m), std::min(y0_m, y1_m), std::max(x0_m, x1_m), std::max(y0_m, y1_m)};
  return o;
}

Obstacle Obstacle::oriented(double centre_x_m, double centre_y_m, double half_length_m, double half_width_m,
                            double angle_rad) {
  Obstacle o;
  o.centre_x_m = centre_x_m;
  o.centre_y_m = centre_y_m;
  o.half_length_m = half_length_m;
  o.half_width_m = half_width_m;
  o.angle_rad = angle_rad;
  return o;
}

Obstacle Obstacle::from_segment(double x1_m, double y1_m, double x2_m, double y2_m, double width_m, WallEnds ends) {
  const double cap = ends == WallEnds::capped ? width_m / 2.0 : 0.0;
  const double half = width_m / 2.0;
  // Along an axis: the box itself, its extent exact.
  if (y1_m == y2_m) {
    Obstacle o = from_box(std::min(x1_m, x2_m) - cap, y1_m - half, std::max(x1_m, x2_m) + cap, y1_m + half);
    o.half_length_m = std::abs(x2_m - x1_m) / 2.0 + cap;
    o.half_width_m = half;
    return o;
  }
  if (x1_m == x2_m) {
    Obstacle o = from_box(x1_m - half, std::min(y1_m, y2_m) - cap, x1_m + half, std::max(y1_m, y2_m) + cap);
    o.half_length_m = half;  // from_box's axis runs east: the wall's length is across it
    o.half_width_m = std::abs(y2_m - y1_m) / 2.0 + cap;
    return o;
  }
  Obstacle o;
  const double dx = x2_m - x1_m;
  const double dy = y2_m - y1_m;
  o.centre_x_m = (x1_m + x2_m) / 2.0;
  o.centre_y_m = (y1_m + y2_m) / 2.0;
  // A horizontal or vertical wall keeps an exact angle (0 or pi/2), so its extent is exact.
  o.half_length_m = std::hypot(dx, dy) / 2.0 + cap;
  o.half_width_m = half;
  o.angle_rad = std::atan2(dy, dx);
  return o;
}

bool Obstacle::axis_aligned() const {
  const double quarter = std::numbers::pi / 2.0;
  return std::abs(angle_rad - quarter * std::round(angle_rad / quarter)) <= 1e-12;
}

std::array<double, 4> Obstacle::bounds() const {
  if (box && angle_rad == 0.0) return *box;
  if (axis_aligned()) {
    const bool across = static_cast<long long>(std::round(angle_rad / (std::numbers::pi / 2.0))) % 2 != 0;
    const double hx = across ? half_width_m : half_length_m;
    const double hy = across ? half_length_m : half_width_m;
    return {centre_x_m - hx, centre_y_m - hy, centre_x_m + hx, centre_y_m + hy};
  }
  const double c = std::abs(std::cos(angle_rad));
  const double s = std::abs(std::sin(angle_rad));
  const double hx = c * half_length_m + s * half_width_m;
  const double hy = s * half_length_m + c * half_width_m;
  return {centre_x_m - hx, centre_y_m - hy, centre_x_m + hx, centre_y_m + hy};
}

std::array<ArenaPoint, 4> Obstacle::corners() const {
  const double l = half_length_m;
  const double w = half_width_m;
  return {to_world(*this, -l, -w), to_world(*this, l, -w), to_world(*this, l, w), to_world(*this, -l, w)};
}

bool Obstacle::contains(double x_m, double y_m) const {
  if (axis_aligned()) {
    const auto b = bounds();
    return x_m >= b[0] && x_m <= b[2] && y_m >= b[1] && y_m <= b[3];
  }
  const Local p = to_local(*this, x_m, y_m);
  return std::abs(p.u) <= half_length_m && std::abs(p.v) <= half_width_m;
}

ArenaPoint Obstacle::nearest_point(double x_m, double y_m) const {
  if (axis_aligned()) {
    const auto b = bounds();
    return {std::clamp(x_m, b[0], b[2]), std::clamp(y_m, b[1], b[3])};
  }
  const Local p = to_local(*this, x_m, y_m);
  return to_world(*this, std::clamp(p.u, -half_length_m, half_length_m),
                  std::clamp(p.v, -half_width_m, half_width_m));
}

double Obstacle::distance_m(double x_m, double y_m) const {
  const ArenaPoint q = nearest_point(x_m, y_m);
  return std::hypot(x_m - q.x_m, y_m - q.y_m);
}

std::array<double, 5> Obstacle::centre_line() const {
  const bool across = half_width_m > half_length_m;
  const ArenaPoint axis = unit_of(across ? angle_rad + std::numbers::pi / 2.0 : angle_rad);
  const double half = across ? half_width_m : half_length_m;
  const double width = 2.0 * (across ? half_length_m : half_width_m);
  return {centre_x_m - axis.x_m * half, centre_y_m - axis.y_m * half, centre_x_m + axis.x_m * half,
          centre_y_m + axis.y_m * half, width};
}

Arena solids_above(const Arena &arena, double z_m) {
  Arena above = arena;
  std::erase_if(above.obstacles, [z_m](const Obstacle &o) { return !(o.height_m > z_m); });
  std::erase_if(above.discs, [z_m](const ArenaDisc &d) { return !(d.top_m() > z_m); });
  return above;
}

bool every_solid_above(const Arena &arena, double z_m) {
  return std::all_of(arena.obstacles.begin(), arena.obstacles.end(), [z_m](const Obstacle &o) { return o.height_m > z_m; }) &&
         std::all_of(arena.discs.begin(), arena.discs.end(), [z_m](const ArenaDisc &d) { return d.top_m() > z_m; });
}

Arena course_empty_floor() {
  Arena arena;
  arena.name = "the course's empty floor";
  const double half = kCourseFloorSide_m / 2.0;
  arena.x_min_m = -half;
  arena.x_max_m = half;
  arena.y_min_m = -half;
  arena.y_max_m = half;
  arena.boundary_walled = false;
  return arena;
}

ArenaPose Arena::start() const {
  if (!starts.empty()) return starts.front();
  return {(x_min_m + x_max_m) / 2.0, (y_min_m + y_max_m) / 2.0, std::numbers::pi / 2.0};
}

ArenaCheck check_arena_finite(const Arena &a) {
  if (!finite(a.x_min_m) || !finite(a.x_max_m) || !finite(a.y_min_m) || !finite(a.y_max_m)) {
    return error_at(a.boundary_where, a, "the boundary has a non-finite coordinate");
  }
  for (std::size_t i = 0; i < a.obstacles.size(); ++i) {
    const Obstacle &o = a.obstacles[i];
    if (!finite(o.centre_x_m) || !finite(o.centre_y_m) || !finite(o.half_length_m) || !finite(o.half_width_m) ||
        !finite(o.angle_rad)) {
      return error_at(o.where, a, fmt::format("obstacle {} has a non-finite coordinate", i + 1));
    }
  }
  for (std::size_t i = 0; i < a.starts.size(); ++i) {
    const ArenaPose &p = a.starts[i];
    if (!finite(p.x_m) || !finite(p.y_m) || !finite(p.yaw_rad)) {
      return error_at(i < a.start_where.size() ? a.start_where[i] : common::SourceLocation{}, a,
                      "the start has a non-finite coordinate");
    }
  }
  for (std::size_t i = 0; i < a.goals.size(); ++i) {
    if (!finite(a.goals[i].x_m) || !finite(a.goals[i].y_m)) {
      return error_at(i < a.goal_where.size() ? a.goal_where[i] : common::SourceLocation{}, a,
                      "the goal has a non-finite coordinate");
    }
  }
  return std::nullopt;
}

ArenaCheck check_arena_boundary(const Arena &a) {
  if (!(a.x_min_m < a.x_max_m) || !(a.y_min_m < a.y_max_m)) {
    return error_at(a.boundary_where, a,
                    fmt::format("the boundary {} is empty: it needs XS < XE and YS < YE", boundary_text(a)));
  }
  return std::nullopt;
}

ArenaCheck check_arena_size(const Arena &a) {
  if (a.obstacles.size() > kMaxObstacles) {
    return error_at(a.obstacles[kMaxObstacles].where, a,
                    fmt::format("{} obstacles: an arena holds at most {}", a.obstacles.size(), kMaxObstacles));
  }
  if (a.width_m() > kMaxArenaSide_m || a.height_m() > kMaxArenaSide_m) {
    return error_at(a.boundary_where, a,
                    fmt::format("the boundary spans {} x {} m; each side must be at most {} m", a.width_m(),
                                a.height_m(), kMaxArenaSide_m));
  }
  return std::nullopt;
}

ArenaCheck check_starts_inside(const Arena &a) {
  for (std::size_t i = 0; i < a.starts.size(); ++i) {
    const ArenaPose &p = a.starts[i];
    if (!a.inside_boundary(p.x_m, p.y_m)) {
      return error_at(i < a.start_where.size() ? a.start_where[i] : common::SourceLocation{}, a,
                      fmt::format("start ({}, {}) is outside the boundary {}", p.x_m, p.y_m, boundary_text(a)));
    }
  }
  return std::nullopt;
}

ArenaCheck check_goals_inside(const Arena &a) {
  for (std::size_t i = 0; i < a.goals.size(); ++i) {
    const ArenaPoint &g = a.goals[i];
    if (!a.inside_boundary(g.x_m, g.y_m)) {
      return error_at(i < a.goal_where.size() ? a.goal_where[i] : common::SourceLocation{}, a,
                      fmt::format("goal ({}, {}) is outside the boundary {}", g.x_m, g.y_m, boundary_text(a)));
    }
  }
  return std::nullopt;
}

ArenaCheck check_starts_clear(const Arena &a, double robot_radius_m) {
  for (std::size_t i = 0; i < a.starts.size(); ++i) {
    const ArenaPose &p = a.starts[i];
    const common::SourceLocation where = i < a.start_where.size() ? a.start_where[i] : common::SourceLocation{};
    for (const Obstacle &o : a.obstacles) {
      if (o.contains(p.x_m, p.y_m)) {
        return error_at(where, a, fmt::format("start ({}, {}) is inside the obstacle{}", p.x_m, p.y_m,
                                              located_line(o.where)));
      }
      if (robot_radius_m > 0.0 && o.distance_m(p.x_m, p.y_m) < robot_radius_m) {
        return error_at(where, a,
                        fmt::format("a robot of radius {} m at start ({}, {}) touches the obstacle{}",
                                    robot_radius_m, p.x_m, p.y_m, located_line(o.where)));
      }
    }
    const double to_edge = std::min({p.x_m - a.x_min_m, a.x_max_m - p.x_m, p.y_m - a.y_min_m, a.y_max_m - p.y_m});
    if (robot_radius_m > 0.0 && to_edge < robot_radius_m) {
      return error_at(where, a,
                      fmt::format("a robot of radius {} m at start ({}, {}) touches the boundary {}", robot_radius_m,
                                  p.x_m, p.y_m, boundary_text(a)));
    }
  }
  return std::nullopt;
}

void validate_arena(const Arena &arena, double robot_radius_m) {
  for (const ArenaCheck &failure :
       {check_arena_finite(arena), check_arena_boundary(arena), check_arena_size(arena), check_starts_inside(arena),
        check_goals_inside(arena), check_starts_clear(arena, robot_radius_m)}) {
    if (failure) throw *failure;
  }
}

}  // namespace maze
