// A supervisor's edits of a simulation's world (maze/sim/simulation.hpp): solids added, the
// robot teleported, the world reset, a line of sight cast.

#include <cmath>

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

}  // namespace

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
