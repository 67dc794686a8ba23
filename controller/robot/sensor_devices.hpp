#pragma once
// The devices a set-up reads (its row in sensing/setups.hpp: a lidar, bumpers or a ring of
// range sensors), found on the robot once, and their readings in the world frame: what the
// cell robot's Senses (robot/senses.hpp) and the room robot's MetricSenses
// (robot/metric/senses.hpp) both read with, before each marks its own grid.

#include <vector>

#include "mapping/grid_types.hpp"
#include "robot/options.hpp"
#include "sensing/range_models.hpp"
#include "sensing/scan.hpp"
#include "sensing/setups.hpp"

namespace webots {
class DistanceSensor;
class Lidar;
class Robot;
class TouchSensor;
}  // namespace webots

namespace robot {

struct SensorDevices {
  // Finds the devices `setup` reads (common::InputError naming one the robot lacks).
  SensorDevices(webots::Robot &robot, const ControllerOptions &options, const sensing::SetUp &setup);
  void enable(int time_step_ms);

  webots::Lidar *lidar = nullptr;                      // set-ups that read a lidar
  std::vector<webots::TouchSensor *> bumpers;          // as options.sensing.bumpers
  std::vector<webots::DistanceSensor *> range_sensors;  // as options.sensing.ranges
};

// The lidar's range image now, as a scan taken at `origin` facing yaw_rad (a fixed lidar's
// beams sit half a beam in, a rotating one's not); common::RuntimeFailure without an image.
// The scan's ranges point into the device's image: valid until the next step.
sensing::LidarScan lidar_scan(const webots::Lidar &lidar, mapping::Point origin, double yaw_rad);

// Every range sensor's reading now in the world frame (the sensor on its mount, `mounts[i]`
// for range_sensors[i], at its origin when it has one; an axial depth as its range along the
// ray), the robot's centre at `centre` facing yaw_rad; into `out`, cleared.
void read_range_sensors(const std::vector<webots::DistanceSensor *> &sensors,
                        const std::vector<RangeSensorMount> &mounts, mapping::Point centre, double yaw_rad,
                        std::vector<sensing::RangeReading> &out);

}  // namespace robot
