// A supervisor's edits of a simulation's world (maze/sim/simulation.hpp): solids added and
// removed, the robot teleported, the world reset, a line of sight cast; and a controller's
// sampling periods and change of a rotating lidar's frequency.

#include <cmath>
#include <algorithm>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "common/angles.hpp"
#include "common/error.hpp"
#include "maze/sim/simulation.hpp"

namespace webots::embedded {

namespace {

void require_solid_size(double value_m, const char *what) {
  if (!(value_m >= 0.0) || !std::isfinite(value_m)) {
    throw common::InputError(fmt::format("{} must be a finite number >= 0 (got {})", what, value_m));
  }
}

void require_finite_value(double value, const char *what) {
  if (!std::isfinite(value)) throw common::InputError(fmt::format("{} must be finite (got {})", what, value));
}

// How far a removed node may lie from the solid it stands for: the course's library writes
// its nodes' numbers with two decimals (a wall at 1.57 rad, a centre to the centimetre).
constexpr double kRemoveTolerance_m = 0.01;
constexpr double kRemoveTolerance_rad = 0.01;

// Whether two axes are parallel or square to each other.
bool parallel_or_square(double a_rad, double b_rad) {
  const double quarter = std::numbers::pi / 2.0;
  const double turn = std::remainder(a_rad - b_rad, quarter);
  return std::abs(turn) < kRemoveTolerance_rad;
}

// The pieces of `box` left when footprint takes what it covers of box's centre line (box
// itself when it covers none of it).
std::vector<maze::Obstacle> cut(const maze::Obstacle &box, const maze::Obstacle &footprint) {
  if (!parallel_or_square(box.angle_rad, footprint.angle_rad)) return {box};
  const double ux = std::cos(box.angle_rad);
  const double uy = std::sin(box.angle_rad);
  double along_min = INFINITY, along_max = -INFINITY, across_min = INFINITY, across_max = -INFINITY;
  for (const maze::ArenaPoint &p : footprint.corners()) {
    const double dx = p.x_m - box.centre_x_m;
    const double dy = p.y_m - box.centre_y_m;
    along_min = std::min(along_min, dx * ux + dy * uy);
    along_max = std::max(along_max, dx * ux + dy * uy);
    across_min = std::min(across_min, -dx * uy + dy * ux);
    across_max = std::max(across_max, -dx * uy + dy * ux);
  }
  const double from = std::max(along_min - kRemoveTolerance_m, -box.half_length_m);
  const double to = std::min(along_max + kRemoveTolerance_m, box.half_length_m);
  // The footprint lies along the box, on its centre line and no wider than it: a wide box
  // taken out cuts no wall that merely crosses it.
  const bool on_line = across_min <= kRemoveTolerance_m && across_max >= -kRemoveTolerance_m &&
                       across_max - across_min <= 2.0 * box.half_width_m + kRemoveTolerance_m;
  if (!on_line || from >= to) return {box};
  std::vector<maze::Obstacle> pieces;
  const auto keep = [&](double a, double b) {  // the part [a, b] of the centre line
    if (b - a <= std::max(2.0 * box.half_width_m, kRemoveTolerance_m)) return;
    maze::Obstacle piece = maze::Obstacle::oriented(box.centre_x_m + ux * (a + b) / 2.0,
                                                    box.centre_y_m + uy * (a + b) / 2.0, (b - a) / 2.0,
                                                    box.half_width_m, box.angle_rad);
    piece.height_m = box.height_m;
    piece.where = box.where;
    pieces.push_back(piece);
  };
  keep(-box.half_length_m, from);
  keep(to, box.half_length_m);
  return pieces;
}

}  // namespace

int Simulation::remove_obstacle(const maze::Obstacle &footprint) {
  if (!geometry_) geometry_ = maze::arena_from_maze(*lattice_);
  std::vector<maze::Obstacle> kept;
  int changed = 0;
  for (const maze::Obstacle &box : geometry_->obstacles) {
    std::vector<maze::Obstacle> pieces = cut(box, footprint);
    if (pieces.size() != 1 || pieces.front().half_length_m != box.half_length_m) ++changed;
    kept.insert(kept.end(), pieces.begin(), pieces.end());
  }
  if (changed > 0) {
    geometry_->obstacles = std::move(kept);
    rebuild_solids();
  }
  return changed;
}

int Simulation::remove_disc(double x_m, double y_m) {
  if (!geometry_) geometry_ = maze::arena_from_maze(*lattice_);
  std::vector<maze::ArenaDisc> &discs = geometry_->discs;
  const auto here = [&](const maze::ArenaDisc &d) {
    return std::hypot(d.centre_x_m - x_m, d.centre_y_m - y_m) <= kRemoveTolerance_m;
  };
  const auto gone = std::erase_if(discs, here);
  if (gone > 0) rebuild_solids();
  return static_cast<int>(gone);
}

void Simulation::use_geometry(maze::Arena geometry) {
  solids_.emplace(geometry);
  geometry_ = std::move(geometry);
  lidar_planes_.place(this->geometry(), lattice(), profile_, height_m_);
}

void Simulation::rebuild_solids() {
  use_geometry(std::move(*geometry_));
  free_centres_.reset();
  for (DeviceState &state : states_) state.read_at_step = -1;  // the sensors see the change at once
}

void Simulation::add_obstacle(const maze::Obstacle &obstacle) {
  require_finite_value(obstacle.centre_x_m, "an obstacle's x");
  require_finite_value(obstacle.centre_y_m, "an obstacle's y");
  require_finite_value(obstacle.angle_rad, "an obstacle's angle");
  require_solid_size(obstacle.half_length_m, "an obstacle's length");
  require_solid_size(obstacle.half_width_m, "an obstacle's width");
  if (!geometry_) geometry_ = maze::arena_from_maze(*lattice_);
  geometry_->obstacles.push_back(obstacle);
  rebuild_solids();
}

void Simulation::add_disc(const maze::ArenaDisc &disc) {
  require_finite_value(disc.centre_x_m, "a cylinder's x");
  require_finite_value(disc.centre_y_m, "a cylinder's y");
  require_solid_size(disc.radius_m, "a cylinder's radius");
  if (!geometry_) geometry_ = maze::arena_from_maze(*lattice_);
  geometry_->discs.push_back(disc);
  rebuild_solids();
}

void Simulation::set_sampling_period(int device, int period_ms) {
  DeviceState &state = states_[static_cast<std::size_t>(device)];
  const int period = std::max(0, period_ms);
  if (period > 0 && state.sampling_period_ms == 0) {
    state.enabled_at_step = steps_;  // a rotating head starts ahead
    if (state.sweep_resumed || state.sweep_start_rev != 0.0) restart_sweep(state, 0.0);
  }
  if (period == 0) state.enabled_at_step = -1;
  state.sampling_period_ms = period;
  state.read_at_step = -1;
}

void Simulation::restart_sweep(DeviceState &state, double start_rev) {
  const maze::sim::LidarSpec &spec = profile_.lidars[static_cast<std::size_t>(state.spec)];
  const double revolutions_per_step = spec.frequency_hz * options_.basic_time_step_ms / 1000.0;
  lidar_sweeps_[static_cast<std::size_t>(state.spec)].emplace(lidar_models_[static_cast<std::size_t>(state.spec)],
                                                              revolutions_per_step, start_rev);
  state.sweep_start_rev = start_rev;
  state.sweep_resumed = false;
  // A beam holds a reading at most one revolution (and one step) old.
  const auto steps_per_revolution = static_cast<std::size_t>(std::ceil(1.0 / revolutions_per_step));
  history_steps_ = std::max(history_steps_, steps_per_revolution + 1);
}

void Simulation::set_lidar_frequency(int device, double frequency_hz) {
  DeviceState &state = states_[static_cast<std::size_t>(device)];
  maze::sim::LidarSpec &spec = profile_.lidars[static_cast<std::size_t>(state.spec)];
  if (!(spec.frequency_hz > 0.0)) {
    throw common::InputError(fmt::format("{} is a fixed lidar: it has no head to turn", spec.name));
  }
  if (!(frequency_hz > 0.0) || !std::isfinite(frequency_hz)) {
    throw common::InputError(fmt::format("a lidar's frequency must be above 0 Hz (got {})", frequency_hz));
  }
  if (frequency_hz == spec.frequency_hz) return;
  if (state.sampling_period_ms == 0) {  // the head turns only while enabled: it starts ahead
    spec.frequency_hz = frequency_hz;
    restart_sweep(state, 0.0);
    return;
  }
  lidar_range_image(device);  // every beam as the head left it
  const double turned = state.sweep_start_rev + static_cast<double>(steps_ - state.enabled_at_step) *
                                                    spec.frequency_hz * options_.basic_time_step_ms / 1000.0;
  spec.frequency_hz = frequency_hz;
  state.enabled_at_step = steps_;
  restart_sweep(state, turned - std::floor(turned));
  state.sweep_resumed = true;
}

void Simulation::teleport(const maze::sim::Pose &pose, double z_m) {
  require_finite_value(pose.x_m, "the robot's x");
  require_finite_value(pose.y_m, "the robot's y");
  require_finite_value(pose.yaw_rad, "the robot's yaw");
  require_finite_value(z_m, "the robot's z");
  pose_ = {pose.x_m, pose.y_m, common::wrap_angle_rad(pose.yaw_rad)};
  height_m_ = z_m;
  lidar_planes_.place(geometry(), lattice(), profile_, height_m_);
  free_centres_.reset();
  for (DeviceState &state : states_) state.read_at_step = -1;
}

void Simulation::reset_world() {
  if (initial_geometry_) {
    use_geometry(*initial_geometry_);
  } else {
    solids_.reset();
    geometry_.reset();
  }
  teleport(initial_pose_, 0.0);
  for (Wheel &wheel : wheels_) {
    wheel.angle_rad = 0.0;
    wheel.velocity_rad_s = 0.0;
    if (std::isfinite(wheel.target_rad)) wheel.target_rad = 0.0;
  }
  time_ms_ = 0;
}

double Simulation::cast(double x_m, double y_m, double angle_rad, double max_range_m) const {
  return with_solids([&](const auto &solids) { return solids.cast(x_m, y_m, angle_rad, max_range_m); });
}

}  // namespace webots::embedded
