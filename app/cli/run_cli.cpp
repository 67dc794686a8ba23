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
#include "common/standard_streams.hpp"

namespace app {
namespace {

void add_model_choice(CLI::App &command, RunOptions &o) {
  add_field_option(command, o, "--subcells");
  add_field_option(command, o.model, "--model");
  add_field_option(command, o, "--threshold");
  add_field_options(command, o.range_model, {"--pie-beta", "--pie-alpha"});
  add_field_options(command, o.model, {"--hit-depth", "--ignore-no-return"});
}

void add_robot_and_faults(CLI::App &command, RunOptions &o) {
  add_field_option(command, o, "--robot");
  add_run_seed_option(command, o.simulation.seed);
  add_field_options(command, o.simulation, {"--noise", "--dropout", "--spikes", "--stuck-bumper", "--wheel-slip"});
}

}  // namespace

void add_mapping_run_options(CLI::App &command, RunOptions &o) {
  add_model_choice(command, o);
  add_robot_and_faults(command, o);
  add_model_options(command, o.sensor);
  add_clamp_option(command, o.sensor);
  add_max_steps_option(command, o);
  add_field_option(command, o, "--time-limit");
  add_field_option(command, o.plan, "--dilate");
  add_world_options(command, o.world_overrides);
}

void add_max_steps_option(CLI::App &command, RunOptions &o) {
  // CLI11 alone clamps a number past the type's range to its maximum, silently.
  const CLI::Validator whole_steps = usage_check("--max-steps", [](const std::string &text) {
    return common::parse_number<std::int64_t>(text) ? std::string()
                                                      : fmt::format("must be a whole number from 1 to {} (got '{}')",
                                                                    std::numeric_limits<std::int64_t>::max(), text);
  });
  command.add_option("--max-steps", o.max_steps, option_help("--max-steps"))->check(whole_steps);
}

void add_strategy_option(CLI::App &command, RunOptions &o, explore::StrategySpace space) {
  if (space == explore::StrategySpace::cells) {
    add_field_option(command, o, "--strategy");
    return;
  }
  command.add_option_function<std::string>(
      "--strategy",
      [&o](const std::string &name) { o.strategy = explore::parse_strategy(name, explore::StrategySpace::metres); },
      fmt::format("{} (default {})", explore::strategy_names(explore::StrategySpace::metres),
                  explore::to_string(o.strategy)));
}

void add_speed_run_option(CLI::App &command, RunOptions &o) { add_field_option(command, o.plan, "--speed-run"); }

void add_picture_format_option(CLI::App &command, RunOptions &o) {
  add_field_option(command, o.output, "--picture-format");
}

void add_exploration_options(CLI::App &command, RunOptions &o) {
  accept_shipped_world_names(command.add_option(
      "WORLD", o.world, "maze file or a shipped world's name (default lab4x4.txt, from worlds/ here or the shipped worlds)"));
  add_strategy_option(command, o, explore::StrategySpace::cells);
  add_mapping_run_options(command, o);
  add_field_options(command, o.output, {"--ascii", "--unknown"});
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
  for (const std::string &warning : warnings) common::print_stderr("{}\n", warning);
}

}  // namespace app
