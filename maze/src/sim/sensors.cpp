#include "maze/sim/sensors.hpp"

#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "common/angles.hpp"
#include "common/error.hpp"

namespace maze::sim {

namespace {
std::uint64_t sensor_seed(std::uint64_t seed, int device, std::int64_t step) {
  const auto d = static_cast<std::uint64_t>(device) + 1;
  const auto s = static_cast<std::uint64_t>(step);
  return seed ^ (d * 0x9e3779b97f4a7c15ULL) ^ (s * 0xd1b54a32d192ed03ULL);
}
}  // namespace

common::Rng sensor_rng(std::uint64_t seed, int device, std::int64_t step) {
  return common::Rng(sensor_seed(seed, device, step));
}

std::uint64_t beam_seed(std::uint64_t seed, int device, std::int64_t step, int beam) {
  const auto b = static_cast<std::uint64_t>(beam) + 1;
  return sensor_seed(seed ^ (b * 0xbf58476d1ce4e5b9ULL), device, step);
}

common::Rng beam_rng(std::uint64_t seed, int device, std::int64_t step, int beam) {
  return common::Rng(beam_seed(seed, device, step, beam));
}

void check_pose_free(const WallGrid &walls, const Pose &pose) {
  if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.yaw_rad)) {
    throw common::InputError("the pose must be finite numbers");
  }
  if (!walls.inside_maze(pose.x_m, pose.y_m)) {
    throw common::InputError(
        fmt::format("pose ({}, {}) is outside the maze", pose.x_m, pose.y_m));
  }
  if (walls.inside_wall(pose.x_m, pose.y_m)) {
    throw common::InputError(fmt::format("pose ({}, {}) is inside a wall", pose.x_m, pose.y_m));
  }
}

double beam_angle_rad(const LidarSpec &lidar, int i) {
  return lidar.fov_rad / 2.0 - i * lidar.fov_rad / lidar.horizontal_resolution;
}

LidarModel::LidarModel(const LidarSpec &spec) : spec_(spec) {
  assert(spec.horizontal_resolution >= 1);
  for (int i = 0; i < spec.horizontal_resolution; ++i) {
    cos_.push_back(std::cos(beam_angle_rad(spec, i)));
    sin_.push_back(std::sin(beam_angle_rad(spec, i)));
    const double turn = -beam_angle_rad(spec, i) / (2.0 * std::numbers::pi);
    sweep_phase_.push_back(turn - std::floor(turn));
  }
}

void LidarModel::range_image(const WallGrid &walls, double noise, const Pose &pose,
                             common::Rng &rng, std::span<float> out) const {
  assert(out.size() == cos_.size());
  const double sigma_m = noise * spec_.max_range_m;
  // Cast a little past max range so that noise can bring a far hit back into range.
  const double reach_m = spec_.max_range_m + 6.0 * sigma_m;
  const double c = std::cos(pose.yaw_rad);
  const double s = std::sin(pose.yaw_rad);
  constexpr float kNoReturn = std::numeric_limits<float>::infinity();
  const WallGrid::CastOrigin origin = walls.cast_origin(pose.x_m, pose.y_m);
  for (std::size_t i = 0; i < cos_.size(); ++i) {
    const double dx = c * cos_[i] - s * sin_[i];
    const double dy = s * cos_[i] + c * sin_[i];
    double range = walls.cast_from(origin, dx, dy, reach_m);
    if (sigma_m > 0.0) range += rng.normal(0.0, sigma_m);
    const bool in_range = range >= spec_.min_range_m && range <= spec_.max_range_m;
    out[i] = in_range ? static_cast<float>(range) : kNoReturn;
  }
}

LidarModel::Viewpoint LidarModel::viewpoint(const WallGrid &walls, const Pose &pose) {
  return {walls.cast_origin(pose.x_m, pose.y_m), std::cos(pose.yaw_rad), std::sin(pose.yaw_rad)};
}

float LidarModel::beam_range(const WallGrid &walls, double noise, const Viewpoint &from, int i,
                             std::uint64_t noise_seed) const {
  const auto b = static_cast<std::size_t>(i);
  assert(b < cos_.size());
  const double sigma_m = noise * spec_.max_range_m;
  const double reach_m = spec_.max_range_m + 6.0 * sigma_m;
  const double dx = from.cos_yaw * cos_[b] - from.sin_yaw * sin_[b];
  const double dy = from.sin_yaw * cos_[b] + from.cos_yaw * sin_[b];
  double range = walls.cast_from(from.origin, dx, dy, reach_m);
  if (sigma_m > 0.0) range += sigma_m * common::Rng::first_normal(noise_seed);
  const bool in_range = range >= spec_.min_range_m && range <= spec_.max_range_m;
  return in_range ? static_cast<float>(range) : std::numeric_limits<float>::infinity();
}

double distance_sensor_value(const WallGrid &walls, const DistanceSensorSpec &sensor,
                             double body_radius_m, const Pose &pose, bool noisy,
                             common::Rng &rng) {
  assert(sensor.rays >= 1 && !sensor.lookup_table.empty());
  const double direction = pose.yaw_rad + sensor.angle_rad;
  const double ox = pose.x_m + body_radius_m * std::cos(direction);
  const double oy = pose.y_m + body_radius_m * std::sin(direction);
  const double reach_m = sensor.lookup_table.back().distance_m;
  double weighted = 0.0;
  double weights = 0.0;
  for (int k = 0; k < sensor.rays; ++k) {
    const double offset =
        sensor.rays == 1 ? 0.0
                         : -sensor.aperture_rad / 2.0 + k * sensor.aperture_rad / (sensor.rays - 1);
    const double w =
        sensor.aperture_rad > 0.0 ? std::exp(-std::pow(offset / sensor.aperture_rad, 2)) : 1.0;
    const double d = std::min(walls.cast(ox, oy, direction + offset, reach_m), reach_m);
    weighted += w * d;
    weights += w;
  }
  const double distance = weighted / weights;
  double value = lookup_value(sensor.lookup_table, distance);
  const double fraction = lookup_noise_fraction(sensor.lookup_table, distance);
  if (noisy && fraction > 0.0) value += rng.normal(0.0, fraction * value);
  return value;
}

bool bumper_pressed(const WallGrid &walls, const BumperSpec &bumper, double body_radius_m,
                    const Pose &pose) {
  for (const Contact &c : walls.contacts(pose.x_m, pose.y_m, body_radius_m + kContactTolerance_m)) {
    const double bearing = std::atan2(c.y_m - pose.y_m, c.x_m - pose.x_m) - pose.yaw_rad;
    if (std::abs(common::wrap_angle_rad(bearing - bumper.angle_rad)) <= bumper.half_arc_rad + 1e-12) {
      return true;
    }
  }
  return false;
}

}  // namespace maze::sim
