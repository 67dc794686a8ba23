#include <doctest/doctest.h>

#include <string>

#include "common/error.hpp"
#include "robot/cell_controller.hpp"

// The control loop itself runs against the embedded simulator (maze/); here, its options.

namespace {

robot::ControllerOptions lab4x4() {
  robot::ControllerOptions o;
  o.geometry.width_cells = 4;
  o.geometry.height_cells = 4;
  o.geometry.subcells = 3;
  o.goals = {{1, 1}};
  return o;
}

std::string error_of(const robot::ControllerOptions &o) {
  try {
    robot::validate(o);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "";
}

}  // namespace

TEST_CASE("ControllerOptions: the defaults are the hambot's and valid") {
  robot::ControllerOptions o = lab4x4();
  CHECK(error_of(o) == "");
  CHECK(o.motion.wheel_radius_m == 0.045);
  CHECK(o.motion.axle_m == 0.184);
  CHECK(o.devices.left_encoder == "left wheel sensor");
  CHECK(o.devices.lidar == "lidar");
}

TEST_CASE("ControllerOptions: each concern validated, messages to the letter") {
  robot::ControllerOptions o = lab4x4();
  o.motion.max_steps = 0;
  CHECK(error_of(o) == "error: --max-steps must be at least 1 (got 0)");
  o = lab4x4();
  o.motion.turn_gain = 1.5;
  CHECK(error_of(o) == "error: turn gain must be in (0, 1] (got 1.5)");
  o = lab4x4();
  o.motion.wheel_radius_m = 0.0;
  CHECK(error_of(o) == "error: wheel radius must be a positive number (got 0)");
  o = lab4x4();
  o.start = {5, 0};
  CHECK(error_of(o) == "error: start cell (5,0) is outside the 4x4 maze");
  o = lab4x4();
  o.sensor.p_occ = 0.4;
  CHECK(error_of(o) == "error: --p-occ must be greater than --prior (got 0.4 <= 0.5)");
  o = lab4x4();
  o.geometry.subcells = 4;
  CHECK(error_of(o) == "error: --subcells must be odd and between 3 and 9 (got 4)");
}

TEST_CASE("EndReason names") {
  CHECK(robot::to_string(robot::EndReason::done) == "done");
  CHECK(robot::to_string(robot::EndReason::no_progress) == "no progress");
  CHECK(robot::to_string(robot::EndReason::max_steps) == "max steps");
  CHECK(robot::to_string(robot::EndReason::simulation_ended) == "simulation ended");
}
