// The whole command line: every subcommand, registered in the order --help lists them.

#include <string>

#include <CLI/CLI.hpp>

#include "app/cli/cli_reference.hpp"
#include "app/cli/help_format.hpp"
#include "app/cli/commands.hpp"

namespace app {
namespace {

// An option's value typed empty (--out "", WORLD "") is refused rather than taken for the
// option left out: each command reads "" as "not given" (no files, the default world).
void refuse_empty_values(CLI::App &command) {
  const CLI::Validator non_empty([](std::string &value) { return value.empty() ? std::string("must not be empty") : std::string(); },
                                 "", "non-empty");
  for (CLI::Option *option : command.get_options()) {
    if (option->get_type_size_max() > 0) option->check(non_empty);
  }
  for (CLI::App *sub : command.get_subcommands([](CLI::App *) { return true; })) refuse_empty_values(*sub);
}

}  // namespace

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
  add_show_command(cli, context);
  add_convert_command(cli, context);
  add_generate_command(cli, context);
  add_scan_command(cli, context);
  add_robot_command(cli, context);
  add_reference_command(cli);
  refuse_empty_values(cli);
  use_readable_help(cli);
}

}  // namespace app
