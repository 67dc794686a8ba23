#include <doctest/doctest.h>

#include <cstdint>

#include "maze/sim/profile.hpp"
#include "maze/sim/simulation.hpp"
#include "maze/world/maze.hpp"
#include "robot/control_loop.hpp"

// The control step every controller kind takes: counted, within the budget, until a stop is
// asked or the time limit, on the embedded simulator's clock.

namespace {

bool stop_now() { return true; }

struct OpenMaze {
  webots::embedded::Simulation sim{maze::world_of(maze::Maze(4, 4)), maze::sim::default_profile(), maze::sim::SimulationOptions{}};
};

}  // namespace

TEST_CASE("a control step is one Robot::step of the controller's time step, counted") {
  OpenMaze m;
  robot::MotionOptions motion;
  motion.max_steps = 1000;
  robot::ControlLoop loop(m.sim.robot(), motion);
  CHECK(loop.time_step_ms() == m.sim.basic_time_step_ms());
  for (int i = 0; i < 5; ++i) REQUIRE(loop.step() == robot::Motion::ok);
  CHECK(loop.steps() == 5);
  CHECK(loop.time_s() == doctest::Approx(5 * loop.time_step_ms() / 1000.0));
  CHECK(m.sim.steps() == 5);
}

TEST_CASE("a control time step longer than the basic one advances the simulated time by it") {
  OpenMaze m;
  robot::MotionOptions motion;
  motion.time_step_ms = 3 * m.sim.basic_time_step_ms();
  robot::ControlLoop loop(m.sim.robot(), motion);
  REQUIRE(loop.step() == robot::Motion::ok);
  CHECK(loop.steps() == 1);
  CHECK(m.sim.time_ms() == motion.time_step_ms);
}

TEST_CASE("no control step past the budget: the step after max_steps is refused, the simulation not stepped") {
  OpenMaze m;
  robot::MotionOptions motion;
  motion.max_steps = 3;
  robot::ControlLoop loop(m.sim.robot(), motion);
  for (int i = 0; i < 3; ++i) REQUIRE(loop.step() == robot::Motion::ok);
  CHECK(loop.step() == robot::Motion::max_steps);
  CHECK(loop.steps() == 3);
  CHECK(m.sim.steps() == 3);
}

TEST_CASE("a stop asked before a step refuses it; the budget is checked first") {
  OpenMaze m;
  robot::MotionOptions motion;
  motion.max_steps = 1000;
  robot::ControlLoop loop(m.sim.robot(), motion, stop_now);
  CHECK(loop.step() == robot::Motion::stopped);
  CHECK_FALSE(loop.time_up());
  CHECK(loop.steps() == 0);
  motion.max_steps = 0;
  robot::ControlLoop spent(m.sim.robot(), motion, stop_now);
  CHECK(spent.step() == robot::Motion::max_steps);
}

TEST_CASE("the time limit refuses the first step at or past it, and says so") {
  OpenMaze m;
  robot::MotionOptions motion;
  motion.max_steps = 1000;
  const double limit_s = 0.1;
  robot::ControlLoop loop(m.sim.robot(), motion, nullptr, limit_s);
  std::int64_t taken = 0;
  while (loop.step() == robot::Motion::ok) ++taken;
  CHECK(loop.time_up());
  CHECK(loop.time_s() >= limit_s);
  CHECK(loop.time_s() - loop.time_step_ms() / 1000.0 < limit_s);
  CHECK(loop.steps() == taken);
}

TEST_CASE("a simulation that ends (Robot::step returns -1) ends the loop, the step not counted") {
  OpenMaze m;
  robot::MotionOptions motion;
  motion.max_steps = 1000;
  robot::ControlLoop loop(m.sim.robot(), motion);
  REQUIRE(loop.step() == robot::Motion::ok);
  m.sim.request_stop();
  CHECK(loop.step() == robot::Motion::ended);
  CHECK(loop.steps() == 1);
}
