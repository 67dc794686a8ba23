#include "maze/sim/profile.hpp"

#include <cassert>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "common/error.hpp"

namespace maze::sim {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// The hambot of the Webots maze labs (DESIGN §5). The body radius and the maximum wheel
// velocity are not in the course material; 0.09 m and 25 rad/s (1.1 m/s) are our choice.
RobotProfile base_robot(std::string name, std::string description) {
  RobotProfile p;
  p.name = std::move(name);
  p.description = std::move(description);
  p.wheel_radius_m = 0.045;
  p.axle_m = 0.184;
  p.body_radius_m = 0.09;
  p.max_wheel_velocity_rad_s = 25.0;
  p.left_motor = "left motor";
  p.right_motor = "right motor";
  p.left_encoder = "left wheel sensor";
  p.right_encoder = "right wheel sensor";
  p.imu = "imu";
  p.gps = "gps";
  return p;
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
  RobotProfile p = base_robot("hambot", "course robot: 360-beam lidar, IMU, GPS, three bumpers");
  p.lidars.push_back({"lidar", 360, 2.0 * kPi, 0.05, 12.0, 0.000833});
  p.bumpers = front_bumpers();
  return p;
}

// Depth rays as nine single-ray distance sensors: a fan from +60 to -60 deg (left to right,
// like a range image), exact distances up to 4 m.
RobotProfile bumper_depth() {
  RobotProfile p = base_robot("bumper-depth", "three bumpers and nine depth rays over 120 deg");
  p.bumpers = front_bumpers();
  for (int i = 0; i < 9; ++i) {
    p.distance_sensors.push_back(
        {fmt::format("depth{}", i), (60.0 - 15.0 * i) * kDeg, 0.0, 1, metres_table(4.0, 0.0)});
  }
  return p;
}

// Six IR sensors: the four directions the cell model needs and the two front diagonals.
// Course numbers: aperture 0.03 rad, 3 rays, +-3 % distance error, range 1.5 m.
RobotProfile ir_ring() {
  RobotProfile p = base_robot("ir-ring", "six IR range sensors, narrow cone, 1.5 m");
  const double angles_deg[] = {0.0, 45.0, 90.0, 180.0, -90.0, -45.0};
  for (int i = 0; i < 6; ++i) {
    p.distance_sensors.push_back({fmt::format("ir{}", i), angles_deg[i] * kDeg, 0.03, 3,
                                  metres_table(1.5, 0.03)});
  }
  return p;
}

// Eight sonars every 45 deg. Course numbers: aperture 0.4 rad, 5 rays, +-6.6 % distance error.
RobotProfile sonar_ring() {
  RobotProfile p = base_robot("sonar-ring", "eight sonars, wide cone, 5 m");
  for (int i = 0; i < 8; ++i) {
    p.distance_sensors.push_back(
        {fmt::format("so{}", i), 45.0 * i * kDeg, 0.4, 5, metres_table(5.0, 0.066)});
  }
  return p;
}

}  // namespace

const std::vector<RobotProfile> &profiles() {
  static const std::vector<RobotProfile> all{hambot(), bumper_depth(), ir_ring(), sonar_ring()};
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

}  // namespace maze::sim
