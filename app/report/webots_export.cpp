#include "app/report/webots_export.hpp"

#include "app/run/run.hpp"
#include "maze/formats/wbt_format.hpp"
#include "robot/controller_args.hpp"

namespace app {

namespace {

sensing::ModelKind model_for(const WebotsExport &options, const maze::sim::RobotProfile &profile) {
  if (!options.model.empty()) return sensing::parse_model(options.model);
  // The first set-up the robot has the devices for.
  for (const sensing::SetUp &setup : sensing::setups()) {
    if (has_devices(profile, setup)) return setup.kind;
  }
  return sensing::ModelKind::cell;
}

}  // namespace

std::string webots_world(const maze::Maze &maze, std::string_view title, const WebotsExport &options) {
  const maze::sim::RobotProfile &profile = maze::sim::find_profile(options.robot);
  RunOptions run;
  run.robot = profile.name;
  run.subcells = options.subcells;
  run.model.kind = model_for(options, profile);
  run.strategy = explore::parse_strategy(options.strategy);
  require_sensors(run, profile);
  const robot::ControllerOptions controller = controller_options(run, maze, profile);
  robot::validate(controller);
  const maze::WbtRobot robot{&profile, "maze_mapper_controller", robot::format_controller_args(controller)};
  return maze::write_wbt(maze, title, robot);
}

}  // namespace app
