#pragma once
// What a command line says about a floor in metres and the grid laid on it: --boundary
// XS,XE,YS,YE and --resolution M.

#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/run/option_values.hpp"
#include "maze/world/world.hpp"

namespace app {

// --boundary XS,XE,YS,YE (m): an arena's floor, over the file's or the default one.
void add_boundary_option(CLI::App &cmd, std::string &boundary);
// --resolution LENGTH: a grid cell's side, declared once for every command that lays a grid
// (room, show, demo pie, demo cone, demo 1d): a finite number > 0 in metres, or with its unit
// (0.1m, 10cm; app/run/option_values.hpp). Else common::InputError "--resolution must be > 0 m
// (got 0)". `take` gets the length as typed (demo 1d reads a bare number as its old cm for
// one release); the second form stores metres. `default_text` ends the help: "(default <it>)".
CLI::Option *add_resolution_option(CLI::App &cmd, std::function<void(const Length &)> take,
                                   const std::string &default_text);
CLI::Option *add_resolution_option(CLI::App &cmd, std::optional<double> &resolution_m, const std::string &default_text);
// `overrides` with the arena's ones set: a --boundary text ("" for none) and the robot's body
// radius. Throws common::InputError naming --boundary for a text that is not four numbers.
maze::WorldOverrides with_arena_overrides(maze::WorldOverrides overrides, const std::string &boundary,
                                          double robot_radius_m = 0.0);

}  // namespace app
