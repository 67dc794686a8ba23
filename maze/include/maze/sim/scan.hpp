#pragma once
// `maze_mapper scan`: one lidar range image at a given pose, for teaching and for checking
// the simulator by hand.

#include <cstdint>
#include <optional>
#include <string>

#include "common/random.hpp"
#include "maze/world/maze.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/sensors.hpp"

namespace maze::sim {

struct ScanRequest {
  Pose pose;
  std::string robot = "hambot";  // a built-in profile with a lidar
  std::optional<RobotProfile> profile;  // when set (a profile file), used instead of robot
  std::optional<double> noise;   // overrides the profile's lidar noise
  std::uint64_t seed = common::kDefaultSeed;
};

// The range image as text, `index angle_rad range_m` a line (angle relative to the heading,
// six decimals; `inf` for no return). The noise is the noise of the first reading a
// controller would get at that pose (step 0) with the same seed from a fixed lidar; a
// rotating lidar is shown as after a full revolution at rest (its noise is drawn per beam
// and step, so it differs from a run's). Throws common::InputError
// for an unknown robot, a robot without a lidar, a bad noise, or a pose outside the maze or
// inside a wall.
std::string format_scan(const Maze &maze, const ScanRequest &request);

}  // namespace maze::sim
