// `convert WORLD out.wbt` carries the robot (app/report/webots_export.hpp): every device of the
// profile by its name, the controller, and controllerArgs that the Webots controller's
// parser reads back into what `run` gives the controller; that controller, run on the
// embedded simulator, prints what `run` prints.

#include <doctest/doctest.h>

#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"

#include "app/run/run.hpp"
#include "app/report/webots_export.hpp"
#include "maze/sim/simulation.hpp"
#include "maze/formats/text_map.hpp"
#include "maze/formats/wbt_format.hpp"
#include "maze/world/world.hpp"
#include "robot/console_main.hpp"
#include "robot/controller_args.hpp"

namespace {

std::size_t count(const std::string &text, std::string_view what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The Robot's controllerArgs strings, unescaped.
std::vector<std::string> controller_args(const std::string &wbt) {
  std::vector<std::string> args;
  std::size_t at = wbt.find("  controllerArgs [\n");
  REQUIRE(at != std::string::npos);
  std::istringstream lines(wbt.substr(at + std::string_view("  controllerArgs [\n").size()));
  for (std::string line; std::getline(lines, line) && line != "  ]";) {
    REQUIRE(line.starts_with("    \""));
    REQUIRE(line.ends_with("\""));
    std::string arg;
    for (std::size_t i = 5; i + 1 < line.size(); ++i) {
      if (line[i] == '\\') ++i;
      arg += line[i];
    }
    args.push_back(arg);
  }
  return args;
}

std::string quoted_name(const std::string &name) { return "name \"" + name + "\"\n"; }

std::vector<std::string> device_names(const maze::sim::RobotProfile &p) {
  std::vector<std::string> names = {p.left_motor, p.right_motor, p.left_encoder, p.right_encoder};
  if (!p.imu.empty()) names.push_back(p.imu);
  if (!p.gps.empty()) names.push_back(p.gps);
  for (const auto &l : p.lidars) names.push_back(l.name);
  for (const auto &d : p.distance_sensors) names.push_back(d.name);
  for (const auto &b : p.bumpers) names.push_back(b.name);
  return names;
}

const maze::Maze &lab4x4() {
  static const maze::Maze m = maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.txt").maze();
  return m;
}

}  // namespace

TEST_CASE("webots export: the robot stands at the start with the controller, at the controller's step") {
  const std::string wbt = app::webots_world(lab4x4(), "lab4x4", {});
  CHECK(count(wbt, "\nDEF ROBOT Robot {\n  translation 0.5 0.5 0\n  rotation 0 0 1 1.570796\n") == 1);
  CHECK(count(wbt, "  controller \"maze_mapper_controller\"\n  controllerArgs [\n") == 1);
  CHECK(count(wbt, "  basicTimeStep 32\n") == 1);
  CHECK(maze::wbt_basic_time_step_ms() == maze::sim::SimulationOptions{}.basic_time_step_ms);
  CHECK(count(wbt, "HingeJoint {") == 2);
  CHECK(count(wbt, "RotationalMotor {") == 2);
  CHECK(count(wbt, "PositionSensor {") == 2);
  CHECK(count(wbt, "physics Physics {") == 5);  // body, two wheels, two casters
  CHECK(count(wbt, "EXTERNPROTO") == 2);        // the background's; the robot is standard nodes
  CHECK(count(wbt, "{") == count(wbt, "}"));
  CHECK(count(wbt, "[") == count(wbt, "]"));
  // Without a robot, the maze alone (as `generate -o x.wbt` writes it).
  CHECK(count(maze::write_wbt(lab4x4(), "lab4x4"), "Robot {") == 0);
}

TEST_CASE("webots export: each profile's devices are named as the profile names them") {
  for (const maze::sim::RobotProfile &p : maze::sim::profiles()) {
    CAPTURE(p.name);
    app::WebotsExport options;
    options.robot = p.name;
    const std::string wbt = app::webots_world(lab4x4(), "lab4x4", options);
    for (const std::string &name : device_names(p)) {
      CAPTURE(name);
      CHECK(count(wbt, quoted_name(name)) == 1);
    }
    CHECK(count(wbt, "Lidar {") == p.lidars.size());
    CHECK(count(wbt, "DistanceSensor {") == p.distance_sensors.size());
    CHECK(count(wbt, "TouchSensor {") == p.bumpers.size());
    CHECK(count(wbt, "InertialUnit {") == (p.imu.empty() ? 0 : 1));
    CHECK(count(wbt, "GPS {") == (p.gps.empty() ? 0 : 1));
    for (const maze::sim::LidarSpec &l : p.lidars) {
      CHECK(count(wbt, fmt::format("horizontalResolution {}\n", l.horizontal_resolution)) >= 1);
    }
  }
}

TEST_CASE("webots export: the controllerArgs read back into what run gives the controller") {
  for (const maze::sim::RobotProfile &p : maze::sim::profiles()) {
    CAPTURE(p.name);
    app::WebotsExport options;
    options.robot = p.name;
    options.subcells = 5;
    const robot::ControllerOptions parsed =
        robot::parse_controller_args(controller_args(app::webots_world(lab4x4(), "lab4x4", options)));
    app::RunOptions run;
    run.robot = p.name;
    run.subcells = 5;
    run.model.kind = parsed.model.kind;
    const robot::ControllerOptions expected = app::controller_options(run, lab4x4(), p);
    CHECK(robot::format_controller_args(parsed) == robot::format_controller_args(expected));
    CHECK(parsed.geometry.width_cells == 4);
    CHECK(parsed.geometry.subcells == 5);
    CHECK(parsed.devices.left_motor == p.left_motor);
    CHECK(parsed.devices.left_encoder == p.left_encoder);
    CHECK(parsed.sensing.bumpers.size() == (parsed.model.kind == sensing::ModelKind::bump ? p.bumpers.size()
                                                                                             : parsed.sensing.bumpers.size()));
  }
}

TEST_CASE("webots export: a model the robot cannot sense with is refused") {
  app::WebotsExport options;
  options.robot = "ir-ring";
  options.model = "cell";
  CHECK_THROWS_WITH_AS(app::webots_world(lab4x4(), "lab4x4", options),
                       "robot 'ir-ring' has no lidar, which the 'cell' model needs (robots with lidar: hambot, hambot-2025, hambot-12m, micromouse)", common::InputError);
}

TEST_CASE("webots controller: on the embedded simulator it prints run's maps and matrices, no truth") {
  const maze::Maze m = maze::read_text_map("o---o---o\n| S     |\no   o---o\n|       |\no---o---o\n", "tiny");
  const std::vector<std::string> args = controller_args(app::webots_world(m, "tiny", {}));

  const maze::sim::RobotProfile &hambot = maze::sim::default_profile();
  webots::embedded::Simulation simulation(maze::world_of(m), hambot, maze::sim::SimulationOptions{});
  const webots::embedded::CurrentSimulation current(simulation);
  std::ostringstream out, err;
  CHECK(robot::console_main(args, out, err) == 0);
  CHECK(err.str().empty());

  app::RunOptions run;
  std::ostringstream expected;
  app::run_maze(run, m, expected);
  const std::string progress = expected.str().substr(0, expected.str().find("world: "));
  REQUIRE(out.str().starts_with(progress));
  const std::string summary = out.str().substr(progress.size());
  CHECK(summary.starts_with("end: done\nsteps: "));
  CHECK(count(summary, "visited: 4\n") == 1);
  CHECK(count(summary, "coverage") == 0);
  CHECK(count(summary, "accuracy") == 0);
}

TEST_CASE("webots controller: a bad argument or a missing device is one line, exit 2") {
  const maze::Maze m = maze::read_text_map("o---o\n| S |\no---o\n", "one");
  webots::embedded::Simulation simulation(maze::world_of(m), maze::sim::default_profile(), maze::sim::SimulationOptions{});
  const webots::embedded::CurrentSimulation current(simulation);
  std::ostringstream out, err;
  CHECK(robot::console_main(std::vector<std::string>{"--size=1x1", "--walls=none"}, out, err) == 2);
  CHECK(err.str().starts_with("error: unknown controller argument '--walls=none'"));
  CHECK(count(err.str(), "\n") == 1);
  err.str("");
  CHECK(robot::console_main(std::vector<std::string>{"--size=1x1", "--lidar=scanner"}, out, err) == 2);
  CHECK(err.str() == "error: the robot has no device \"scanner\"\n");
  CHECK(out.str().empty());
}
