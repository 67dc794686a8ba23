#include "maze/sim/profile.hpp"

#include <cassert>
#include <cmath>
#include <numbers>
#include <set>

#include <fmt/format.h>

#include "common/error.hpp"

namespace maze::sim {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// The wheels, motors, encoders, IMU and GPS of FAIRIS-Lite's HamBot (docs/simulator.md, Robots), as
// biorobaw/FAIRIS-Lite WebotsSim/protos/HamBot/HamBot.proto defines them since the Spring
// 2026 course update: wheel radius 0.045 m (the wheels' Cylinder), max wheel speed 20 rad/s
// (both RotationalMotors' maxVelocity), axle 0.184 m (the wheel joints at +-0.092 m). The
// body radius is not in the course material: 0.09 m is our choice (the bounding box is
// 0.19 x 0.15 m).
// The straights a robot drives in one leg (the speed run's, mms's moveForward) ramp: the
// proto sets no acceleration on its motors (Webots' default, unlimited), while a real
// robot's wheels speed up at a finite rate. 1 m/s^2 is our choice: the motors' top speed at
// the wheel's rim, 20 rad/s x 0.045 m = 0.9 m/s, is then reached in 0.9 s over 0.405 m, under
// half of a 1 m cell, so a move of one cell speeds up and slows down visibly, as the real
// robot's does.
constexpr double kHambotAcceleration_m_s2 = 1.0;

RobotProfile base_robot(std::string name, std::string description) {
  RobotProfile p;
  p.name = std::move(name);
  p.description = std::move(description);
  p.wheel_radius_m = 0.045;
  p.axle_m = 0.184;
  p.body_radius_m = 0.09;
  p.max_wheel_velocity_rad_s = 20.0;
  p.left_motor = "left motor";
  p.right_motor = "right motor";
  p.left_encoder = "left wheel encoder";
  p.right_encoder = "right wheel encoder";
  p.imu = "imu";
  p.gps = "gps";
  p.speed_run = SpeedRunProfile{kHambotAcceleration_m_s2, 0.9};  // 20 rad/s x 0.045 m
  return p;
}

// HamBot's Lidar node this term: 360 beams, fieldOfView 2 pi, near and minRange 0.05,
// maxRange 12, noise 0.000833, resolution 0.01, type "fixed".
// The course's HamBot.proto mounts its Lidar 0.13 m above the robot's origin.
constexpr double kHambotLidarHeight_m = 0.13;

LidarSpec hambot_lidar() { return {"lidar", 360, 2.0 * kPi, 0.05, 12.0, 0.000833, 0.0, 0.01, kHambotLidarHeight_m}; }

// Last year's (2025) RotationalMotors: maxVelocity 18 rad/s.
constexpr double kHambot2025MaxWheelVelocity_rad_s = 18.0;

// Last year's motors: their top speed bounds the speed run's too.
void use_2025_motors(RobotProfile &p) {
  p.max_wheel_velocity_rad_s = kHambot2025MaxWheelVelocity_rad_s;
  p.speed_run = SpeedRunProfile{kHambotAcceleration_m_s2, 0.81};  // 18 rad/s x 0.045 m
}

// Last year's (2025) Lidar node: minRange 0.07, maxRange 3, noise 0.000833, no resolution,
// type "rotating" at defaultFrequency 12 Hz.
LidarSpec hambot_2025_lidar(double max_range_m) {
  return {"lidar", 360, 2.0 * kPi, 0.07, max_range_m, 0.000833, 12.0, 0.0, kHambotLidarHeight_m};
}

// Three bumpers at 0 and +-45 deg, each covering a 45 deg arc: together the front 135 deg.
std::vector<BumperSpec> front_bumpers() {
  const double half = 22.5 * kDeg;
  return {{"bumper front", 0.0, half}, {"bumper left", 45.0 * kDeg, half},
          {"bumper right", -45.0 * kDeg, half}};
}

// A table mapping distance to itself (metres) from 0 to range_m with a constant noise fraction.
std::vector<LookupRow> metres_table(double range_m, double noise_fraction) {
  return {{0.0, 0.0, noise_fraction}, {range_m, range_m, noise_fraction}};
}

RobotProfile hambot() {
  RobotProfile p = base_robot("hambot", "the course robot (FAIRIS-Lite HamBot): fixed 360-beam lidar (12 m, 1 cm), IMU, GPS");
  p.lidars.push_back(hambot_lidar());
  return p;
}

// Last year's course robot: its lidar rotates (a revolution at rest before a whole image)
// and sees 3 m, 2.5 cells of 1 m. Kept so that rotating-lidar and short-view behaviour stay
// tested and last year's results can be reproduced.
RobotProfile hambot_2025() {
  RobotProfile p = base_robot("hambot-2025", "last year's HamBot: rotating 360-beam lidar (3 m, 12 Hz), IMU, GPS");
  use_2025_motors(p);
  p.lidars.push_back(hambot_2025_lidar(3.0));
  return p;
}

// Last year's rotating lidar reaching 12 m: the one profile with a rotating head and long
// views together (a rotating image mixes the poses of a turn over far walls too).
RobotProfile hambot_12m() {
  RobotProfile p = base_robot("hambot-12m", "hambot-2025 with its rotating lidar reaching 12 m");
  use_2025_motors(p);
  p.lidars.push_back(hambot_2025_lidar(12.0));
  return p;
}

// For classic 0.18 m micromouse cells with 12 mm walls (0.168 m between wall faces): an
// 0.08 m wide body, 25 mm wheels 0.07 m apart, 80 rad/s (1 m/s). Real mice carry a few IR
// range sensors; this one carries a small fixed 360-beam lidar (a ring of time-of-flight
// sensors), so that the lidar models (cell, ray) run on it unchanged: 0.02 m to 1 m (five
// cells), the hambot's noise fraction.
RobotProfile micromouse() {
  RobotProfile p = base_robot("micromouse", "for 0.18 m cells: 0.04 m body radius, small fixed 360-beam lidar (1 m)");
  p.wheel_radius_m = 0.0125;
  p.axle_m = 0.07;
  p.body_radius_m = 0.04;
  p.max_wheel_velocity_rad_s = 80.0;
  p.lidars.push_back({"lidar", 360, 2.0 * kPi, 0.02, 1.0, 0.000833, 0.0, 0.0, 0.02});
  // Its speed run: 2 m/s^2 up to 1 m/s (the motors' 80 rad/s), straights in one go.
  p.speed_run = SpeedRunProfile{2.0, 1.0};
  return p;
}

// Depth rays as nine single-ray distance sensors: a fan from +60 to -60 deg (left to right,
// like a range image), exact distances up to 4 m.
RobotProfile bumper_depth() {
  RobotProfile p = base_robot("bumper-depth", "three bumpers and nine depth rays over 120 deg");
  p.bumpers = front_bumpers();
  for (int i = 0; i < 9; ++i) {
    p.distance_sensors.push_back(
        {fmt::format("depth{}", i), (60.0 - 15.0 * i) * kDeg, 0.0, 1, metres_table(4.0, 0.0),
         DistanceSensorType::generic});
  }
  return p;
}

// Six IR sensors: the four directions the cell model needs and the two front diagonals.
// Course numbers: aperture 0.03 rad, 3 rays, +-3 % distance error, range 1.5 m. Webots'
// infra-red type: the rays' Gaussian-weighted mean (the walls' colour is not modelled: a
// reflection factor of 1).
RobotProfile ir_ring() {
  RobotProfile p = base_robot("ir-ring", "six IR range sensors, narrow cone, 1.5 m");
  const double angles_deg[] = {0.0, 45.0, 90.0, 180.0, -90.0, -45.0};
  for (int i = 0; i < 6; ++i) {
    p.distance_sensors.push_back({fmt::format("ir{}", i), angles_deg[i] * kDeg, 0.03, 3,
                                  metres_table(1.5, 0.03), DistanceSensorType::infra_red});
  }
  return p;
}

// The IR assignment's Figure 1 (`demo pie`, app/course/demo_pie.hpp): six IR sensors 30 deg
// apart over the robot's front, from +75 deg (left) to -75 deg (right); none looks back.
// Each is ir-ring's sensor (the course's numbers); the pie model's 20 deg slice (--pie-beta
// 10 deg) is the model's, not the beam's.
RobotProfile ir_fan() {
  RobotProfile p = base_robot("ir-fan", "six IR range sensors 30 deg apart over the front (the IR lab's Figure 1), 1.5 m");
  for (int i = 0; i < 6; ++i) {
    p.distance_sensors.push_back({fmt::format("ir{}", i), (75.0 - 30.0 * i) * kDeg, 0.03, 3, metres_table(1.5, 0.03),
                                  DistanceSensorType::infra_red});
  }
  return p;
}

// Eight sonars every 45 deg. Course numbers: aperture 0.4 rad, 5 rays, +-6.6 % distance error.
// Webots' sonar type: the nearest ray, rays beyond 22.5 deg incidence lost.
RobotProfile sonar_ring() {
  RobotProfile p = base_robot("sonar-ring", "eight sonars, wide cone, 5 m");
  for (int i = 0; i < 8; ++i) {
    p.distance_sensors.push_back(
        {fmt::format("so{}", i), 45.0 * i * kDeg, 0.4, 5, metres_table(5.0, 0.066), DistanceSensorType::sonar});
  }
  return p;
}

}  // namespace

std::string_view to_string(DistanceSensorType type) {
  switch (type) {
    case DistanceSensorType::generic: return "generic";
    case DistanceSensorType::infra_red: return "infra-red";
    case DistanceSensorType::sonar: return "sonar";
  }
  return "generic";
}

std::optional<DistanceSensorType> parse_distance_sensor_type(std::string_view text) {
  for (const auto t : {DistanceSensorType::generic, DistanceSensorType::infra_red, DistanceSensorType::sonar}) {
    if (text == to_string(t)) return t;
  }
  return std::nullopt;
}

const std::vector<RobotProfile> &profiles() {
  static const std::vector<RobotProfile> all{hambot(),       hambot_2025(), hambot_12m(), bumper_depth(),
                                             ir_ring(),      ir_fan(),      sonar_ring(),  micromouse()};
  return all;
}

const RobotProfile &default_profile() { return profiles().front(); }

std::string profile_names() {
  std::string names;
  for (const RobotProfile &p : profiles()) {
    if (!names.empty()) names += ", ";
    names += p.name;
  }
  return names;
}

const RobotProfile &find_profile(std::string_view name) {
  for (const RobotProfile &p : profiles()) {
    if (p.name == name) return p;
  }
  throw common::InputError(
      fmt::format("unknown robot '{}' (known robots: {})", name, profile_names()));
}

namespace {

// The index of the first row at or beyond distance_m, clamped to [1, rows - 1].
std::size_t upper_row(const std::vector<LookupRow> &table, double distance_m) {
  std::size_t i = 1;
  while (i + 1 < table.size() && table[i].distance_m < distance_m) ++i;
  return i;
}

double interpolate(const std::vector<LookupRow> &table, double distance_m,
                   double LookupRow::*field) {
  assert(!table.empty());
  if (table.size() == 1 || distance_m <= table.front().distance_m) return table.front().*field;
  if (distance_m >= table.back().distance_m) return table.back().*field;
  const std::size_t i = upper_row(table, distance_m);
  const LookupRow &a = table[i - 1];
  const LookupRow &b = table[i];
  const double f = (distance_m - a.distance_m) / (b.distance_m - a.distance_m);
  return a.*field + f * (b.*field - a.*field);
}

}  // namespace

double lookup_value(const std::vector<LookupRow> &table, double distance_m) {
  return interpolate(table, distance_m, &LookupRow::value);
}

double lookup_noise_fraction(const std::vector<LookupRow> &table, double distance_m) {
  return interpolate(table, distance_m, &LookupRow::noise_fraction);
}

namespace {

[[noreturn]] void bad(const std::string &key, const std::string &what) {
  throw common::InputError(fmt::format("{} {}", key, what));
}

void require_positive(const std::string &key, double value) {
  if (!std::isfinite(value) || value <= 0.0) bad(key, fmt::format("must be a positive number (got {})", value));
}

void require_non_negative(const std::string &key, double value) {
  if (!std::isfinite(value) || value < 0.0) bad(key, fmt::format("must be a finite number >= 0 (got {})", value));
}

void require_finite(const std::string &key, double value) {
  if (!std::isfinite(value)) bad(key, fmt::format("must be a finite number (got {})", value));
}

void require_at_most(const std::string &key, double value, double limit, const char *limit_text) {
  if (value > limit) bad(key, fmt::format("must be at most {} (got {})", limit_text, value));
}

// Each device name once across the robot: Robot::get* finds a device by name alone.
class DeviceNameSet {
 public:
  void add(const std::string &key, const std::string &name, bool required) {
    if (name.empty()) {
      if (required) bad(key, "must name a device");
      return;
    }
    if (!names_.insert(name).second) bad(key, fmt::format("'{}' names a second device", name));
  }

 private:
  std::set<std::string> names_;
};

void validate_lidar(const std::string &key, const LidarSpec &l) {
  if (l.horizontal_resolution < 1 || l.horizontal_resolution > 100000) {
    bad(key + ".horizontal_resolution", fmt::format("must be 1 to 100000 beams (got {})", l.horizontal_resolution));
  }
  require_positive(key + ".fov_rad", l.fov_rad);
  require_at_most(key + ".fov_rad", l.fov_rad, 2.0 * kPi, "2 pi");
  require_non_negative(key + ".min_range_m", l.min_range_m);
  require_finite(key + ".max_range_m", l.max_range_m);
  if (!(l.max_range_m > l.min_range_m)) {
    bad(key + ".max_range_m",
        fmt::format("must be greater than min_range_m (got {} <= {})", l.max_range_m, l.min_range_m));
  }
  require_non_negative(key + ".noise", l.noise);
  require_non_negative(key + ".frequency_hz", l.frequency_hz);
  require_non_negative(key + ".resolution_m", l.resolution_m);
  require_non_negative(key + ".height_m", l.height_m);
}

void validate_distance_sensor(const std::string &key, const DistanceSensorSpec &d) {
  require_finite(key + ".angle_rad", d.angle_rad);
  require_non_negative(key + ".aperture_rad", d.aperture_rad);
  require_at_most(key + ".aperture_rad", d.aperture_rad, kPi, "pi");
  if (d.rays < 1 || d.rays > 1000) bad(key + ".rays", fmt::format("must be 1 to 1000 (got {})", d.rays));
  require_positive(key + ".gaussian_width", d.gaussian_width);
  if (d.axial && !(std::abs(d.angle_rad) < kPi / 2)) bad(key + ".angle_rad", "must be within (-pi/2, pi/2) for an axial depth");
  if (d.origin_m) require_finite(key + ".origin_m", (*d.origin_m)[0] + (*d.origin_m)[1]);
  if (d.lookup_table.empty()) bad(key + ".lookup_table", "must have at least one row");
  for (std::size_t i = 0; i < d.lookup_table.size(); ++i) {
    const std::string row = fmt::format("{}.lookup_table[{}]", key, i);
    const LookupRow &r = d.lookup_table[i];
    require_non_negative(row + ".distance_m", r.distance_m);
    require_finite(row + ".value", r.value);
    require_non_negative(row + ".noise_fraction", r.noise_fraction);
    if (i > 0 && !(r.distance_m > d.lookup_table[i - 1].distance_m)) {
      bad(row + ".distance_m", fmt::format("must be greater than the row before's (got {} <= {})",
                                           r.distance_m, d.lookup_table[i - 1].distance_m));
    }
  }
}

void validate_bumper(const std::string &key, const BumperSpec &b) {
  require_finite(key + ".angle_rad", b.angle_rad);
  require_positive(key + ".half_arc_rad", b.half_arc_rad);
  require_at_most(key + ".half_arc_rad", b.half_arc_rad, kPi, "pi");
}

}  // namespace

void validate_profile(const RobotProfile &p) {
  if (p.name.empty()) bad("name", "must not be empty");
  require_positive("wheel_radius_m", p.wheel_radius_m);
  require_positive("axle_m", p.axle_m);
  require_positive("body_radius_m", p.body_radius_m);
  if (p.speed_run) {
    require_positive("speed_run.acceleration_m_s2", p.speed_run->acceleration_m_s2);
    require_positive("speed_run.top_speed_m_s", p.speed_run->top_speed_m_s);
  }
  require_positive("max_wheel_velocity_rad_s", p.max_wheel_velocity_rad_s);
  DeviceNameSet names;
  names.add("left_motor", p.left_motor, true);
  names.add("right_motor", p.right_motor, true);
  names.add("left_encoder", p.left_encoder, true);
  names.add("right_encoder", p.right_encoder, true);
  names.add("imu", p.imu, false);
  names.add("gps", p.gps, false);
  for (std::size_t i = 0; i < p.lidars.size(); ++i) {
    const std::string key = fmt::format("lidars[{}]", i);
    names.add(key + ".name", p.lidars[i].name, true);
    validate_lidar(key, p.lidars[i]);
  }
  for (std::size_t i = 0; i < p.distance_sensors.size(); ++i) {
    const std::string key = fmt::format("distance_sensors[{}]", i);
    names.add(key + ".name", p.distance_sensors[i].name, true);
    validate_distance_sensor(key, p.distance_sensors[i]);
  }
  for (std::size_t i = 0; i < p.bumpers.size(); ++i) {
    const std::string key = fmt::format("bumpers[{}]", i);
    names.add(key + ".name", p.bumpers[i].name, true);
    validate_bumper(key, p.bumpers[i]);
  }
}

}  // namespace maze::sim
