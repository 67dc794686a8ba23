#include "app/cli/arena_options.hpp"

#include <cstdio>
#include <vector>

#include <fmt/format.h>

#include "app/run/option_values.hpp"

namespace app {

void add_boundary_option(CLI::App &cmd, std::string &boundary) {
  cmd.add_option("--boundary", boundary,
                 "XS,XE,YS,YE: an arena's floor, m (default the file's; without one, the walls' box when they "
                 "enclose the start, else the course's 17 x 17 m floor centred on the origin)");
}

maze::ArenaOverrides arena_overrides(const std::string &boundary, double robot_radius_m) {
  maze::ArenaOverrides o;
  o.robot_radius_m = robot_radius_m;
  if (!boundary.empty()) {
    const std::vector<double> b = parse_number_list(boundary, "--boundary", 4);
    o.boundary_m = std::array<double, 4>{b[0], b[1], b[2], b[3]};
  }
  return o;
}

maze::AnyWorld load_any_world_reporting(const std::string &path, const maze::WorldOverrides &maze_overrides,
                                        const maze::ArenaOverrides &arena_overrides) {
  maze::AnyWorld world = maze::load_any_world(path, maze_overrides, arena_overrides);
  for (const std::string &warning : maze::world_warnings(world)) fmt::print(stderr, "{}\n", warning);
  return world;
}

}  // namespace app
