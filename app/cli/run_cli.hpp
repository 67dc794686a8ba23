#pragma once
// The options of a maze run as the command line spells them, shared by run, plan, compare
// and batch so that all read the same words, parsed (CLI11) straight into the concern
// structs of RunOptions (app/run/run_options.hpp).

#include <vector>

#include <CLI/CLI.hpp>

#include "app/run/run_options.hpp"

namespace app {

// The mapping options run, batch, compare and plan take: --subcells --model --threshold
// --pie-beta --pie-alpha --hit-depth --ignore-no-return --robot --seed --noise
// --p-free --p-occ --prior --log-base --clamp --max-steps --dilate, the faults --dropout
// --spikes --stuck-bumper --wheel-slip, and the world options --cell-size --start --goal.
// A value that cannot be read throws common::InputError naming the option as typed.
void add_mapping_run_options(CLI::App &command, RunOptions &options);

// --max-steps N (every run): a whole number from 1, its help the run options' one line.
void add_max_steps_option(CLI::App &command, RunOptions &options);

// --strategy NAME of the strategies that explore in `space` (explore/strategies.hpp's table):
// a maze's cells (run, plan, compare, mms) or metres (room).
void add_strategy_option(CLI::App &command, RunOptions &options, explore::StrategySpace space);

// --speed-run (run, batch).
void add_speed_run_option(CLI::App &command, RunOptions &options);

// --picture-format LIST (run, plan): png, svg and/or pdf, comma-separated.
void add_picture_format_option(CLI::App &command, RunOptions &options);

// add_mapping_run_options, with WORLD, --strategy (a maze run's; batch reads its own, for maze
// and room runs), --ascii and --unknown (run, compare, plan).
void add_exploration_options(CLI::App &command, RunOptions &options);

// The options as parsed into `options` by `command`, made whole and checked once: the
// model's default robot when --robot was not given, the default world when none was given
// and `default_world` is set; then validate(). Throws common::InputError.
RunOptions checked_run_options(const CLI::App &command, RunOptions options, bool default_world);

// check_options_apply() for what `command` parsed.
std::vector<std::string> options_not_applying(const CLI::App &command, const RunOptions &options);

// Prints the warnings on stderr, one a line.
void print_warnings(const std::vector<std::string> &warnings);

}  // namespace app
