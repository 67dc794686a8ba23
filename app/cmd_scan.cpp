// maze_mapper scan WORLD --pose X Y YAW [--robot NAME] [--noise X] [--seed N]
// Prints one lidar range image at a pose: `index angle_rad range_m` a line, `inf` for no return.

#include <cstdint>
#include <memory>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/run_cli.hpp"
#include "app/profile_json.hpp"
#include "commands.hpp"
#include "maze/sim/scan.hpp"

namespace app {

namespace {

struct ScanArgs {
  std::string world;
  std::vector<double> pose;
  std::string robot = "hambot";
  std::optional<double> noise;
  std::uint64_t seed = common::kDefaultSeed;
  WorldInput world_input;
};

}  // namespace

void add_scan_command(CLI::App &cli, CommandContext &context) {
  auto args = std::make_shared<ScanArgs>();
  CLI::App *scan = cli.add_subcommand(
      "scan", "print one lidar range image at a pose: `index angle_rad range_m` a line");
  scan->add_option("WORLD", args->world, "maze file")->required();
  scan->add_option("--pose", args->pose, "X Y YAW: position (m, world frame) and heading (rad)")
      ->expected(3)
      ->required();
  scan->add_option("--robot", args->robot, "NAME or FILE.json: robot profile with a lidar (default hambot)");
  scan->add_option("--noise", args->noise, "lidar noise as a fraction of max range (0: exact)");
  scan->add_option("--seed", args->seed, "seed of the noise");
  add_cell_size_option(*scan, args->world_input);
  scan->callback([args, &context] {
    const maze::Maze maze = load_world_reporting(args->world, to_world_overrides(args->world_input)).maze;
    maze::sim::ScanRequest request;
    request.pose = {args->pose[0], args->pose[1], args->pose[2]};
    request.robot = args->robot;
    if (names_a_profile_file(args->robot)) request.profile = resolve_robot(args->robot);
    request.noise = args->noise;
    request.seed = args->seed;
    std::cout << maze::sim::format_scan(maze, request);
    context.status = 0;
  });
}

}  // namespace app
