// The bump and depth marks of one pose on a numCells grid (sensing/bump_depth_marks.hpp).

#include "sensing/bump_depth_marks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "common/angles.hpp"
#include "common/error.hpp"

namespace sensing {
namespace {

constexpr int kMaxCells = 2000;

enum Level { occupied = 0, free_cell = 1, ray = 2 };  // lower wins

// Marks gathered for one step: cell index -> strongest level.
class StepMarks {
 public:
  StepMarks(const BumpDepthOptions &o) : o_(o) {}
  void mark(double x, double y, Level level) {
    const double w = (o_.x_end_m - o_.x_start_m) / o_.cells_x;
    const double h = (o_.y_end_m - o_.y_start_m) / o_.cells_y;
    const double i = std::floor((x - o_.x_start_m) / w);
    const double j = std::floor((y - o_.y_start_m) / h);
    if (!(i >= 0 && i < o_.cells_x && j >= 0 && j < o_.cells_y)) return;
    const int index = static_cast<int>(j) * o_.cells_x + static_cast<int>(i);
    const auto [it, added] = marks_.emplace(index, level);
    if (!added && level < it->second) it->second = level;
  }
  const std::map<int, Level> &marks() const { return marks_; }

 private:
  const BumpDepthOptions &o_;
  std::map<int, Level> marks_;
};

void mark_bumps(const BumpDepthOptions &o, const PoseStep &s, StepMarks &marks) {
  const struct {
    double offset_rad;
    bool pressed;
  } bumpers[] = {{-std::numbers::pi / 4, s.bump_right}, {std::numbers::pi / 4, s.bump_left}, {0.0, s.bump_front}};
  for (const auto &b : bumpers) {
    const double a = s.theta_rad + b.offset_rad;
    marks.mark(s.x_m + o.bump_radius_m * std::cos(a), s.y_m + o.bump_radius_m * std::sin(a),
               b.pressed ? occupied : free_cell);
  }
}

void mark_depth(const BumpDepthOptions &o, const PoseStep &s, StepMarks &marks) {
  const double step = std::min((o.x_end_m - o.x_start_m) / o.cells_x, (o.y_end_m - o.y_start_m) / o.cells_y);
  const double cos_t = std::cos(s.theta_rad);
  const double sin_t = std::sin(s.theta_rad);
  const double x0 = s.x_m + o.depth_origin_x_m * cos_t - o.depth_origin_y_m * sin_t;
  const double y0 = s.y_m + o.depth_origin_x_m * sin_t + o.depth_origin_y_m * cos_t;
  for (int n = 0; n < kDepthRays; ++n) {
    const double z = s.depth_m[static_cast<std::size_t>(n)];
    if (!(z > 0.0 && z < o.depth_max_m)) continue;
    const double angle = o.depth_angles_deg[static_cast<std::size_t>(n)] * common::kRadPerDeg;
    const double range = o.depth_reading == DepthReading::axial ? z / std::cos(angle) : z;
    const double a = s.theta_rad + angle;
    for (int k = 0; k * step < range; ++k) marks.mark(x0 + k * step * std::cos(a), y0 + k * step * std::sin(a), ray);
    marks.mark(x0 + range * std::cos(a), y0 + range * std::sin(a), occupied);
  }
}

}  // namespace

void require_boundary_m(double x_start_m, double x_end_m, double y_start_m, double y_end_m) {
  for (const double v : {x_start_m, x_end_m, y_start_m, y_end_m}) {
    common::require_input(std::isfinite(v), "--boundary must be four finite numbers XS,XE,YS,YE");
  }
  common::require_input(x_start_m < x_end_m,
                        fmt::format("--boundary: XS must be less than XE (got {} and {})", x_start_m, x_end_m));
  common::require_input(y_start_m < y_end_m,
                        fmt::format("--boundary: YS must be less than YE (got {} and {})", y_start_m, y_end_m));
}

void validate(const BumpDepthOptions &o) {
  common::require_input(
      o.cells_x >= 1 && o.cells_x <= kMaxCells && o.cells_y >= 1 && o.cells_y <= kMaxCells,
      fmt::format("--cells must be X,Y with each 1 to {} (got {},{})", kMaxCells, o.cells_x, o.cells_y));
  require_boundary_m(o.x_start_m, o.x_end_m, o.y_start_m, o.y_end_m);
  common::require_input(o.prior > 0.0 && o.prior < 1.0, fmt::format("--prior must be in (0, 1) (got {})", o.prior));
  common::require_input(o.bump_radius_m > 0.0 && std::isfinite(o.bump_radius_m),
                        fmt::format("--bump-radius must be > 0 m (got {})", o.bump_radius_m));
  common::require_input(o.depth_max_m > 0.0 && std::isfinite(o.depth_max_m),
                        fmt::format("--depth-max must be > 0 m (got {})", o.depth_max_m));
  for (const double a : o.depth_angles_deg)
    common::require_input(std::isfinite(a), "--depth-angles must be nine finite numbers");
  common::require_input(std::isfinite(o.depth_origin_x_m) && std::isfinite(o.depth_origin_y_m),
                        "--depth-origin must be two finite numbers X,Y");
  for (const double a : o.depth_angles_deg) {
    common::require_input(
        o.depth_reading == DepthReading::range || std::abs(a) < 90.0,
        fmt::format("--depth-reading axial needs every depth angle within (-90, 90) degrees (got {})", a));
  }
}

LogOddsGrid make_log_odds_grid(const BumpDepthOptions &o) {
  LogOddsGrid g;
  g.cells_x = o.cells_x;
  g.cells_y = o.cells_y;
  g.log_odds.assign(static_cast<std::size_t>(o.cells_x * o.cells_y), mapping::log_odds(o.prior, o.base));
  return g;
}

void apply_bump_depth_marks(const BumpDepthOptions &o, BumpDepthSensor sensor, const PoseStep &s, LogOddsGrid &grid) {
  StepMarks marks(o);
  marks.mark(s.x_m, s.y_m, free_cell);
  if (sensor == BumpDepthSensor::bump) mark_bumps(o, s, marks);
  if (sensor == BumpDepthSensor::depth) mark_depth(o, s, marks);
  const double l0 = mapping::log_odds(o.prior, o.base);
  const double increments[] = {mapping::log_odds(kBumpDepthOccupiedP, o.base) - l0,
                               mapping::log_odds(kBumpDepthFreeP, o.base) - l0,
                               mapping::log_odds(kBumpDepthRayP, o.base) - l0};
  for (const auto &[index, level] : marks.marks()) {
    grid.log_odds[static_cast<std::size_t>(index)] += increments[level];
  }
}

}  // namespace sensing
