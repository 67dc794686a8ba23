#include "app/report/trace_sensors.hpp"

#include <algorithm>
#include <iterator>

#include <fmt/format.h>
#include <webots/DistanceSensor.hpp>
#include <webots/GPS.hpp>
#include <webots/InertialUnit.hpp>
#include <webots/Robot.hpp>
#include <webots/TouchSensor.hpp>

#include "common/fixed_decimal.hpp"
#include "sensing/setups.hpp"

namespace app {
namespace {

// The bumpers as right, left, front (by the sign of their angle), or none when the robot's
// are not one of each.
std::vector<webots::TouchSensor *> bump_columns(webots::Robot &robot, const std::vector<robot::BumperMount> &mounts) {
  std::vector<webots::TouchSensor *> found(3, nullptr);
  for (const robot::BumperMount &m : mounts) {
    const std::size_t role = m.angle_rad < 0.0 ? 0 : (m.angle_rad > 0.0 ? 1 : 2);
    if (found[role] != nullptr) return {};
    found[role] = robot.getTouchSensor(m.name);
  }
  if (std::count(found.begin(), found.end(), nullptr) > 0) return {};
  return found;
}

}  // namespace

TraceSensors::TraceSensors(webots::Robot &robot, const robot::ControllerOptions &options)
    : gps_(options.devices.gps.empty() ? nullptr : robot.getGPS(options.devices.gps)),
      imu_(robot.getInertialUnit(options.devices.imu)) {
  if (gps_ != nullptr) header_ += ",gps_x_m,gps_y_m";
  if (imu_ != nullptr) header_ += ",imu_yaw_rad";
  const sensing::SetUp &setup = sensing::setup(options.model.kind);
  if (setup.reads_bumpers()) {
    bumps_ = bump_columns(robot, options.sensing.bumpers);
    if (!bumps_.empty()) header_ += ",bump_right,bump_left,bump_front";
  }
  if (options.model.kind == sensing::ModelKind::depth) {
    std::vector<robot::RangeSensorMount> mounts = options.sensing.ranges;
    std::stable_sort(mounts.begin(), mounts.end(),
                     [](const auto &a, const auto &b) { return a.angle_rad > b.angle_rad; });
    for (const robot::RangeSensorMount &m : mounts) {
      webots::DistanceSensor *sensor = robot.getDistanceSensor(m.name);
      if (sensor == nullptr) continue;
      depths_.push_back({sensor, m.offset_m, m.max_range_m});
      header_ += fmt::format(",depth_{}_m", depths_.size());
    }
  }
}

void TraceSensors::append_values(std::string &csv) const {
  const auto metres = [&csv](double v) {  // ",{:.4f}"
    csv += ',';
    common::append_fixed(csv, v, 4);
  };
  if (gps_ != nullptr) {
    const double *v = gps_->getValues();
    metres(v[0]);
    metres(v[1]);
  }
  if (imu_ != nullptr) metres(imu_->getRollPitchYaw()[2]);
  for (const webots::TouchSensor *b : bumps_) csv += b->getValue() > 0.5 ? ",1" : ",0";
  for (const Depth &d : depths_) {
    const double reading_m = d.sensor->getValue();
    const bool nothing = !(reading_m < d.max_range_m);
    metres(nothing ? 0.0 : reading_m + d.offset_m);
  }
}

}  // namespace app
