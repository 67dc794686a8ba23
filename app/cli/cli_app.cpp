// The whole command line: every subcommand, registered in the order --help lists them.

#include <string>

#include <CLI/CLI.hpp>

#include "app/cli/cli_errors.hpp"
#include "app/cli/cli_reference.hpp"
#include "app/cli/help_format.hpp"
#include "app/cli/commands.hpp"

namespace app {
void add_commands(CLI::App &cli, CommandContext &context) {
  // Before the subcommands: each copies its parent's help flag as it is added.
  cli.set_help_flag("-h,--help", "print this help and exit");
  cli.set_version_flag("--version", std::string(MAZE_MAPPER_VERSION), "print the version and exit");
  cli.require_subcommand(0, 1);
  add_run_command(cli, context);
  add_compare_command(cli, context);
  add_plan_command(cli, context);
  add_batch_command(cli, context);
  add_mms_command(cli, context);
  add_demo_command(cli, context);
  add_explain_command(cli, context);
  add_map_log_command(cli, context);
  add_room_command(cli, context);
  add_show_command(cli, context);
  add_convert_command(cli, context);
  add_generate_command(cli, context);
  add_scan_command(cli, context);
  add_robot_command(cli, context);
  add_reference_command(cli);
  check_values_ourselves(cli);
  use_readable_help(cli);
}

}  // namespace app
