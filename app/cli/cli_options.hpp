#pragma once
// Options several commands take, registered by one function each so that they read, and
// are checked, the same everywhere.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/run/option_fields.hpp"  // robot_names()
#include "app/run/option_values.hpp"  // parse_number_list(), parse_pose()
#include "app/run/terminal.hpp"       // ColorChoice
#include "mapping/grid_types.hpp"
#include "maze/world/world.hpp"

namespace app {

// --seed N: a whole number from 0 to 2^64 - 1. Anything else ("-4", "abc", "1e3", a number
// past 2^64 - 1) is "--seed must be a whole number from 0 to 18446744073709551615 (got
// '-4')" (CLI11 alone would wrap "-4" to 2^64 - 4). `what` says what the seed drives; the
// description ends "(default <seed's value>)".
CLI::Option *add_seed_option(CLI::App &command, std::uint64_t &seed, const std::string &what);
// --seed N of a run (run, room, mms, batch, ...), checked as above, with the one help line of
// the run's options (app/run/option_fields.hpp's option_help).
CLI::Option *add_run_seed_option(CLI::App &command, std::uint64_t &seed);

// -o, --out DIR of a run (run, room, mms), with the one help line of the run's options.
CLI::Option *add_out_option(CLI::App &command, std::string &out_dir);

// --color WHEN (auto, always, never; auto honours NO_COLOR) into `color`, and its old spelling
// --no-color (hidden; warns and means --color never): the same in every command that colours.
void add_color_option(CLI::App &command, ColorChoice &color);

// A WORLD argument (one or several) as every command reads it: a path, else the name of a
// shipped world, with or without its extension (app/run/shipped_worlds.hpp, world_argument).
CLI::Option *accept_shipped_world_names(CLI::Option *world);

// "X,Y" (whole numbers, blanks around them allowed) -> the cell; throws common::InputError
// naming `option` as the user typed it: "--to must be X,Y (got '1')".
mapping::Cell parse_cell(const std::string &text, const std::string &option);

// --cell-size M alone (scan, convert), or with --start X,Y[,HEADING] and --goal X,Y (repeated
// for more cells; the old X,Y;X,Y warns) (run, compare, plan, batch), parsed straight into the
// overrides and checked as they are read (common::InputError naming the option). Cells are checked against the maze when it
// is loaded (maze::load_world).
void add_cell_size_option(CLI::App &command, maze::WorldOverrides &overrides);
void add_world_options(CLI::App &command, maze::WorldOverrides &overrides);

// "Xm,Ym" -> the point in metres, each a finite number with the unit m; nothing for any other
// text (a cell's "X,Y" among them).
std::optional<std::array<double, 2>> metres_point(std::string_view text);

// `old_name` kept for one release as another name of an option with a value: hidden from
// --help, the man page and the completions, it passes its value to `take` and warns on
// standard error with old_spelling_warning(old_name, new_name).
CLI::Option *add_old_spelling(CLI::App &command, const std::string &old_name, const std::string &new_name,
                              std::function<void(const std::string &)> take);

}  // namespace app
