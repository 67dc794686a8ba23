#include "common/parse_number.hpp"
#include "app/cli/cli_errors.hpp"
#include "app/cli/run_cli.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "app/cli/cli_options.hpp"
#include "app/cli/commands.hpp"
#include "app/run/shipped_worlds.hpp"
#include "common/error.hpp"
#include "app/cli/model_options.hpp"

namespace app {
namespace {

// The set-ups' names grouped by `key` ("cell, ray (a lidar); bump (bumpers); ...") or the
// names sharing one key.
template <typename Key>
std::vector<std::pair<std::string_view, std::string>> grouped(Key key, std::string_view separator) {
  std::vector<std::pair<std::string_view, std::string>> groups;
  for (const sensing::SetUp &s : sensing::setups()) {
    const auto same = [&](const auto &g) { return g.first == key(s); };
    auto group = std::find_if(groups.begin(), groups.end(), same);
    if (group == groups.end()) {
      groups.emplace_back(key(s), std::string(s.name));
    } else {
      group->second += fmt::format("{}{}", separator, s.name);
    }
  }
  return groups;
}

// "cell, ray (a lidar); bump (bumpers); depth, pie, cone (range sensors)"
std::string models_by_device() {
  std::string text;
  for (const auto &[devices, names] : grouped([](const sensing::SetUp &s) { return s.devices(); }, ", ")) {
    text += fmt::format("{}{} ({})", text.empty() ? "" : "; ", names, devices);
  }
  return text;
}

// "hambot; bumper-depth for bump and depth, ir-ring for pie and cone": the set-ups' default
// robots, the first set-up's first.
std::string default_robots() {
  std::string text;
  std::string others;
  for (const auto &[robot, names] : grouped([](const sensing::SetUp &s) { return s.default_robot; }, " and ")) {
    if (text.empty()) {
      text = robot;
    } else {
      others += fmt::format("{}{} for {}", others.empty() ? "" : ", ", robot, names);
    }
  }
  return others.empty() ? text : fmt::format("{}; {}", text, others);
}

void add_model_choice(CLI::App &command, RunOptions &o) {
  command.add_option("--subcells", o.subcells,
                     fmt::format("K: sub-cells per cell side, odd, 3 to 9 (default {})", o.subcells));
  command.add_option_function<std::string>(
      "--model", [&o](const std::string &name) { o.model.kind = sensing::parse_model(name); },
      fmt::format("mapping model: {} (default {})", models_by_device(), sensing::to_string(o.model.kind)));
  command.add_option("--threshold", o.threshold,
                     "L: a sub-cell is occupied when its log-odds >= L, for the map and the walls "
                     "(default none: when above 0)");
  command.add_option_function<double>(
      "--pie-beta", [&o](double deg) { o.range_model.pie_half_angle_rad = deg * std::numbers::pi / 180.0; },
      fmt::format("pie model: slice half-angle, degrees (default {:g})",
                  o.range_model.pie_half_angle_rad * 180.0 / std::numbers::pi));
  command.add_option("--pie-alpha", o.range_model.pie_contact_m,
                     fmt::format("pie model: contact slice length, m (default {})", o.range_model.pie_contact_m));
  command.add_option("--hit-depth", o.model.hit_depth,
                     fmt::format("ray model: sub-cells behind a hit also occupied (default {})", o.model.hit_depth));
  command.add_flag("--ignore-no-return", o.model.ignore_no_return,
                   "ray model: a beam with no return frees nothing (default off: it frees up to max range)");
  command.add_option_function<std::string>(
      "--strategy", [&o](const std::string &name) { o.strategy = explore::parse_strategy(name); },
      "exploration: dfs, frontier, left-wall, right-wall or floodfill (default dfs)");
}

void add_robot_and_faults(CLI::App &command, RunOptions &o) {
  command.add_option("--robot", o.robot,
                     fmt::format("NAME or FILE.json: robot profile, one of {} (default {})", robot_names(),
                                 default_robots()));
  add_seed_option(command, o.simulation.seed, "the sensor noise and the faults");
  command.add_option("--noise", o.simulation.noise,
                     "lidar noise, standard deviation as a fraction of max range; 0 makes every sensor "
                     "exact (default the robot's)");
  command.add_option("--dropout", o.simulation.dropout,
                     "fault: fraction of lidar beams that read +infinity (default 0)");
  command.add_option("--spikes", o.simulation.spikes,
                     "fault: fraction of lidar beams that read a random range (default 0)");
  command.add_option("--stuck-bumper", o.simulation.stuck_bumper,
                     "fault: NAME, a bumper that always reads pressed (default none)");
  command.add_option("--wheel-slip", o.simulation.wheel_slip,
                     "fault: fraction of wheel turning that does not move the robot; the encoders count "
                     "it all (default 0)");
}

}  // namespace

void add_mapping_run_options(CLI::App &command, RunOptions &o) {
  add_model_choice(command, o);
  add_robot_and_faults(command, o);
  add_model_options(command, o.sensor);
  add_clamp_option(command, o.sensor);
  // CLI11 alone clamps a number past the type's range to its maximum, silently.
  const CLI::Validator whole_steps = usage_check("--max-steps", [](const std::string &text) {
    return common::parse_number<std::int64_t>(text) ? std::string()
                                                      : fmt::format("must be a whole number from 1 to {} (got '{}')",
                                                                    std::numeric_limits<std::int64_t>::max(), text);
  });
  command
      .add_option("--max-steps", o.max_steps, "N: stop after this many control steps (default 1000 a cell, at least 100000)")
      ->check(whole_steps);
  command.add_option("--dilate", o.plan.wavefront.dilate,
                     fmt::format("N: planning: grow obstacles by N sub-cells (default {})", o.plan.wavefront.dilate));
  add_world_options(command, o.world_overrides);
}

void add_speed_run_option(CLI::App &command, RunOptions &o) {
  command.add_flag("--speed-run", o.plan.speed_run,
                   "after the search, drive the known shortest path from the start to the goal, returning to "
                   "the start first (a micromouse speed run; with floodfill the path is searched until proven)");
}

std::vector<PictureFormat> parse_picture_formats(const std::string &text) {
  std::vector<PictureFormat> formats;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    const std::string name = text.substr(begin, comma - begin);
    const std::optional<PictureFormat> format = picture_format_named(name);
    if (!format) throw common::InputError(fmt::format("--picture-format takes png, svg and pdf (got '{}')", name));
    if (std::find(formats.begin(), formats.end(), *format) != formats.end()) {
      throw common::InputError(fmt::format("--picture-format names {} twice", name));
    }
    formats.push_back(*format);
    begin = comma + 1;
  }
  return formats;
}

void add_picture_format_option(CLI::App &command, RunOptions &o) {
  command.add_option_function<std::string>(
      "--picture-format", [&o](const std::string &text) { o.output.picture_formats = parse_picture_formats(text); },
      "LIST: with --out, map, truth, plan and the snapshots as png, svg and/or pdf, comma-separated "
      "(default png; svg and pdf print at any size)");
}

void add_exploration_options(CLI::App &command, RunOptions &o) {
  command.add_option("WORLD", o.world, "maze file (default lab4x4.txt, from worlds/ here or the shipped worlds)");
  add_mapping_run_options(command, o);
  command.add_flag("--ascii", o.output.ascii, "heading arrows as ^ > v < instead of ↑ → ↓ ←");
  command.add_option_function<std::string>(
      "--unknown",
      [&o](const std::string &text) {
        validate_unknown(text);
        o.output.unknown = text[0];
      },
      "CHAR: drawn for never-observed sub-cells (default blank)");
}

RunOptions checked_run_options(const CLI::App &command, RunOptions options, bool with_default_world) {
  if (command.count("--robot") == 0) options.robot = std::string(default_robot(options.model.kind));
  if (with_default_world && options.world.empty()) options.world = default_world();
  options.world_overrides.random_start_seed = options.simulation.seed;  // --start random
  validate(options);
  return options;
}

std::vector<std::string> options_not_applying(const CLI::App &command, const RunOptions &options) {
  const GivenOptions given{command.get_name(),
                           [&command](std::string_view option) {
                             const CLI::Option *o = command.get_option_no_throw(std::string(option));
                             return o != nullptr && o->count() > 0;
                           }};
  return check_options_apply(given, options);
}

void print_warnings(const std::vector<std::string> &warnings) {
  for (const std::string &warning : warnings) fmt::print(stderr, "{}\n", warning);
}

}  // namespace app
