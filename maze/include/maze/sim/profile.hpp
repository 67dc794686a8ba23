#pragma once
// Robot profiles: which wheels and devices a simulated robot has, as data (DESIGN §5).
// `--robot NAME` selects one; find_profile() says which names exist.
//
// Device names (the strings a controller passes to Robot::get*):
//
// | profile        | motors / encoders              | other devices                              |
// |----------------|--------------------------------|--------------------------------------------|
// | hambot         | "left motor", "right motor",   | Lidar "lidar" (360 beams, 2 pi, 0.05-12 m, |
// |  (default)     | "left wheel sensor",           |   noise 0.000833); InertialUnit "imu";     |
// |                | "right wheel sensor"           |   GPS "gps"; TouchSensor "bumper front",   |
// |                |                                |   "bumper left" (+45 deg), "bumper right"  |
// | bumper-depth   | as hambot                      | imu, gps, the three bumpers; DistanceSensor|
// |                |                                |   "depth0" ... "depth8" (+60 deg ... -60   |
// |                |                                |   deg in 15 deg steps, one ray, 0-4 m)     |
// | ir-ring        | as hambot                      | imu, gps; DistanceSensor "ir0" ... "ir5"   |
// |                |                                |   (0, +45, +90, 180, -90, -45 deg; 1.5 m)  |
// | sonar-ring     | as hambot                      | imu, gps; DistanceSensor "so0" ... "so7"   |
// |                |                                |   (every 45 deg from 0 ccw; 5 m)           |
//
// Angles are relative to the robot's heading, counter-clockwise positive (+90 deg = left).
// Distance sensors sit on the body's rim and look outward; the lidar sits at the centre.
// A distance sensor's value is in metres of distance (its lookup table maps distance d to
// value d), so the controller reads metres as from the lidar.

#include <string>
#include <string_view>
#include <vector>

namespace maze::sim {

struct LidarSpec {
  std::string name;
  int horizontal_resolution = 360;  // beams in the one layer
  double fov_rad = 0.0;
  double min_range_m = 0.0;
  double max_range_m = 0.0;
  double noise = 0.0;  // Gaussian sigma as a fraction of max_range_m (Webots' `noise`)
};

// One row of a Webots lookup table: at distance_m the sensor returns value, with Gaussian
// noise of standard deviation noise_fraction x value. Linear between rows; clamped outside.
struct LookupRow {
  double distance_m;
  double value;
  double noise_fraction;
};

struct DistanceSensorSpec {
  std::string name;
  double angle_rad = 0.0;     // mounting direction relative to the heading
  double aperture_rad = 0.0;  // the cone the rays spread over
  int rays = 1;
  std::vector<LookupRow> lookup_table;  // increasing distance
};

struct BumperSpec {
  std::string name;
  double angle_rad = 0.0;       // centre of the bumper's arc relative to the heading
  double half_arc_rad = 0.0;    // pressed by a contact within +- half_arc_rad of angle_rad
};

struct RobotProfile {
  std::string name;
  std::string description;
  double wheel_radius_m = 0.0;
  double axle_m = 0.0;  // distance between the wheels
  double body_radius_m = 0.0;
  double max_wheel_velocity_rad_s = 0.0;
  std::string left_motor, right_motor;
  std::string left_encoder, right_encoder;
  std::string imu, gps;  // empty: the robot has none
  std::vector<LidarSpec> lidars;
  std::vector<DistanceSensorSpec> distance_sensors;
  std::vector<BumperSpec> bumpers;
};

// Every profile, the default (hambot) first.
const std::vector<RobotProfile> &profiles();
const RobotProfile &default_profile();
// The profile called name; throws common::InputError naming the known profiles otherwise.
const RobotProfile &find_profile(std::string_view name);
// "hambot, bumper-depth, ir-ring, sonar-ring"
std::string profile_names();

// The value of a lookup table at distance_m (linear between rows, clamped outside) and the
// noise fraction there. The table has at least one row.
double lookup_value(const std::vector<LookupRow> &table, double distance_m);
double lookup_noise_fraction(const std::vector<LookupRow> &table, double distance_m);

}  // namespace maze::sim
