// The devices a set-up reads (robot/sensor_devices.hpp).

#include "robot/sensor_devices.hpp"

#include <cmath>
#include <span>

#include <webots/DistanceSensor.hpp>
#include <webots/Lidar.hpp>
#include <webots/Robot.hpp>
#include <webots/TouchSensor.hpp>

#include "common/error.hpp"
#include "robot/require_device.hpp"

namespace robot {

SensorDevices::SensorDevices(webots::Robot &robot, const ControllerOptions &options, const sensing::SetUp &setup) {
  if (setup.reads_lidar()) {
    lidar = require_device(robot.getLidar(options.devices.lidar), options.devices.lidar);
  } else if (setup.reads_bumpers()) {
    for (const BumperMount &b : options.sensing.bumpers) bumpers.push_back(require_device(robot.getTouchSensor(b.name), b.name));
  } else {
    for (const RangeSensorMount &r : options.sensing.ranges) {
      range_sensors.push_back(require_device(robot.getDistanceSensor(r.name), r.name));
    }
  }
}

void SensorDevices::enable(int time_step_ms) {
  if (lidar != nullptr) lidar->enable(time_step_ms);
  for (webots::TouchSensor *b : bumpers) b->enable(time_step_ms);
  for (webots::DistanceSensor *r : range_sensors) r->enable(time_step_ms);
}

sensing::LidarScan lidar_scan(const webots::Lidar &lidar, mapping::Point origin, double yaw_rad) {
  const float *ranges = lidar.getRangeImage();
  if (ranges == nullptr) throw common::RuntimeFailure("the lidar returned no range image");
  sensing::LidarScan s;
  s.origin = origin;
  s.yaw_rad = yaw_rad;
  s.fov_rad = lidar.getFov();
  s.min_range_m = lidar.getMinRange();
  s.max_range_m = lidar.getMaxRange();
  s.beam_offset = lidar.getFrequency() > 0.0 ? 0.0 : 0.5;
  s.ranges = std::span<const float>(ranges, static_cast<std::size_t>(lidar.getHorizontalResolution()));
  return s;
}

void read_range_sensors(const std::vector<webots::DistanceSensor *> &sensors,
                        const std::vector<RangeSensorMount> &mounts, mapping::Point centre, double yaw_rad,
                        std::vector<sensing::RangeReading> &out) {
  out.clear();
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    const RangeSensorMount &m = mounts[i];
    const webots::DistanceSensor &sensor = *sensors[i];
    const double a = yaw_rad + m.angle_rad;
    mapping::Point origin{centre.x_m + m.offset_m * std::cos(a), centre.y_m + m.offset_m * std::sin(a)};
    if (m.origin) {
      origin = {centre.x_m + m.origin->x_m * std::cos(yaw_rad) - m.origin->y_m * std::sin(yaw_rad),
                centre.y_m + m.origin->x_m * std::sin(yaw_rad) + m.origin->y_m * std::cos(yaw_rad)};
    }
    double value = sensor.getValue();
    if (m.axial && value < m.max_range_m) value /= std::cos(m.angle_rad);  // the depth's range along its ray
    out.push_back({origin, a, value, m.max_range_m, m.aperture_rad, m.range_error,
                   sensor.getType() == webots::DistanceSensor::SONAR});
  }
}

}  // namespace robot
