#pragma once
// `maze_mapper convert WORLD out.wbt`: the Webots world with the robot in it (maze/
// wbt_format.hpp draws the nodes) and, in its controllerArgs, what `run` would tell the
// controller (app::controller_options, written by robot::format_controller_args): the
// maze's geometry, start and goals, the mapping options, the robot's description - never
// the walls.

#include <string>
#include <string_view>

#include "maze/world/maze.hpp"
#include "maze/sim/profile.hpp"

namespace app {

struct WebotsExport {
  std::string robot = maze::sim::default_profile().name;  // --robot
  std::string model;             // --model; empty: cell with a lidar, else bump with bumpers, else depth
  std::string strategy = "dfs";  // --strategy
  int subcells = 3;              // --subcells
};

// The .wbt text. Throws common::InputError for an unknown robot, model or strategy, a robot
// without the sensors the model reads, or options the controller would refuse.
std::string webots_world(const maze::Maze &maze, std::string_view title, const WebotsExport &options);

}  // namespace app
