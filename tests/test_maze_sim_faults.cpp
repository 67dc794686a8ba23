// Simulated sensor and motion faults: --dropout, --spikes, --stuck-bumper,
// --wheel-slip, and their validation.

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <webots/Lidar.hpp>
#include <webots/Motor.hpp>
#include <webots/PositionSensor.hpp>
#include <webots/Robot.hpp>
#include <webots/TouchSensor.hpp>

#include "common/error.hpp"
#include "maze/world/maze.hpp"
#include "maze/sim/simulation.hpp"

namespace {

using webots::embedded::Simulation;

maze::sim::SimulationOptions middle_of_3x3() {
  maze::sim::SimulationOptions o;
  o.noise = 0.0;
  o.start = maze::sim::Pose{1.5, 1.5, std::numbers::pi / 2};
  return o;
}

// hambot-2025's rotating lidar after a whole revolution at rest (3 steps of 32 ms at 12 Hz).
std::vector<float> scan_once(const maze::sim::SimulationOptions &o) {
  Simulation sim(maze::world_of(maze::Maze(3, 3)), maze::sim::find_profile("hambot-2025"), o);
  webots::Lidar *lidar = sim.robot().getLidar("lidar");
  lidar->enable(32);
  for (int i = 0; i < 3; ++i) REQUIRE(sim.robot().step(32) == 0);
  const float *r = lidar->getRangeImage();
  return {r, r + lidar->getHorizontalResolution()};
}

std::string error_of(const maze::sim::SimulationOptions &o) {
  try {
    Simulation sim(maze::world_of(maze::Maze(3, 3)), maze::sim::default_profile(), o);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "no error";
}

}  // namespace

TEST_CASE("Faults: dropout turns about that fraction of beams into +infinity, the rest untouched") {
  const std::vector<float> clean = scan_once(middle_of_3x3());
  int dropped = 0, total = 0;
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    maze::sim::SimulationOptions o = middle_of_3x3();
    o.seed = seed;
    o.dropout = 0.2;
    const std::vector<float> faulty = scan_once(o);
    for (std::size_t i = 0; i < clean.size(); ++i) {
      ++total;
      if (std::isinf(faulty[i])) {
        ++dropped;
      } else {
        REQUIRE(faulty[i] == clean[i]);
      }
    }
  }
  CHECK(dropped / static_cast<double>(total) == doctest::Approx(0.2).epsilon(0.05));
}

TEST_CASE("Faults: spikes read a range in [min, max]; the same seed gives the same bytes") {
  maze::sim::SimulationOptions o = middle_of_3x3();
  o.spikes = 0.5;
  const std::vector<float> clean = scan_once(middle_of_3x3());
  const std::vector<float> a = scan_once(o);
  CHECK(a == scan_once(o));
  int spiked = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    REQUIRE(std::isfinite(a[i]));
    CHECK(a[i] >= 0.07f);
    CHECK(a[i] <= 3.0f);
    if (a[i] != clean[i]) ++spiked;
  }
  CHECK(spiked > 140);
  CHECK(spiked < 220);
}

TEST_CASE("Faults: turning faults on leaves the noise of the other beams as it was") {
  maze::sim::SimulationOptions noisy = middle_of_3x3();
  noisy.noise.reset();
  maze::sim::SimulationOptions faulty = noisy;
  faulty.dropout = 0.1;
  const std::vector<float> a = scan_once(noisy);
  const std::vector<float> b = scan_once(faulty);
  std::size_t compared = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isinf(b[i])) continue;
    CHECK(a[i] == b[i]);
    ++compared;
  }
  // A scan of nothing but dropped beams would compare nothing: about 90 % are kept.
  CHECK(compared > a.size() * 8 / 10);
  CHECK(compared < a.size());
}

TEST_CASE("Faults: a stuck bumper reads pressed, the others do not") {
  maze::sim::SimulationOptions o = middle_of_3x3();
  o.stuck_bumper = "bumper left";
  Simulation sim(maze::world_of(maze::Maze(3, 3)), maze::sim::find_profile("bumper-depth"), o);
  webots::TouchSensor *left = sim.robot().getTouchSensor("bumper left");
  webots::TouchSensor *front = sim.robot().getTouchSensor("bumper front");
  left->enable(32);
  front->enable(32);
  CHECK(left->getValue() == 1.0);
  CHECK(front->getValue() == 0.0);
}

TEST_CASE("Faults: wheel slip moves the robot less than the encoders count") {
  maze::Maze corridor(4, 1);
  corridor.set_start({0, 0}, maze::Side::east);
  maze::sim::SimulationOptions o;
  o.noise = 0.0;
  o.wheel_slip = 0.25;
  Simulation sim(maze::world_of(corridor), maze::sim::default_profile(), o);
  webots::Robot &robot = sim.robot();
  webots::PositionSensor *encoder = robot.getPositionSensor("left wheel encoder");
  encoder->enable(32);
  const double speed = 1.0 / (1.6 * 0.045);  // 1 m in 50 steps of 32 ms without slip
  for (const char *name : {"left motor", "right motor"}) {
    robot.getMotor(name)->setPosition(std::numeric_limits<double>::infinity());
    robot.getMotor(name)->setVelocity(speed);
  }
  for (int i = 0; i < 50; ++i) REQUIRE(robot.step(32) == 0);
  CHECK(sim.pose().x_m == doctest::Approx(0.5 + 0.75).epsilon(1e-9));
  CHECK(encoder->getValue() == doctest::Approx(speed * 1.6).epsilon(1e-9));
}

TEST_CASE("Faults: fractions from 0 to 1 and known bumper names only") {
  maze::sim::SimulationOptions o = middle_of_3x3();
  o.dropout = 1.5;
  CHECK(error_of(o) == "error: --dropout must be a fraction from 0 to 1 (got 1.5)");
  o.dropout = std::numeric_limits<double>::quiet_NaN();
  CHECK(error_of(o) == "error: --dropout must be a fraction from 0 to 1 (got nan)");
  o.dropout = 0.0;
  o.spikes = -0.1;
  CHECK(error_of(o) == "error: --spikes must be a fraction from 0 to 1 (got -0.1)");
  o.spikes = 0.0;
  o.wheel_slip = 2.0;
  CHECK(error_of(o) == "error: --wheel-slip must be a fraction from 0 to 1 (got 2)");
  o.wheel_slip = 0.0;
  o.dropout = 0.7;
  o.spikes = 0.5;
  CHECK(error_of(o) == "error: --dropout and --spikes together must be at most 1 (got 0.7 + 0.5)");
  o.dropout = o.spikes = 0.0;
  o.stuck_bumper = "nose";
  CHECK(error_of(o) == "error: --stuck-bumper: the robot hambot has no bumper named 'nose' (it has none)");
}
