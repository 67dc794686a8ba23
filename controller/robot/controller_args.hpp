#pragma once
// The controller's command line: what a Webots controller learns from its robot's
// `controllerArgs` field (Webots passes each string as one argv element). It carries the
// grid's geometry, the start, the goals, the mapping options and the robot's description
// (wheels, device names, sensor mounts) - never the walls. `maze_mapper convert WORLD
// out.wbt` writes them; the controller reads them back into the same ControllerOptions
// the embedded run builds.
//
// One argument is `--key=value` (the value may hold spaces: Webots does not split them):
//
//   --size=4x4  --cell-size=1  --origin=0,0  --subcells=3      grid: W x H cells of M metres,
//   --start=0,0  --heading=N  --goal=1,2 (repeated)              south-west corner at X,Y
//   --model=cell  --strategy=dfs  --hit-depth=0  --ignore-no-return=true  --threshold=L
//   --p-free=0.3  --p-occ=0.6  --prior=0.5  --log-base=e|10  --clamp=MIN,MAX
//   --pie-beta-rad=R  --pie-alpha=M  --pie-usable=F  --speed-run=true  --max-steps=N
//   --wheel-radius=M  --axle=M  --lidar-noise=M   (range noise sigma, metres)
//   --left-motor=NAME  --right-motor=NAME  --left-encoder=NAME  --right-encoder=NAME
//   --imu=NAME  --gps=NAME (empty: the robot has none)  --lidar=NAME
//   --bumper=ANGLE_RAD,OFFSET_M,NAME                       (repeated; name last, may hold ',')
//   --range=ANGLE_RAD,OFFSET_M,MAX_M,APERTURE_RAD,ERROR,NAME (repeated)
//
// --size is required; every other key has ControllerOptions' default. Numbers are written
// in the shortest form that reads back to the same double.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "robot/cell/controller.hpp"

namespace robot {

// Parses the arguments (argv without the program name) and validates the result
// (robot::validate). Throws common::InputError with one line naming the argument:
// "controller argument '--size=4': expected WxH, e.g. 4x4", "unknown controller argument
// '--walls=1' (known, as --key=value: --size, ...)", "missing controller argument
// --size=WxH (the maze's size in cells)"; and validate's messages.
ControllerOptions parse_controller_args(std::span<const std::string> args);

// The arguments that parse_controller_args reads back into options (every field it knows;
// options at their default are left out). Each element is one Webots controllerArgs string.
std::vector<std::string> format_controller_args(const ControllerOptions &options);

// Every key the controller reads ("size", "cell-size", ...), in the order
// format_controller_args writes them.
std::vector<std::string_view> controller_arg_keys();

}  // namespace robot
