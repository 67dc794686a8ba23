#pragma once
// The subcommands of maze_mapper. Each add_*_command registers its options and a callback
// with CLI11; the callback does the work and stores the process exit status in `status`.
// User errors are thrown as common::InputError and reported by main().

#include <CLI/CLI.hpp>

namespace app {

struct CommandContext {
  int status = 0;  // exit status of the command that ran
};

// maze_mapper demo 1d: the textbook 1-D log-odds exercise (cmd_demo.cpp).
void add_demo_command(CLI::App &cli, CommandContext &context);

// maze_mapper explain: the sensor model's numbers (cmd_explain.cpp).
void add_explain_command(CLI::App &cli, CommandContext &context);

}  // namespace app
