#pragma once
// The subcommands of maze_mapper. Each add_*_command registers its options and a callback
// with CLI11; the callback does the work and stores the process exit status in `status`.
// User errors are thrown as common::InputError and reported by main().

#include <string>

#include <CLI/CLI.hpp>

#include "maze/world.hpp"

namespace app {

struct CommandContext {
  int status = 0;  // exit status of the command that ran
};

// Loads a world (maze::load_world) and prints its warnings on stderr, one a line.
maze::World load_world_reporting(const std::string &path);

// `show WORLD`: the canonical text map on stdout, nothing else.
void add_show_command(CLI::App &cli, CommandContext &context);
// `convert WORLD OUT`: writes OUT in the format its extension names (.txt, .num, .xml, .wbt).
void add_convert_command(CLI::App &cli, CommandContext &context);
// `generate WxH [--seed N] [--loops F] [--algorithm dfs|kruskal|prim] [-o FILE]`.
void add_generate_command(CLI::App &cli, CommandContext &context);

}  // namespace app
