// maze_mapper robot [NAME|FILE.json]: the built-in robot profiles, one a line (name and
// description), or one profile as JSON (app/run/profile_json.hpp), to edit and load back with
// --robot FILE.json.

#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "app/cli/cli_options.hpp"
#include "app/run/profile_json.hpp"
#include "app/run/run.hpp"
#include "app/run/shipped_worlds.hpp"
#include "app/cli/commands.hpp"
#include "maze/sim/profile.hpp"
#include "sensing/setups.hpp"

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

// A profile file passes only what `run --robot FILE` passes: besides its own checks (made
// when it is read), one control step of the default world with the first set-up whose
// devices it has, which checks what only the controller and the simulator check (a noise
// whose range error overflows, a device name the robot does not carry).
void check_as_run_does(const std::string &file, const maze::sim::RobotProfile &profile) {
  RunOptions options;
  options.world = default_world();
  options.robot = file;
  options.max_steps = 1;
  options.output.quiet = true;
  for (const sensing::SetUp &setup : sensing::setups()) {
    if (!has_devices(profile, setup)) continue;
    options.model.kind = setup.kind;
    std::ostringstream ignored;
    run_world(options, ignored);
    return;
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
      const maze::sim::RobotProfile profile = resolve_robot(*name);
      if (names_a_profile_file(*name)) check_as_run_does(*name, profile);
      std::cout << profile_to_json(profile);
    }
    context.status = 0;
  });
}

}  // namespace app
