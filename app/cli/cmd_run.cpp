// maze_mapper run [WORLD] [options]: explore and map one world (see app/run/run.hpp), and plan:
// explore, then a wavefront path on the learned map.

#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/report/files_recorder.hpp"
#include "app/cli/cli_errors.hpp"
#include "app/cli/cli_options.hpp"
#include "app/cli/option_binding.hpp"
#include "app/run/run.hpp"
#include "app/cli/run_cli.hpp"
#include "app/run/terminal.hpp"
#include "app/cli/commands.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "common/standard_streams.hpp"
#include "maze/world/world.hpp"

namespace app {
namespace {

// --narrow, --wide: the terminal columns of a sub-cell (OutputOptions::subcell_columns).
void add_width_options(CLI::App &command, RunOptions &o) {
  CLI::Option *narrow = command.add_flag_callback(
      "--narrow", [&o] { o.output.subcell_columns = 1; },
      "one column a sub-cell, the classroom look (default when standard output is not a terminal)");
  command
      .add_flag_callback("--wide", [&o] { o.output.subcell_columns = 2; },
                         "two columns a sub-cell, the maze at its true aspect (default in a terminal the map fits)")
      ->excludes(narrow);
}

// What only `run` takes, besides the exploration options.
void add_run_only_options(CLI::App &run, RunOptions &o, ColorChoice &color) {
  add_field_option(run, o.output, "--quiet");
  add_speed_run_option(run, o);
  run.add_option_function<std::string>(
      "--plan-to", [&o](const std::string &text) { o.plan.to = parse_cell(text, "--plan-to"); },
      "X,Y: after the run, plan (wavefront) from where the robot ended to this cell");
  add_out_option(run, o.output.out_dir);
  add_field_option(run, o.output, "--snapshots");
  add_picture_format_option(run, o);
  add_field_options(run, o.output, {"--no-trace", "--trace-steps", "--no-replay"});
  add_color_option(run, color);
  add_field_option(run, o.output, "--animate");
  add_width_options(run, o);
  add_field_options(run, o.output, {"--fps", "--speed", "--step"});
  add_field_options(run, o.localize, {"--localize", "--sensor", "--motion", "--localized"});
}

void run_in_terminal(const RunOptions &options, CommandContext &context) {
  RunControls controls;
  common::InterruptibleInputBuffer stdin_buffer(STDIN_FILENO);  // --step's wait ends on a stop signal
  std::istream step_input(&stdin_buffer);
  controls.in = &step_input;
  if (options.output.step && is_terminal(STDIN_FILENO)) controls.prompt = &std::cerr;
  controls.interrupted = &common::interrupted;
  controls.terminal_fd = STDOUT_FILENO;
  controls.progress_fd = progress_fd(options.output.quiet, options.output.animate);
  const common::SignalsStopWork stop_signals;
  const RunSummary summary = run_and_write(options, std::cout, controls);
  context.status = exit_status(summary);
}

}  // namespace

void add_run_command(CLI::App &cli, CommandContext &context) {
  auto parsed = std::make_shared<RunOptions>();
  auto color = std::make_shared<ColorChoice>(ColorChoice::automatic);
  CLI::App *run = cli.add_subcommand(
      "run", "explore a world cell by cell and map it; print the map as it goes and a summary");
  add_exploration_options(*run, *parsed);
  add_run_only_options(*run, *parsed, *color);
  run->callback([run, parsed, color, &context] {
    RunOptions options = checked_run_options(*run, *parsed, true);
    const std::vector<std::string> warnings = options_not_applying(*run, options);
    if (context.run_parse_only != nullptr) {
      *context.run_parse_only = options;
      return;
    }
    if (options.output.animate && !is_terminal(STDOUT_FILENO)) {
      throw common::InputError(
          "--animate redraws a terminal in place and standard output is not one; without --animate the run "
          "prints the map at each new cell");
    }
    print_warnings(warnings);
    options.output.color = use_color(*color, STDOUT_FILENO);
    run_in_terminal(options, context);
  });
}

void add_plan_command(CLI::App &cli, CommandContext &context) {
  auto parsed = std::make_shared<RunOptions>();
  CLI::App *plan = cli.add_subcommand(
      "plan", "explore a world quietly, then plan a path on the learned map (wavefront) and draw it; "
              "exit status 1 when no path is found");
  add_exploration_options(*plan, *parsed);
  add_width_options(*plan, *parsed);
  plan->add_option_function<std::string>(
      "--from", [parsed](const std::string &text) { parsed->plan.from = parse_cell(text, "--from"); },
      "X,Y: start cell of the path (default the maze's start)");
  plan->add_option_function<std::string>(
      "--to", [parsed](const std::string &text) { parsed->plan.to = parse_cell(text, "--to"); },
      "X,Y: goal cell of the path (default the maze's first goal)");
  plan->add_option("-o,--out", parsed->output.out_dir,
                   "DIR: run --out's files, and plan.png (the learned map with the planned path) and plan.csv (its sub-cells)");
  add_picture_format_option(*plan, *parsed);
  plan->callback([plan, parsed, &context] {
    RunOptions options = checked_run_options(*plan, *parsed, true);
    options.output.quiet = true;
    options.plan.only = true;
    print_warnings(options_not_applying(*plan, options));
    const maze::World world = maze::load_world(options.world, options.world_overrides);
    if (!options.plan.from) options.plan.from = mapping::Cell{world.maze().start().x, world.maze().start().y};
    if (!options.plan.to) {
      if (world.maze().goals().empty()) throw common::InputError("plan: the maze has no goal; give --to X,Y");
      options.plan.to = mapping::Cell{world.maze().goals().front().x, world.maze().goals().front().y};
    }
    RunControls controls;
    controls.interrupted = &common::interrupted;
    controls.terminal_fd = STDOUT_FILENO;
    controls.progress_fd = progress_fd(true, false);  // plan explores quietly
    const common::SignalsStopWork stop_signals;
    const RunSummary summary = run_and_write(options, std::cout, controls);
    context.status = exit_status(summary);  // 1 when no path is found
  });
}

RunOptions parse_run_options(int argc, const char *const *argv) {
  CLI::App cli{"maze_mapper", "maze_mapper"};
  cli.require_subcommand(0, 1);
  RunOptions options;
  CommandContext context;
  context.run_parse_only = &options;
  add_run_command(cli, context);
  check_values_ourselves(cli);  // as add_commands() does for the program
  cli.parse(argc, argv);
  return options;
}

}  // namespace app
