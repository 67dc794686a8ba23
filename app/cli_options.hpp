#pragma once
// Options several commands take, registered by one function each so that they read, and
// are checked, the same everywhere.

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "mapping/grid_types.hpp"
#include "maze/world.hpp"

namespace app {

// --seed N: a whole number from 0 to 2^64 - 1. Anything else ("-4", "abc", "1e3", a number
// past 2^64 - 1) is "--seed must be a whole number from 0 to 18446744073709551615 (got
// '-4')" (CLI11 alone would wrap "-4" to 2^64 - 4). `what` says what the seed drives; the
// description ends "(default <seed's value>)".
CLI::Option *add_seed_option(CLI::App &command, std::uint64_t &seed, const std::string &what);

// "hambot, hambot-2025, ...": the built-in robot profiles' names (maze::sim::profiles()).
std::string robot_names();

// "X,Y" (whole numbers, blanks around them allowed) -> the cell; throws common::InputError
// naming `option` as the user typed it: "--to must be X,Y (got '1')".
mapping::Cell parse_cell(const std::string &text, const std::string &option);

// --cell-size M alone (scan, convert), or with --start X,Y[,HEADING] and --goal X,Y[;X,Y...]
// (run, compare, plan, batch), parsed straight into the overrides and checked as they are
// read (common::InputError naming the option). Cells are checked against the maze when it
// is loaded (maze::load_world).
void add_cell_size_option(CLI::App &command, maze::WorldOverrides &overrides);
void add_world_options(CLI::App &command, maze::WorldOverrides &overrides);

}  // namespace app
