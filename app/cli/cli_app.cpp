// The whole command line: every subcommand, registered in the order --help lists them.

#include <algorithm>
#include <iterator>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "app/cli/cli_errors.hpp"
#include "app/cli/cli_reference.hpp"
#include "app/cli/help_format.hpp"
#include "app/cli/commands.hpp"

namespace app {
namespace {

using AddCommand = void (*)(CLI::App &, CommandContext &);

struct Command {
  std::string_view name;
  AddCommand add;
};

// Every subcommand, in the order `maze_mapper --help` lists them.
constexpr Command kCommands[] = {
    {"run", add_run_command},
    {"compare", add_compare_command},
    {"plan", add_plan_command},
    {"batch", add_batch_command},
    {"mms", add_mms_command},
    {"demo", add_demo_command},
    {"explain", add_explain_command},
    {"map-log", add_map_log_command},
    {"room", add_room_command},
    {"worlds", add_worlds_command},
    {"show", add_show_command},
    {"convert", add_convert_command},
    {"generate", add_generate_command},
    {"scan", add_scan_command},
    {"robot", add_robot_command},
    {"reference", [](CLI::App &cli, CommandContext &) { add_reference_command(cli); }},
};

}  // namespace

void add_commands(CLI::App &cli, CommandContext &context, std::string_view first_word) {
  // Before the subcommands: each copies its parent's help flag as it is added.
  cli.set_help_flag("-h,--help", "print this help and exit");
  cli.set_version_flag("--version", std::string(MAZE_MAPPER_VERSION), "print the version and exit");
  cli.require_subcommand(0, 1);
  // `reference` describes the whole tree, so it is built with all the others.
  const auto named = std::find_if(std::begin(kCommands), std::end(kCommands), [first_word](const Command &c) {
    return c.name == first_word && c.name != "reference";
  });
  if (named != std::end(kCommands)) {
    named->add(cli, context);
  } else if (first_word != "--version") {
    for (const Command &c : kCommands) c.add(cli, context);
  }
  check_values_ourselves(cli);
  use_readable_help(cli);
}

}  // namespace app
