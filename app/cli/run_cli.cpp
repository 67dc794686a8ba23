#include "common/parse_number.hpp"
#include "app/cli/cli_errors.hpp"
#include "app/cli/run_cli.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli/cli_options.hpp"
#include "app/cli/commands.hpp"
#include "app/run/shipped_worlds.hpp"
#include "common/error.hpp"
#include "app/cli/model_options.hpp"
#include "app/cli/option_binding.hpp"

namespace app {
namespace {

void add_model_choice(CLI::App &command, RunOptions &o) {
  add_field_option(command, o, "--subcells");
  add_field_option(command, o.model, "--model");
  add_field_option(command, o, "--threshold");
  add_field_options(command, o.range_model, {"--pie-beta", "--pie-alpha"});
  add_field_options(command, o.model, {"--hit-depth", "--ignore-no-return"});
  add_field_option(command, o, "--strategy");
}

void add_robot_and_faults(CLI::App &command, RunOptions &o) {
  add_field_option(command, o, "--robot");
  add_seed_option(command, o.simulation.seed, "the sensor noise and the faults");
  add_field_options(command, o.simulation, {"--noise", "--dropout", "--spikes", "--stuck-bumper", "--wheel-slip"});
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
  add_field_option(command, o.plan, "--dilate");
  add_world_options(command, o.world_overrides);
}

void add_speed_run_option(CLI::App &command, RunOptions &o) { add_field_option(command, o.plan, "--speed-run"); }

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
  add_field_option(command, o.output, "--ascii");
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
