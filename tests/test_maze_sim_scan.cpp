#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <webots/Lidar.hpp>
#include <webots/Robot.hpp>

#include "common/error.hpp"
#include "maze/world/maze.hpp"
#include "maze/sim/scan.hpp"
#include "maze/sim/simulation.hpp"

namespace {

std::vector<std::string> lines(const std::string &text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace

TEST_CASE("format_scan: index, angle and range a line, inf for no return") {
  maze::Maze corridor(20, 1);
  maze::sim::ScanRequest request;
  request.pose = {0.5, 0.5, 0.0};
  request.noise = 0.0;
  const std::vector<std::string> out = lines(maze::sim::format_scan(corridor, request));
  REQUIRE(out.size() == 360);
  // The default robot's fixed lidar: beams half a degree in, depth 0.494 rounded to 0.49 and
  // divided by cos 0.5 deg (test_maze_sim_fixed_lidar.cpp works it out).
  CHECK(out[0] == "0 3.132866 0.490019");       // back: the west wall
  CHECK(out[90] == "90 1.562070 0.490019");     // left: the north wall
  CHECK(out[180] == "180 -0.008727 inf");       // ahead: 19.494 m, beyond max range
  CHECK(out[270] == "270 -1.579523 0.490019");  // right: the south wall
  // Last year's rotating lidar: the beams on whole degrees, no rounding.
  request.profile = maze::sim::find_profile("hambot-2025");
  const std::vector<std::string> old = lines(maze::sim::format_scan(corridor, request));
  CHECK(old[0] == "0 3.141593 0.494000");
  CHECK(old[180] == "180 0.000000 inf");
}

TEST_CASE("format_scan: the noise is the simulation's first reading with the same seed") {
  maze::Maze m(4, 4);
  maze::sim::RobotProfile fixed = maze::sim::find_profile("hambot-12m");
  fixed.lidars[0].frequency_hz = 0.0;  // a fixed lidar reads at once, one stream per step
  maze::sim::ScanRequest request;
  request.profile = fixed;
  request.pose = {1.5, 2.5, 0.7};
  request.seed = 99;
  const std::vector<std::string> out = lines(maze::sim::format_scan(m, request));
  maze::sim::SimulationOptions o;
  o.seed = 99;
  o.start = request.pose;
  webots::embedded::Simulation sim(maze::world_of(m), fixed, o);
  webots::Lidar *lidar = sim.robot().getLidar("lidar");
  lidar->enable(32);
  const float *ranges = lidar->getRangeImage();
  for (int i = 0; i < 360; i += 37) {
    CHECK(out[static_cast<std::size_t>(i)].ends_with(fmt::format(" {:.6f}", ranges[i])));
  }
  CHECK(maze::sim::format_scan(m, request) == maze::sim::format_scan(m, request));
  request.seed = 100;
  CHECK(lines(maze::sim::format_scan(m, request)) != out);
}

TEST_CASE("format_scan: bad poses and robots are errors") {
  maze::Maze m(2, 2);
  maze::sim::ScanRequest request;
  request.pose = {-0.5, 0.5, 0.0};
  CHECK_THROWS_WITH_AS(maze::sim::format_scan(m, request), "pose (-0.5, 0.5) is outside the maze",
                       common::InputError);
  request.pose = {0.003, 0.5, 0.0};  // in the west outer wall
  CHECK_THROWS_WITH_AS(maze::sim::format_scan(m, request), "pose (0.003, 0.5) is inside a wall",
                       common::InputError);
  request.pose = {1.0, 0.5, 0.0};  // no wall between (0, 0) and (1, 0) yet: free
  CHECK(lines(maze::sim::format_scan(m, request)).size() == 360);
  m.set_wall({0, 0}, maze::Side::east, true);
  CHECK_THROWS_WITH_AS(maze::sim::format_scan(m, request), "pose (1, 0.5) is inside a wall",
                       common::InputError);
  request.pose = {0.5, 0.5, 0.0};
  request.robot = "ir-ring";
  CHECK_THROWS_WITH_AS(maze::sim::format_scan(m, request),
                       "robot 'ir-ring' has no lidar (robots with one: hambot, hambot-2025, hambot-12m, micromouse)",
                       common::InputError);
  request.robot = "nope";
  CHECK_THROWS_AS(maze::sim::format_scan(m, request), common::InputError);
}
