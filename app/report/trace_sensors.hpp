#pragma once
// The robot's own readings in trace.csv, under the names `maze_mapper map-log`
// reads, so that a bump or depth run can be mapped again offline at another resolution.
// Columns after trace_header()'s, as the robot has the devices:
//
//   gps_x_m,gps_y_m            the GPS as the robot reads it (the position its models map
//                              from; absent without a GPS, when the robot maps from the cell's
//                              centre instead)
//   imu_yaw_rad                the IMU's yaw (0 east, counter-clockwise)
//   bump_right,bump_left,      the bump set-up: 1 pressed, 0 not; the bumpers at -45, +45 and
//   bump_front                 0 deg from the heading (a robot whose bumpers are not one of
//                              each writes none)
//   depth_1_m ... depth_N_m    the depth set-up: the N range sensors, left to right (angle
//                              descending), as distances from the robot's centre (the
//                              reading plus the sensor's mount offset); 0 when the ray saw
//                              nothing (a reading at or beyond its max range)
//
// map-log reads gps_x_m/gps_y_m/imu_yaw_rad/time_s as x/y/theta/t and depth_n_m as depth_n.

#include <string>
#include <vector>

#include "robot/options.hpp"

namespace webots {
class DistanceSensor;
class GPS;
class InertialUnit;
class Robot;
class TouchSensor;
}  // namespace webots

namespace app {

class TraceSensors {
 public:
  // Finds the devices of the controller's options in the robot (enabled by the controller).
  // The robot must outlive this.
  TraceSensors(webots::Robot &robot, const robot::ControllerOptions &options);

  // ",gps_x_m,...": the columns to append to trace_header()'s, without a line end.
  const std::string &header() const { return header_; }
  // ",1.5000,...": the readings now, in the header's order, without a line end.
  void append_values(std::string &csv) const;

 private:
  struct Depth {
    webots::DistanceSensor *sensor = nullptr;
    double offset_m = 0.0;
    double max_range_m = 0.0;
  };
  webots::GPS *gps_ = nullptr;
  webots::InertialUnit *imu_ = nullptr;
  std::vector<webots::TouchSensor *> bumps_;  // right, left, front
  std::vector<Depth> depths_;                 // left to right
  std::string header_;
};

}  // namespace app
