// maze_mapper scan WORLD --pose X,Y,YAW [--robot NAME] [--noise X] [--seed N]
// Prints one lidar range image at a pose: `index angle_rad range_m` a line, `inf` for no return.
// The pose is spelled as everywhere (app/cli/cli_options.hpp: YAW in degrees, or 1.5708rad); the
// old `--pose X Y YAW` (three words, YAW in radians within a turn, or 90deg) still works, with
// a warning, for one release.

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

#include "app/cli/cli_options.hpp"
#include "app/run/shipped_worlds.hpp"
#include "common/error.hpp"
#include "maze/sim/profile.hpp"

#include "app/cli/run_cli.hpp"
#include "app/cli/help_format.hpp"
#include "app/run/profile_json.hpp"
#include "app/cli/commands.hpp"
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

// The old spelling's YAW: radians (kept for one release), or degrees with a deg suffix. A
// YAW in radians beyond a turn is refused: written as `--pose 0.5 0.5 90` it is meant as
// degrees, and 90 radians would scan another way without a word.
double old_spelling_yaw_rad(const std::string &x, const std::string &y, const std::string &yaw) {
  const double value = yaw_rad(yaw);
  if (!yaw.ends_with("deg") && std::abs(value) > 2.0 * std::numbers::pi) {
    throw common::InputError(fmt::format("--pose {} {} {}: this old spelling's YAW is in radians, and {} radians is more "
                                         "than a turn; for {} degrees write --pose {}m,{}m,{}",
                                         x, y, yaw, yaw, yaw, x, y, yaw));
  }
  return value;
}

// The pose from --pose's words: one word Xm,Ym,YAW, or the old three words X Y YAW; the word
// after them, when WORLD was not given before, is WORLD (CLI11 gives --pose up to four).
maze::sim::Pose scan_pose(ScanArgs &args, std::vector<std::string> &warnings) {
  const std::vector<std::string> &words = args.pose;
  const bool old_spelling = words.size() >= 3 && words[0].find(',') == std::string::npos;
  for (std::size_t i = old_spelling ? 3 : 1; i < words.size(); ++i) {
    if (!args.world.empty()) throw common::InputError(fmt::format("scan: unexpected argument '{}'", words[i]));
    args.world = world_argument(words[i]);
  }
  if (args.world.empty()) throw common::InputError("scan needs a WORLD (a maze file) before or after --pose");
  if (old_spelling) {
    const double x = metres(words[0], "X");
    const double y = metres(words[1], "Y");
    const double yaw = old_spelling_yaw_rad(words[0], words[1], words[2]);
    warnings.push_back(old_spelling_warning(fmt::format("--pose {} {} {}", words[0], words[1], words[2]),
                                            fmt::format("--pose {:g}m,{:g}m,{:g} (YAW in degrees)", x, y,
                                                        yaw * 180.0 / std::numbers::pi)));
    return {x, y, yaw};
  }
  const PoseArgument pose = parse_pose(words[0], "--pose", warnings);
  return {pose.x_m, pose.y_m, pose.yaw_rad};
}

}  // namespace

void add_scan_command(CLI::App &cli, CommandContext &context) {
  auto args = std::make_shared<ScanArgs>();
  CLI::App *scan = cli.add_subcommand(
      "scan", "print one lidar range image at a pose: `index angle_rad range_m` a line");
  // Not required() for CLI11: a required positional takes a value of --pose's when WORLD is
  // left out, and the error then blames --pose. scan_pose asks for it instead.
  show_as_required(*accept_shipped_world_names(scan->add_option("WORLD", args->world, "maze file or a shipped world's name")));
  CLI::Option *pose = scan->add_option("--pose", args->pose,
                                       "X,Y,YAW: position, X and Y with their unit m (world frame), heading YAW in degrees, "
                                       "counter-clockwise from east (1.5708rad: in radians)");
  pose->expected(1, 4)->required();
  show_as_required(*pose);
  scan->add_option("--robot", args->robot,
                   fmt::format("NAME or FILE.json: robot profile with a lidar, one of {} (default {})", robot_names(),
                               args->robot));
  scan->add_option("--noise", args->noise,
                   "lidar noise, standard deviation as a fraction of max range; 0 makes it exact (default the robot's)");
  add_seed_option(*scan, args->seed, "the noise");
  add_cell_size_option(*scan, args->world_overrides);
  scan->callback([args, &context] {
    std::vector<std::string> warnings;
    const maze::sim::Pose at = scan_pose(*args, warnings);
    const maze::Maze maze = load_world_reporting(args->world, args->world_overrides).maze();
    maze::sim::ScanRequest request;
    request.pose = at;
    request.robot = args->robot;
    if (names_a_profile_file(args->robot)) request.profile = resolve_robot(args->robot);
    request.noise = args->noise;
    request.seed = args->seed;
    const std::string scan_text = maze::sim::format_scan(maze, request);
    print_warnings(warnings);  // once the scan is sure: an error stays the one line on stderr
    std::cout << scan_text;
    context.status = 0;
  });
}

}  // namespace app
