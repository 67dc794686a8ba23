#include <doctest/doctest.h>

#include <cstdint>
#include <string>

#include "common/error.hpp"
#include "maze/world/maze.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/simulation.hpp"
#include "mapping/walls.hpp"
#include "robot/cell/controller.hpp"

// The control loop itself runs against the embedded simulator (maze/) in the app's tests;
// here, its options, and the rescans of a side a faulty scan left unknown.

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

// Runs the cell model on an open 4 x 4 maze whose lidar drops `dropout` of its beams, and
// counts the arrivals after which a side of the robot's cell is still unknown.
struct RescanRun {
  int arrivals = 0;
  int with_unknown_side = 0;
  std::int64_t steps = 0;
};

RescanRun run_with_dropout(double dropout, int max_rescans) {
  maze::sim::SimulationOptions sim_options;
  sim_options.seed = 5;
  sim_options.dropout = dropout;
  webots::embedded::Simulation sim(maze::world_of(maze::Maze(4, 4)), maze::sim::default_profile(), sim_options);
  robot::ControllerOptions o = lab4x4();
  o.max_rescans = max_rescans;
  o.motion.max_steps = 20'000;
  robot::CellController controller(sim.robot(), o);
  RescanRun run;
  robot::RunHooks hooks;
  hooks.on_move = [&](const robot::MoveReport &r) {
    ++run.arrivals;
    for (const mapping::Heading h : mapping::kHeadings) {
      if (mapping::side_state(*r.grid, 0.0f, r.cell, h) == mapping::SideState::unknown) {
        ++run.with_unknown_side;
        break;
      }
    }
  };
  run.steps = controller.run(hooks).steps;
  return run;
}

}  // namespace

TEST_CASE("CellController: a side a faulty scan left unknown is scanned again") {
  // Fault-free: every side is known after the arrival scan, so rescans change nothing.
  const RescanRun clean = run_with_dropout(0.0, 3);
  CHECK(clean.with_unknown_side == 0);
  CHECK(clean.steps == run_with_dropout(0.0, 0).steps);
  // Most beams dropped: the robot rescans, then faces each side still unknown, and no
  // arrival ends with a side unknown; that costs steps.
  const RescanRun faulty = run_with_dropout(0.7, 3);
  CAPTURE(faulty.with_unknown_side);
  CHECK(faulty.with_unknown_side == 0);
  CHECK(faulty.steps > clean.steps);
}

namespace {

// A corridor 20 cells long up the middle of a 3 x 20 maze, with a dead-end pocket on either
// side of every other cell: the corridor's walls seen at a grazing angle are broken by the
// pockets, so no surface recedes steadily towards max range beside the view down it.
maze::Maze pocketed_corridor() {
  maze::Maze m(3, 20);
  for (int y = 0; y < 20; ++y) {
    for (const int x : {0, 2}) {
      if (y + 1 < 20) m.set_wall({x, y}, maze::Side::north, true);
      m.set_wall({x, y}, x == 0 ? maze::Side::east : maze::Side::west, y % 2 == 1);
    }
  }
  m.set_start({1, 0}, maze::Side::north);
  return m;
}

// The cell model up that corridor from its south end, hambot-12m's lidar: from the first cells
// the corridor's end is beyond max range, a view of 4-5 beams. The pockets of the odd rows
// are closed cells (unreachable).
robot::RunResult run_corridor(const sensing::ScanFilterOptions &filter) {
  webots::embedded::Simulation sim(maze::world_of(pocketed_corridor()), maze::sim::find_profile("hambot-12m"), {});
  robot::ControllerOptions o;
  o.start = {1, 0};
  o.geometry.width_cells = 3;
  o.geometry.height_cells = 20;
  o.geometry.subcells = 3;
  o.scan_filter = filter;
  o.motion.max_steps = 20'000;
  robot::CellController controller(sim.robot(), o);
  return controller.run();
}

}  // namespace

TEST_CASE("CellController: a corridor longer than the lidar's range, seen end-on, is open") {
  // The first scan takes the view for dropped beams; the rescan from the same pose sees it
  // again and it stands.
  const robot::RunResult r = run_corridor({});
  CHECK(r.reason == robot::EndReason::done);
  CHECK(r.visited == 40);  // the corridor and its 20 open pockets
}

TEST_CASE("CellController: a side still unknown after every look ends the run incomplete, not done") {
  // A filter that never takes a short run of no returns for a view (wider than 32 beams):
  // the corridor's north side from the start stays unknown however often and from whichever
  // heading the robot scans, and an unknown side is not a wall.
  sensing::ScanFilterOptions never_a_view;
  never_a_view.min_repeated_view = 32;
  const robot::RunResult r = run_corridor(never_a_view);
  CHECK(r.reason == robot::EndReason::incomplete);
  CHECK(r.message == "1 side of visited cells still unknown: N of (1,0)");
  CHECK(r.visited == 3);
}

TEST_CASE("ControllerOptions: the defaults drive the hambot through a maze, and no other robot") {
  // Nothing set but the maze: the default wheels, axle and device names are the hambot's,
  // so it turns and drives cell by cell (a wrong wheel radius or axle would overshoot or
  // stall) and maps the whole open 4 x 4 maze.
  webots::embedded::Simulation hambot(maze::world_of(maze::Maze(4, 4)), maze::sim::default_profile(), maze::sim::SimulationOptions{});
  robot::CellController controller(hambot.robot(), lab4x4());
  const robot::RunResult r = controller.run(robot::RunHooks{});
  CHECK(r.reason == robot::EndReason::done);
  CHECK(r.visited == 16);
  CHECK(r.moves >= 15);
  // A robot whose devices are named otherwise is refused, naming the device.
  webots::embedded::Simulation other(maze::world_of(maze::Maze(4, 4)), maze::sim::find_profile("bumper-depth"),
                                     maze::sim::SimulationOptions{});
  CHECK_THROWS_WITH_AS(robot::CellController(other.robot(), lab4x4()), "the robot has no device \"lidar\"",
                       common::InputError);
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
  o = lab4x4();
  o.max_rescans = -1;
  CHECK(error_of(o) == "error: rescans must be 0 to 100 (got -1)");
  o = lab4x4();
  o.scan_filter.neighbour_reach = 11;
  CHECK(error_of(o) == "error: scan filter: neighbour reach must be 1 to 10 beams (got 11)");
}

TEST_CASE("EndReason names") {
  CHECK(robot::to_string(robot::EndReason::done) == "done");
  CHECK(robot::to_string(robot::EndReason::no_progress) == "no progress");
  CHECK(robot::to_string(robot::EndReason::max_steps) == "max steps");
  CHECK(robot::to_string(robot::EndReason::simulation_ended) == "simulation ended");
}
