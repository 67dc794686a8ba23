#include "maze/sim/scan.hpp"

#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/wall_grid.hpp"

namespace maze::sim {

namespace {

std::string lidar_robots() {
  std::string names;
  for (const RobotProfile &p : profiles()) {
    if (p.lidars.empty()) continue;
    if (!names.empty()) names += ", ";
    names += p.name;
  }
  return names;
}

}  // namespace

std::string format_scan(const Maze &maze, const ScanRequest &request) {
  const RobotProfile &profile = request.profile ? *request.profile : find_profile(request.robot);
  if (profile.lidars.empty()) {
    throw common::InputError(fmt::format("robot '{}' has no lidar (robots with one: {})",
                                         profile.name, lidar_robots()));
  }
  // run's rule, in run's words: a standard deviation of more than the max range is no lidar.
  if (request.noise && !(*request.noise >= 0.0 && *request.noise <= 1.0)) {
    throw common::InputError(fmt::format("--noise must be a fraction of the max range from 0 to 1 (got {})", *request.noise));
  }
  const WallGrid walls(maze);
  check_pose_free(walls, request.pose);
  const LidarSpec &lidar = profile.lidars.front();
  std::vector<float> ranges(static_cast<std::size_t>(lidar.horizontal_resolution));
  // The lidar is the simulation's first device; its reading at step 0 uses this stream.
  common::Rng rng = sensor_rng(request.seed, 0, 0);
  LidarModel(lidar).range_image(walls, request.noise.value_or(lidar.noise), request.pose, rng,
                               ranges);
  std::string out;
  for (int i = 0; i < lidar.horizontal_resolution; ++i) {
    fmt::format_to(std::back_inserter(out), "{} {:.6f} {:.6f}\n", i, beam_angle_rad(lidar, i),
                   ranges[static_cast<std::size_t>(i)]);
  }
  return out;
}

}  // namespace maze::sim
