// maze_mapper mms [WORLD] [options] -- COMMAND [ARGS...] (see app/mms/mms_session.hpp).

#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli/cli_options.hpp"
#include "app/cli/option_binding.hpp"
#include "app/cli/mms_options.hpp"
#include "app/mms/mms_session.hpp"
#include "app/cli/run_cli.hpp"
#include "app/run/terminal.hpp"
#include "app/cli/commands.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"

namespace app {

std::vector<std::string> split_child_command(const std::vector<std::string> &args, CommandContext &context) {
  if (args.size() < 2 || (args[1] != "mms" && args[1] != "batch")) return args;
  const auto dash = std::find(args.begin(), args.end(), "--");
  if (dash == args.end()) return args;
  context.child_command.assign(dash + 1, args.end());
  return {args.begin(), dash};
}

void add_mms_command(CLI::App &cli, CommandContext &context) {
  auto parsed = std::make_shared<RunOptions>();
  auto mms = std::make_shared<MmsOptions>();
  auto color = std::make_shared<ColorChoice>(ColorChoice::automatic);
  CLI::App *command = cli.add_subcommand(
      "mms", "run an mms-protocol micromouse algorithm (any program: mms WORLD -- python3 algo.py) on the "
             "simulated robot; print the map, its marks, and mms's stats and score");
  add_exploration_options(*command, *parsed);
  add_mms_options(*command, *mms);
  add_field_option(*command, parsed->output, "--quiet");
  add_out_option(*command, parsed->output.out_dir);
  add_color_option(*command, *color);
  command->add_flag("--transcript", mms->transcript,
                    "print the conversation on stderr: `mms N> line` from the algorithm, `mms N< answer` back");
  command->callback([command, parsed, mms, color, &context] {
    RunOptions options = checked_run_options(*command, *parsed, true);
    check_mms_command_line(*command);
    print_warnings(options_not_applying(*command, options));
    options.output.color = use_color(*color, STDOUT_FILENO);
    MmsOptions asked = *mms;
    asked.command = context.child_command;
    validate(asked);
    RunControls controls;
    controls.interrupted = &common::interrupted;
    controls.terminal_fd = STDOUT_FILENO;
    // The progress line on stderr, unless the transcript is printed there.
    controls.progress_fd = asked.transcript ? -1 : progress_fd(options.output.quiet, false);
    const common::SignalsStopWork stop_signals;  // the children are ended and reaped first
    const MmsRun run = run_mms_world(options, asked, std::cout, controls);
    context.status = exit_status(run);
  });
}

}  // namespace app
