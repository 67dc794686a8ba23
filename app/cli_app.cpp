// The whole command line: every subcommand, registered in the order --help lists them.

#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "demo_commands.hpp"

namespace app {

void add_commands(CLI::App &cli, CommandContext &context) {
  // Before the subcommands: each copies its parent's help flag as it is added.
  cli.set_help_flag("-h,--help", "print this help and exit");
  cli.set_version_flag("--version", std::string(MAZE_MAPPER_VERSION), "print the version and exit");
  cli.require_subcommand(0, 1);
  add_run_command(cli, context);
  add_batch_command(cli, context);
  add_demo_command(cli, context);
  add_explain_command(cli, context);
  add_map_log_command(cli, context);
  add_show_command(cli, context);
  add_convert_command(cli, context);
  add_generate_command(cli, context);
  add_scan_command(cli, context);
  add_robot_command(cli, context);
}

}  // namespace app
