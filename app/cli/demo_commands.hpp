#pragma once
// The course demos besides demo 1d, registered under `demo` by add_demo_command
// (cmd_demo.cpp): `demo pie` (cmd_demo_pie.cpp) and `demo cone` (cmd_demo_cone.cpp), and the
// number lists the course commands read. The top-level commands: commands.hpp.

#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/commands.hpp"

namespace app {

void add_demo_pie(CLI::App &demo, CommandContext &context);
void add_demo_cone(CLI::App &demo, CommandContext &context);

// "1, 1.5,0.8" -> {1, 1.5, 0.8}; throws common::InputError naming `option`:
// "--readings item 2 is not a number (got 'x')". Exactly `count` items when count > 0.
std::vector<double> parse_number_list(std::string_view text, const std::string &option, std::size_t count = 0);

}  // namespace app
