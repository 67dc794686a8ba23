// maze_mapper robot [NAME|FILE.json]: the built-in robot profiles, one a line (name and
// description), or one profile as JSON (app/profile_json.hpp), to edit and load back with
// --robot FILE.json.

#include <iostream>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/cli_options.hpp"
#include "app/profile_json.hpp"
#include "commands.hpp"
#include "maze/sim/profile.hpp"

namespace app {
namespace {

void list_profiles(std::ostream &out) {
  std::size_t width = 0;
  for (const maze::sim::RobotProfile &p : maze::sim::profiles()) width = std::max(width, p.name.size());
  for (const maze::sim::RobotProfile &p : maze::sim::profiles()) {
    out << fmt::format("{:<{}}  {}{}\n", p.name, width, p.description,
                       &p == &maze::sim::default_profile() ? " (default)" : "");
  }
}

}  // namespace

void add_robot_command(CLI::App &cli, CommandContext &context) {
  auto *cmd = cli.add_subcommand("robot", "list the robot profiles, or print one as JSON");
  auto name = std::make_shared<std::string>();
  cmd->add_option("NAME", *name, "a built-in profile, one of " + robot_names() + ", or a profile file (FILE.json) to check and print");
  cmd->callback([name, &context] {
    if (name->empty()) {
      list_profiles(std::cout);
    } else {
      std::cout << profile_to_json(resolve_robot(*name));
    }
    context.status = 0;
  });
}

}  // namespace app
