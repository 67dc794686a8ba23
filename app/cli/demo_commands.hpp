#pragma once
// The course demos besides demo 1d, registered under `demo` by add_demo_command
// (cmd_demo.cpp): `demo pie` (cmd_demo_pie.cpp), `demo cone` (cmd_demo_cone.cpp), `demo trilaterate` and
// `demo localize` (cmd_demo_localize.cpp). What
// each demo does is in app/course/; the top-level commands: commands.hpp.

#include <CLI/CLI.hpp>

#include "app/cli/commands.hpp"

namespace app {

void add_demo_pie(CLI::App &demo, CommandContext &context);
void add_demo_cone(CLI::App &demo, CommandContext &context);
void add_demo_trilaterate(CLI::App &demo, CommandContext &context);
void add_demo_localize(CLI::App &demo, CommandContext &context);

}  // namespace app
