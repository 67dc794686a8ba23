// The Webots controller's command line (robot/controller_args.hpp): what format writes,
// parse reads back field for field; every bad argument is one line naming it.

#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "common/error.hpp"
#include "robot/controller_args.hpp"

namespace {

std::string error_of(const std::vector<std::string> &args) {
  try {
    robot::parse_controller_args(args);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "";
}

// A set-up with every field away from its default.
robot::ControllerOptions everything_set() {
  robot::ControllerOptions o;
  o.geometry = {5, 3, 5, 0.18, {-1.25, 0.1}};
  o.start = {4, 2};
  o.start_heading = mapping::Heading::west;
  o.goals = {{2, 1}, {3, 1}};
  o.model.kind = sensing::ModelKind::ray;
  o.model.hit_depth = 2;
  o.model.ignore_no_return = true;
  o.occupied_threshold = 0.7f;
  o.sensor = {0.35, 0.65, 0.45, mapping::LogBase::ten, mapping::Clamp{-2.0, 3.5}};
  o.sensing.range_model = {0.2, 0.05, 0.5};
  o.strategy = explore::StrategyKind::floodfill;
  o.speed_run = true;
  o.motion.max_steps = 123456;
  o.motion.wheel_radius_m = 0.0165;
  o.motion.axle_m = 0.0761;
  o.scan_filter.range_noise_m = 0.0025;
  o.devices = {"motor L", "motor R", "enc L", "enc R", "imu 2", "", "scanner, front"};
  o.sensing.bumpers = {{"bump, left", 0.7853981633974483, 0.09}};
  o.sensing.ranges = {{"ir0", -1.5707963267948966, 0.09, 1.5, 0.03, 0.03}};
  return o;
}

}  // namespace

TEST_CASE("controller args: format then parse gives back every field") {
  const robot::ControllerOptions o = everything_set();
  const std::vector<std::string> args = robot::format_controller_args(o);
  CHECK(args.front() == "--size=5x3");
  const robot::ControllerOptions p = robot::parse_controller_args(args);
  CHECK(p.geometry.width_cells == 5);
  CHECK(p.geometry.height_cells == 3);
  CHECK(p.geometry.subcells == 5);
  CHECK(p.geometry.cell_size_m == o.geometry.cell_size_m);
  CHECK(p.geometry.origin.x_m == o.geometry.origin.x_m);
  CHECK(p.geometry.origin.y_m == o.geometry.origin.y_m);
  CHECK(p.start == o.start);
  CHECK(p.start_heading == o.start_heading);
  CHECK(p.goals == o.goals);
  CHECK(p.model.kind == o.model.kind);
  CHECK(p.model.hit_depth == 2);
  CHECK(p.model.ignore_no_return);
  CHECK(p.occupied_threshold == o.occupied_threshold);
  CHECK(p.sensor.p_free == o.sensor.p_free);
  CHECK(p.sensor.p_occ == o.sensor.p_occ);
  CHECK(p.sensor.prior == o.sensor.prior);
  CHECK(p.sensor.base == mapping::LogBase::ten);
  REQUIRE(p.sensor.clamp.has_value());
  CHECK(p.sensor.clamp->min == -2.0);
  CHECK(p.sensor.clamp->max == 3.5);
  CHECK(p.sensing.range_model.pie_half_angle_rad == 0.2);
  CHECK(p.sensing.range_model.pie_contact_m == 0.05);
  CHECK(p.sensing.range_model.pie_usable_fraction == 0.5);
  CHECK(p.strategy == o.strategy);
  CHECK(p.speed_run);
  CHECK(p.motion.max_steps == 123456);
  CHECK(p.motion.wheel_radius_m == o.motion.wheel_radius_m);
  CHECK(p.motion.axle_m == o.motion.axle_m);
  CHECK(p.scan_filter.range_noise_m == o.scan_filter.range_noise_m);
  CHECK(p.devices.left_motor == "motor L");
  CHECK(p.devices.right_motor == "motor R");
  CHECK(p.devices.left_encoder == "enc L");
  CHECK(p.devices.right_encoder == "enc R");
  CHECK(p.devices.imu == "imu 2");
  CHECK(p.devices.gps.empty());
  CHECK(p.devices.lidar == "scanner, front");
  REQUIRE(p.sensing.bumpers.size() == 1);
  CHECK(p.sensing.bumpers[0].name == "bump, left");
  CHECK(p.sensing.bumpers[0].angle_rad == o.sensing.bumpers[0].angle_rad);
  CHECK(p.sensing.bumpers[0].offset_m == 0.09);
  REQUIRE(p.sensing.ranges.size() == 1);
  const robot::RangeSensorMount &r = p.sensing.ranges[0];
  CHECK(r.name == "ir0");
  CHECK(r.angle_rad == o.sensing.ranges[0].angle_rad);
  CHECK(r.offset_m == 0.09);
  CHECK(r.max_range_m == 1.5);
  CHECK(r.aperture_rad == 0.03);
  CHECK(r.range_error == 0.03);
  CHECK(robot::format_controller_args(p) == args);
}

TEST_CASE("controller args: only --size is required; the rest keep their defaults") {
  const robot::ControllerOptions p = robot::parse_controller_args(std::vector<std::string>{"--size=2x3"});
  const robot::ControllerOptions d;
  CHECK(p.geometry.width_cells == 2);
  CHECK(p.geometry.height_cells == 3);
  CHECK(p.geometry.cell_size_m == d.geometry.cell_size_m);
  CHECK(p.devices.lidar == d.devices.lidar);
  CHECK(p.model.kind == sensing::ModelKind::cell);
}

TEST_CASE("controller args: a bad argument is one line naming it") {
  CHECK(error_of({}) == "error: missing controller argument --size=WxH (the maze's size in cells)");
  CHECK(error_of({"--size=4"}) == "error: controller argument '--size=4': expected WxH, e.g. 4x4");
  CHECK(error_of({"--size=4x4", "--cell-size=wide"}) == "error: controller argument '--cell-size=wide': expected a number");
  CHECK(error_of({"--size=4x4", "--cell-size=inf"}) == "error: controller argument '--cell-size=inf': expected a number");
  CHECK(error_of({"--size=4x4", "--start=1"}) ==
        "error: controller argument '--start=1': expected X,Y cell coordinates, e.g. 0,0");
  CHECK(error_of({"--size=4x4", "--heading=up"}) == "error: controller argument '--heading=up': expected N, E, S or W");
  CHECK(error_of({"--size=4x4", "--speed-run=yes"}) == "error: controller argument '--speed-run=yes': expected true or false");
  CHECK(error_of({"--size=4x4", "--lidar="}) == "error: controller argument '--lidar=': expected a device name");
  CHECK(error_of({"--size=4x4", "--bumper=0.5,x,b"}) ==
        "error: controller argument '--bumper=0.5,x,b': expected ANGLE_RAD,OFFSET_M,NAME");
  CHECK(error_of({"--size=4x4", "--range=1,2,3"}) ==
        "error: controller argument '--range=1,2,3': expected ANGLE_RAD,OFFSET_M,MAX_M,APERTURE_RAD,ERROR,NAME");
  CHECK(error_of({"--size=4x4", "--walls=1"}).starts_with(
      "error: unknown controller argument '--walls=1' (known, as --key=value: --size, --cell-size, "));
  CHECK(error_of({"--size=4x4", "size=4x4"}).starts_with("error: unknown controller argument 'size=4x4'"));
  CHECK(error_of({"--size=4x4", "--model=sonar"}).starts_with("error: unknown --model 'sonar'"));
  // Parsed values go through the controller's own validation.
  CHECK(error_of({"--size=4x4", "--subcells=4"}).starts_with("error: "));
  CHECK(error_of({"--size=4x4", "--start=7,0"}).starts_with("error: "));
}
