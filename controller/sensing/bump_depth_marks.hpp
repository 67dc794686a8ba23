#pragma once
// The bump and depth marks of one pose on a plain numCells grid: X × Y cells over a boundary
// in metres, not the maze's 4D grid. The numbers are the Cornell-style bump and depth
// homework's; `maze_mapper map-log` marks a pose log with them, and the room map's bump and
// depth set-ups mark each scan.
//
//   cell (i, j): i = floor((x - x_start) / w), j = floor((y - y_start) / h),
//                w = (x_end - x_start) / X, h = (y_end - y_start) / Y; a point with i outside
//                [0, X) or j outside [0, Y) is ignored.
//
// Per time step (PoseStep) the marks are gathered, then each marked cell gets one update
// l <- l + l(p) - l0, the strongest mark winning:
//   occupied  p = 0.99999  a pressed bumper's contact point; a depth ray's end (reading z)
//   free      p = 0.3      the robot's cell; the contact points of the bumpers not pressed
//   ray       p = 0.4      a depth ray's points at k s, k = 0, 1, ... while k s < z,
//                          s = min(w, h)
// occupied over free over ray. Bumpers touch at bump_radius from the centre: front along
// theta, left at theta + 45 deg, right at theta - 45 deg. Depth rays leave the centre at
// theta + angle (angles left positive) from the sensor's origin (depth_origin, in the robot's
// frame: x forward, y left; default the centre); a reading z <= 0 or >= depth_max is ignored.
// A reading is the range along its ray (this program's depth robot and its trace), or with
// DepthReading::axial the depth along the sensor's forward axis, as a depth camera and the
// Cornell homework's simulator report it (its depthPredict): the ray's range is then
// z / cos(angle). Base 10:
// l(0.99999) = +5.000, l(0.3) = -0.368, l(0.4) = -0.176.

#include <array>
#include <vector>

#include "mapping/log_odds.hpp"

namespace sensing {

enum class BumpDepthSensor { bump, depth };

// What a depth reading measures: the range along its ray, or the depth along the sensor's axis.
enum class DepthReading { range, axial };

inline constexpr double kBumpDepthOccupiedP = 0.99999;
inline constexpr double kBumpDepthFreeP = 0.3;
inline constexpr double kBumpDepthRayP = 0.4;
inline constexpr int kDepthRays = 9;

// The grid and the robot's geometry, given by the caller: the cells, the bumpers' radius and
// the depth rays' angles and max range have no defaults of their own.
struct BumpDepthOptions {
  int cells_x = 0;
  int cells_y = 0;
  double x_start_m = 0.0, x_end_m = 0.0, y_start_m = 0.0, y_end_m = 0.0;  // the boundary
  double prior = 0.5;
  mapping::LogBase base = mapping::LogBase::ten;
  double bump_radius_m = 0.0;
  std::array<double, kDepthRays> depth_angles_deg{};  // depth_1 ... depth_9, deg, left positive
  double depth_max_m = 0.0;
  DepthReading depth_reading = DepthReading::range;
  double depth_origin_x_m = 0.0;  // the depth sensor's origin in the robot's frame, forward
  double depth_origin_y_m = 0.0;  // and left
};

// Throws common::InputError naming the option: cells not 1 ... 2000, a boundary of zero or
// negative width or height, a prior not in (0, 1), a radius or depth max not > 0, a number
// not finite, an axial reading's angle not within (-90, 90) degrees.
void validate(const BumpDepthOptions &options);
// A floor XS..XE, YS..YE (m) as --boundary gives it: four finite numbers, XS < XE and YS < YE;
// throws common::InputError naming --boundary otherwise.
void require_boundary_m(double x_start_m, double x_end_m, double y_start_m, double y_end_m);

// One time step: the pose (m, rad) and the readings.
struct PoseStep {
  double t = 0.0;
  double x_m = 0.0, y_m = 0.0, theta_rad = 0.0;
  bool bump_right = false, bump_left = false, bump_front = false;
  std::array<double, kDepthRays> depth_m{};
};

// The grid: log-odds of cell (i, j) at index j * cells_x + i (row 0 the south row).
struct LogOddsGrid {
  int cells_x = 0;
  int cells_y = 0;
  std::vector<double> log_odds;
  double at(int i, int j) const { return log_odds[static_cast<std::size_t>(j * cells_x + i)]; }
};

// Every cell at l0 = l(prior).
LogOddsGrid make_log_odds_grid(const BumpDepthOptions &options);

// Gathers one step's marks and applies them (valid options).
void apply_bump_depth_marks(const BumpDepthOptions &options, BumpDepthSensor sensor, const PoseStep &step,
                            LogOddsGrid &grid);

}  // namespace sensing
