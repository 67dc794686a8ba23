#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "common/error.hpp"
#include "maze/sim/profile.hpp"

// FAIRIS-Lite's HamBot.proto and hambot.py (biorobaw/FAIRIS-Lite, WebotsSim/protos/HamBot/).
TEST_CASE("profiles: hambot is the default and is the course robot exactly") {
  const maze::sim::RobotProfile &p = maze::sim::default_profile();
  CHECK(p.name == "hambot");
  CHECK(p.wheel_radius_m == 0.045);
  CHECK(p.axle_m == 0.184);
  CHECK(p.max_wheel_velocity_rad_s == 20.0);
  CHECK(p.left_motor == "left motor");
  CHECK(p.right_motor == "right motor");
  CHECK(p.left_encoder == "left wheel encoder");
  CHECK(p.right_encoder == "right wheel encoder");
  CHECK(p.imu == "imu");
  CHECK(p.gps == "gps");
  REQUIRE(p.lidars.size() == 1);
  CHECK(p.lidars[0].name == "lidar");
  CHECK(p.lidars[0].horizontal_resolution == 360);
  CHECK(p.lidars[0].fov_rad == 2.0 * std::numbers::pi);
  CHECK(p.lidars[0].min_range_m == 0.05);
  CHECK(p.lidars[0].max_range_m == 12.0);
  CHECK(p.lidars[0].noise == 0.000833);
  CHECK(p.lidars[0].frequency_hz == 0.0);  // type "fixed"
  CHECK(p.lidars[0].resolution_m == 0.01);
  CHECK(p.axle_m == 0.184);
  CHECK(p.wheel_radius_m == 0.045);
  CHECK(p.max_wheel_velocity_rad_s == 20.0);
  CHECK(p.bumpers.empty());
  CHECK(p.distance_sensors.empty());
}

TEST_CASE("profiles: hambot-2025 is last year's robot, motors of 18 rad/s; hambot-12m its rotating lidar reaching 12 m") {
  maze::sim::RobotProfile last_year = maze::sim::find_profile("hambot-2025");
  REQUIRE(last_year.lidars.size() == 1);
  CHECK(last_year.lidars[0].min_range_m == 0.07);
  CHECK(last_year.lidars[0].max_range_m == 3.0);
  CHECK(last_year.lidars[0].frequency_hz == 12.0);
  CHECK(last_year.lidars[0].resolution_m == 0.0);
  CHECK(last_year.max_wheel_velocity_rad_s == 18.0);
  // The speed run's top speed is the motors' at the wheel's rim: 18 x 0.045 m/s, and this term's 20 x 0.045.
  REQUIRE(last_year.speed_run);
  CHECK(last_year.speed_run->top_speed_m_s == 0.81);
  CHECK(maze::sim::default_profile().speed_run->top_speed_m_s == 0.9);
  // The same wheels and devices as this term's robot: only the lidar and the motors' maximum (and the speed run's top speed with it) differ.
  maze::sim::RobotProfile as_today = last_year;
  as_today.max_wheel_velocity_rad_s = maze::sim::default_profile().max_wheel_velocity_rad_s;
  as_today.speed_run = maze::sim::default_profile().speed_run;  // its top speed, the motors'
  as_today.name = "hambot";
  as_today.description = maze::sim::default_profile().description;
  as_today.lidars = maze::sim::default_profile().lidars;
  CHECK(as_today == maze::sim::default_profile());

  maze::sim::RobotProfile long_range = maze::sim::find_profile("hambot-12m");
  CHECK(long_range.lidars.at(0).max_range_m == 12.0);
  long_range.lidars[0].max_range_m = 3.0;
  long_range.name = "hambot-2025";
  long_range.description = last_year.description;
  CHECK(long_range == last_year);
}

TEST_CASE("profiles: micromouse fits a 0.18 m cell") {
  const maze::sim::RobotProfile &mouse = maze::sim::find_profile("micromouse");
  const double between_walls_m = 0.18 - 0.012;
  CHECK(2.0 * mouse.body_radius_m < between_walls_m / 2.0);  // room to turn and to miss
  CHECK(mouse.axle_m < 2.0 * mouse.body_radius_m);
  REQUIRE(mouse.lidars.size() == 1);
  CHECK(mouse.lidars[0].frequency_hz == 0.0);
  CHECK(mouse.lidars[0].min_range_m < between_walls_m / 2.0);  // sees the walls of its own cell
  CHECK(mouse.lidars[0].max_range_m == 1.0);
}

TEST_CASE("profiles: every built-in is valid") {
  for (const maze::sim::RobotProfile &p : maze::sim::profiles()) {
    CAPTURE(p.name);
    CHECK_NOTHROW(maze::sim::validate_profile(p));
  }
}

namespace {

std::string validation_error(const maze::sim::RobotProfile &p) {
  try {
    maze::sim::validate_profile(p);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "no error";
}

}  // namespace

TEST_CASE("validate_profile: the first bad field by its key path") {
  maze::sim::RobotProfile p = maze::sim::default_profile();
  p.lidars[0].max_range_m = 0.05;
  CHECK(validation_error(p) == "error: lidars[0].max_range_m must be greater than min_range_m (got 0.05 <= 0.05)");
  p = maze::sim::default_profile();
  p.lidars[0].resolution_m = -0.01;
  CHECK(validation_error(p) == "error: lidars[0].resolution_m must be a finite number >= 0 (got -0.01)");
  p = maze::sim::default_profile();
  p.lidars[0].fov_rad = 7.0;
  CHECK(validation_error(p) == "error: lidars[0].fov_rad must be at most 2 pi (got 7)");
  p = maze::sim::default_profile();
  p.lidars[0].frequency_hz = -1.0;
  CHECK(validation_error(p) == "error: lidars[0].frequency_hz must be a finite number >= 0 (got -1)");
  p = maze::sim::default_profile();
  p.wheel_radius_m = 0.0;
  CHECK(validation_error(p) == "error: wheel_radius_m must be a positive number (got 0)");
  p = maze::sim::default_profile();
  p.gps = "imu";
  CHECK(validation_error(p) == "error: gps 'imu' names a second device");
  p = maze::sim::default_profile();
  p.left_encoder.clear();
  CHECK(validation_error(p) == "error: left_encoder must name a device");
  p = maze::sim::find_profile("ir-ring");
  p.distance_sensors[2].lookup_table[1].distance_m = 0.0;
  CHECK(validation_error(p) ==
        "error: distance_sensors[2].lookup_table[1].distance_m must be greater than the row before's (got 0 <= 0)");
  p = maze::sim::find_profile("bumper-depth");
  p.bumpers[1].half_arc_rad = 0.0;
  CHECK(validation_error(p) == "error: bumpers[1].half_arc_rad must be a positive number (got 0)");
}

TEST_CASE("profiles: the ring and depth robots carry the course's cone numbers") {
  const auto &ir = maze::sim::find_profile("ir-ring");
  REQUIRE(ir.distance_sensors.size() == 6);
  CHECK(ir.distance_sensors[0].aperture_rad == 0.03);
  CHECK(ir.distance_sensors[0].rays == 3);
  CHECK(ir.distance_sensors[0].lookup_table.back().distance_m == 1.5);
  CHECK(ir.distance_sensors[0].lookup_table.back().noise_fraction == 0.03);
  const auto &sonar = maze::sim::find_profile("sonar-ring");
  CHECK(sonar.distance_sensors[0].aperture_rad == 0.4);
  CHECK(sonar.distance_sensors[0].rays == 5);
  CHECK(sonar.distance_sensors[0].lookup_table.back().noise_fraction == 0.066);
  const auto &depth = maze::sim::find_profile("bumper-depth");
  CHECK(depth.distance_sensors.size() == 9);
  CHECK(depth.bumpers.size() == 3);
  CHECK(depth.lidars.empty());
}

TEST_CASE("find_profile: an unknown name lists the known ones") {
  try {
    maze::sim::find_profile("roomba");
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() ==
          "error: unknown robot 'roomba' (known robots: hambot, hambot-2025, hambot-12m, bumper-depth, ir-ring, "
          "ir-fan, sonar-ring, micromouse)");
  }
}

TEST_CASE("lookup tables: linear between rows, clamped outside") {
  const std::vector<maze::sim::LookupRow> table{{0.1, 1000.0, 0.1}, {0.5, 200.0, 0.05}, {1.0, 0.0, 0.0}};
  CHECK(maze::sim::lookup_value(table, 0.0) == 1000.0);
  CHECK(maze::sim::lookup_value(table, 0.1) == 1000.0);
  CHECK(maze::sim::lookup_value(table, 0.3) == doctest::Approx(600.0));
  CHECK(maze::sim::lookup_value(table, 0.5) == doctest::Approx(200.0));
  CHECK(maze::sim::lookup_value(table, 0.75) == doctest::Approx(100.0));
  CHECK(maze::sim::lookup_value(table, 3.0) == 0.0);
  CHECK(maze::sim::lookup_noise_fraction(table, 0.3) == doctest::Approx(0.075));
}
