#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "common/error.hpp"
#include "maze/sim/profile.hpp"

TEST_CASE("profiles: hambot is the default and has the course's devices") {
  const maze::sim::RobotProfile &p = maze::sim::default_profile();
  CHECK(p.name == "hambot");
  CHECK(p.wheel_radius_m == 0.045);
  CHECK(p.axle_m == 0.184);
  REQUIRE(p.lidars.size() == 1);
  CHECK(p.lidars[0].name == "lidar");
  CHECK(p.lidars[0].horizontal_resolution == 360);
  CHECK(p.lidars[0].min_range_m == 0.05);
  CHECK(p.lidars[0].max_range_m == 12.0);
  CHECK(p.lidars[0].noise == 0.000833);
  CHECK(p.bumpers.size() == 3);
  CHECK(p.left_motor == "left motor");
  CHECK(p.right_encoder == "right wheel sensor");
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
          "error: unknown robot 'roomba' (known robots: hambot, bumper-depth, ir-ring, sonar-ring)");
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
