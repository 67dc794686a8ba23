// maze_mapper scan WORLD --pose X Y YAW [--robot NAME] [--noise X] [--seed N]
// Prints one lidar range image at a pose: `index angle_rad range_m` a line, `inf` for no return.
// YAW is radians (counter-clockwise from east), or degrees written with a deg suffix (90deg).

#include <charconv>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>
#include <system_error>
#include <memory>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_options.hpp"
#include "common/error.hpp"
#include "maze/sim/profile.hpp"

#include "app/run_cli.hpp"
#include "app/profile_json.hpp"
#include "commands.hpp"
#include "maze/sim/scan.hpp"

namespace app {

namespace {

struct ScanArgs {
  std::string world;
  std::vector<std::string> pose;
  std::string robot = maze::sim::default_profile().name;
  std::optional<double> noise;
  std::uint64_t seed = common::kDefaultSeed;
  maze::WorldOverrides world_overrides;
};

// A finite number and the rest of the text after it, or nothing.
std::optional<double> leading_number(const std::string &text, std::string_view &rest) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || !std::isfinite(value)) return std::nullopt;
  rest = std::string_view(end, static_cast<std::size_t>(text.data() + text.size() - end));
  return value;
}

double metres(const std::string &text, const char *which) {
  std::string_view rest;
  const std::optional<double> value = leading_number(text, rest);
  if (!value || !rest.empty()) {
    throw common::InputError(fmt::format("--pose {} must be a finite number of metres (got '{}')", which, text));
  }
  return *value;
}

// YAW in radians, or in degrees with a "deg" suffix.
double yaw_rad(const std::string &text) {
  std::string_view rest;
  const std::optional<double> value = leading_number(text, rest);
  if (value && rest.empty()) return *value;
  if (value && rest == "deg") return *value * std::numbers::pi / 180.0;
  throw common::InputError(fmt::format(
      "--pose YAW must be a finite number of radians, or of degrees with a deg suffix like 90deg (got '{}')", text));
}

}  // namespace

void add_scan_command(CLI::App &cli, CommandContext &context) {
  auto args = std::make_shared<ScanArgs>();
  CLI::App *scan = cli.add_subcommand(
      "scan", "print one lidar range image at a pose: `index angle_rad range_m` a line");
  // Not required() for CLI11: a required positional takes the last of --pose's values when
  // WORLD is left out, and the error then blames --pose. The callback asks for it instead.
  scan->add_option("WORLD", args->world, "maze file");
  scan->add_option("--pose", args->pose,
                   "X Y YAW: position in metres (world frame) and heading in radians, counter-clockwise "
                   "from east, or in degrees with a deg suffix (90deg)")
      ->expected(3)
      ->required();
  scan->add_option("--robot", args->robot,
                   fmt::format("NAME or FILE.json: robot profile with a lidar, one of {} (default {})", robot_names(),
                               args->robot));
  scan->add_option("--noise", args->noise,
                   "lidar noise, standard deviation as a fraction of max range; 0 makes it exact (default the robot's)");
  add_seed_option(*scan, args->seed, "the noise");
  add_cell_size_option(*scan, args->world_overrides);
  scan->callback([args, &context] {
    if (args->world.empty()) throw common::InputError("scan needs a WORLD (a maze file) before or after --pose");
    const double x = metres(args->pose[0], "X");
    const double y = metres(args->pose[1], "Y");
    const double yaw = yaw_rad(args->pose[2]);
    const maze::Maze maze = load_world_reporting(args->world, args->world_overrides).maze;
    maze::sim::ScanRequest request;
    request.pose = {x, y, yaw};
    request.robot = args->robot;
    if (names_a_profile_file(args->robot)) request.profile = resolve_robot(args->robot);
    request.noise = args->noise;
    request.seed = args->seed;
    std::cout << maze::sim::format_scan(maze, request);
    context.status = 0;
  });
}

}  // namespace app
