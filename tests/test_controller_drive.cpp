#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "common/angles.hpp"
#include "robot/drive.hpp"

// The motion loop without the simulator: a chassis that moves exactly as its wheel speeds
// say (a differential drive integrated over each step), and steps counted here.

namespace {

using mapping::Heading;
using mapping::Point;

struct FakeChassis final : robot::Chassis {
  double x_m = 0.5, y_m = 0.5, yaw = std::numbers::pi / 2;  // facing north
  double left_rad = 0.0, right_rad = 0.0;                    // encoders
  double left_rad_s = 0.0, right_rad_s = 0.0;                // commanded
  bool has_gps = false;
  bool stuck = false;  // the wheels spin, the body does not move
  double radius_m = 0.045, axle_m = 0.184;

  double yaw_rad() const override { return yaw; }
  robot::WheelAngles wheel_angles() const override { return {left_rad, right_rad}; }
  std::optional<Point> gps() const override { return has_gps ? std::optional<Point>(Point{x_m, y_m}) : std::nullopt; }
  double max_wheel_speed_rad_s() const override { return 18.0; }
  void set_wheel_speeds(double l, double r) override {
    left_rad_s = l;
    right_rad_s = r;
  }
  void advance(double dt_s) {
    left_rad += left_rad_s * dt_s;
    right_rad += right_rad_s * dt_s;
    if (stuck) return;
    const double v = radius_m * (left_rad_s + right_rad_s) / 2.0;
    const double w = radius_m * (right_rad_s - left_rad_s) / axle_m;
    x_m += v * std::cos(yaw) * dt_s;
    y_m += v * std::sin(yaw) * dt_s;
    yaw = common::wrap_angle_rad(yaw + w * dt_s);
  }
};

struct Rig {
  FakeChassis chassis;
  robot::MotionOptions options;
  int steps = 0;
  int rest_steps = 0;
  int limit = 10'000;
  robot::Drive drive{chassis, options, 32, [this](robot::Action a) {
                       if (steps >= limit) return robot::Motion::max_steps;
                       chassis.advance(0.032);
                       ++steps;
                       if (a == robot::Action::rest) ++rest_steps;
                       return robot::Motion::ok;
                     }};
};

}  // namespace

TEST_CASE("Drive: a turn ends within the yaw tolerance, at rest, and no turn takes no step") {
  Rig rig;
  REQUIRE(rig.drive.turn_to(Heading::east) == robot::Motion::ok);
  CHECK(rig.drive.moved());
  CHECK(std::abs(rig.chassis.yaw) < rig.options.yaw_tolerance_rad);
  CHECK(rig.chassis.left_rad_s == 0.0);
  CHECK(rig.chassis.right_rad_s == 0.0);
  CHECK(rig.rest_steps == 1);
  const int steps = rig.steps;
  CHECK(steps > 5);   // a quarter turn at 5 rad/s wheel speed cannot happen in a step
  CHECK(steps < 60);
  REQUIRE(rig.drive.turn_to(Heading::east) == robot::Motion::ok);
  CHECK_FALSE(rig.drive.moved());
  CHECK(rig.steps == steps);
}

TEST_CASE("Drive: the wheels stay under the motors' maximum while the turn rate is capped") {
  FakeChassis chassis;
  robot::MotionOptions options;
  options.turn_speed_rad_s = 100.0;  // the motors' 18 rad/s caps it
  double fastest = 0.0;
  robot::Drive drive(chassis, options, 32, [&](robot::Action) {
    fastest = std::max({fastest, std::abs(chassis.left_rad_s), std::abs(chassis.right_rad_s)});
    chassis.advance(0.032);
    return robot::Motion::ok;
  });
  REQUIRE(drive.turn_to(Heading::south) == robot::Motion::ok);
  CHECK(fastest == doctest::Approx(18.0));
  CHECK(std::abs(common::wrap_angle_rad(chassis.yaw + std::numbers::pi / 2)) < options.yaw_tolerance_rad);
}

TEST_CASE("Drive: driving a cell by the encoders ends within the position tolerance, at rest") {
  Rig rig;
  REQUIRE(rig.drive.drive_to(Point{0.5, 1.5}, Heading::north, 1.0, "cell (0,1)") == robot::Motion::ok);
  CHECK(std::abs(rig.chassis.y_m - 1.5) < rig.options.position_tolerance_m);
  CHECK(std::abs(rig.drive.travelled_m() - 1.0) < rig.options.position_tolerance_m);
  CHECK(rig.chassis.left_rad_s == 0.0);
  CHECK(rig.rest_steps == 1);
}

TEST_CASE("Drive: with a GPS the drive steers back onto the line and backs up to a point behind") {
  Rig rig;
  rig.chassis.has_gps = true;
  rig.chassis.x_m = 0.53;  // 3 cm right of the line x = 0.5, facing north
  REQUIRE(rig.drive.drive_to(Point{0.5, 1.5}, Heading::north, 1.0, "cell (0,1)") == robot::Motion::ok);
  CHECK(std::abs(rig.chassis.y_m - 1.5) < rig.options.position_tolerance_m);
  CHECK(std::abs(rig.chassis.x_m - 0.5) < 0.01);
  REQUIRE(rig.drive.drive_to(Point{0.5, 1.2}, Heading::north, -0.3, "back") == robot::Motion::ok);
  CHECK(std::abs(rig.chassis.y_m - 1.2) < rig.options.position_tolerance_m);
  CHECK(rig.drive.travelled_m() < 0.0);
}

TEST_CASE("Drive: a creep stops when asked, moving, and at its limit otherwise") {
  Rig rig;
  int asked = 0;
  REQUIRE(rig.drive.creep(Heading::north, Point{0.5, 0.5}, 0.6, "probing N", [&] { return ++asked > 10; }) ==
          robot::Motion::ok);
  CHECK(asked == 11);
  CHECK(rig.steps == 10);
  CHECK(rig.chassis.left_rad_s > 0.0);  // the caller comes to rest
  CHECK(rig.drive.travelled_m() == doctest::Approx(10 * 0.032 * 0.1).epsilon(0.02));
  Rig far;
  REQUIRE(far.drive.creep(Heading::north, Point{0.5, 0.5}, 0.2, "probing N", [] { return false; }) == robot::Motion::ok);
  CHECK(far.drive.travelled_m() >= 0.2);
  CHECK(far.drive.travelled_m() < 0.2 + 0.1 * 0.032 + 1e-9);
}

TEST_CASE("Drive: a chassis that does not move is no progress, named; the step limit ends a motion") {
  Rig rig;
  rig.chassis.stuck = true;
  CHECK(rig.drive.turn_to(Heading::west) == robot::Motion::no_progress);
  CHECK(rig.drive.failure() == "turning to W made no progress for 60 steps (yaw 1.5708 rad)");
  CHECK(rig.steps == 60);
  // By the encoders alone a spinning wheel is progress (they count it all); the GPS says not.
  rig.chassis.has_gps = true;
  CHECK(rig.drive.drive_to(Point{0.5, 1.5}, Heading::north, 1.0, "cell (0,1)") == robot::Motion::no_progress);
  CHECK(rig.drive.failure().starts_with("driving N to cell (0,1) made no progress for 60 steps ("));
  Rig limited;
  limited.limit = 3;
  CHECK(limited.drive.turn_to(Heading::south) == robot::Motion::max_steps);
  CHECK(limited.steps == 3);
}

TEST_CASE("Drive: a ramped straight speeds up at the ramp's acceleration to its top speed and stops at the target") {
  FakeChassis chassis;
  robot::MotionOptions options;
  options.ramp_acceleration_m_s2 = 1.0;
  options.ramp_top_speed_m_s = 0.5;
  double last_v = 0.0;
  double max_v = 0.0;
  double max_dv = 0.0;
  int steps = 0;
  robot::Drive drive{chassis, options, 32, [&](robot::Action) {
                       const double v = chassis.radius_m * (chassis.left_rad_s + chassis.right_rad_s) / 2.0;
                       max_v = std::max(max_v, v);
                       max_dv = std::max(max_dv, std::abs(v - last_v));
                       last_v = v;
                       chassis.advance(0.032);
                       ++steps;
                       return robot::Motion::ok;
                     }};
  REQUIRE(drive.drive_ramped(Point{0.5, 3.5}, Heading::north, 3.0, "three cells on") == robot::Motion::ok);
  CHECK(chassis.y_m == doctest::Approx(3.5).epsilon(0.001));
  CHECK(max_v == doctest::Approx(0.5));            // the top speed, reached on 3 m
  // About a * dt a step, up or down; the last stop, from under sqrt(2 a * 2 tolerance), at most twice that.
  CHECK(max_dv <= 2.0 * 1.0 * 0.032);
  // A trapezoid: 0.5 s up and 0.5 s down (0.125 m each), 2.75 m at 0.5 m/s: 6.5 s, about 203 steps.
  CHECK(steps > 180);
  CHECK(steps < 230);
}
