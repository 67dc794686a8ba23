// maze_mapper room WORLD: a robot in a room, mapping onto a numCells grid (app/run/metric_run.hpp);
// its options are described in app/cli/room_options.hpp.

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli/floor_options.hpp"
#include "app/cli/cli_options.hpp"
#include "app/cli/model_options.hpp"
#include "app/cli/option_binding.hpp"
#include "app/cli/room_options.hpp"
#include "app/cli/run_cli.hpp"
#include "app/report/metric_files_recorder.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/demo_commands.hpp"

namespace app {
namespace {

struct RoomInput {
  std::string start, boundary;
  MetricRunOptions options;
};

// --start Xm,Ym[,YAW]: a pose as every command spells it (app/run/option_values.hpp); the old
// X,Y[,DEG] (no unit) is read the same, with a warning.
void read_start(const std::string &text, MetricRunOptions &o) {
  std::vector<std::string> warnings;
  const PoseArgument pose = parse_pose(text, "--start", warnings, PoseYaw::optional);
  print_warnings(warnings);
  o.start = mapping::Point{pose.x_m, pose.y_m};
  if (pose.yaw_given) o.start_yaw_deg = pose.yaw_deg;
}

// The options in the order the help shows them (app/cli/help_format.hpp groups them).
void add_room_options(CLI::App &cmd, RoomInput &in) {
  MetricRunOptions &o = in.options;
  o.model.kind = sensing::ModelKind::ray;  // a room's default: the lidar's rays (a maze's is cell)
  accept_shipped_world_names(cmd.add_option("WORLD", o.world, "the world file, or a shipped world's name"))->required();
  add_field_options(cmd, o, {"--strategy", "--model", "--robot", "--cells"});
  add_resolution_option(cmd, o.resolution_m, "0.1");
  add_boundary_option(cmd, in.boundary);
  cmd.add_option("--start", in.start, "X,Y[,YAW]: where the robot starts, X and Y with their unit m (0.5m,1.2m), and "
                                      "its heading, degrees from east or N, E, S, W (default the world's start)");
  add_field_options(cmd, o, {"--waypoints", "--laps", "--goal", "--dilate", "--time-limit"});
  add_old_spelling(cmd, "--time", "--time-limit", [&o](const std::string &text) {
    o.room.time_limit_s = parse_number_list(text, "--time-limit", 1)[0];
  });
  add_field_options(cmd, o, {"--snapshots-at", "--snapshot-steps", "--threshold", "--max-steps", "--depth-reading",
                             "--depth-origin"});
  add_seed_option(cmd, o.simulation.seed, "the simulation's noise and wander's turns");
  add_model_options(cmd, o.sensor);
  add_field_option(cmd, o, "--quiet");
  cmd.add_option("-o,--out", o.out_dir, "DIR: trace.csv, logodds.csv, thresholded.txt, map.pgm + map.yaml, summary.json, "
                                        "map.png, truth.png, replay.html (wavefront: wave.png), snapshots/*.png");
}

// The options once all are read: checked together, the ones that do nothing warned about.
void finish_options(RoomInput &in, const CLI::App &cmd) {
  MetricRunOptions &o = in.options;
  if (!in.start.empty()) read_start(in.start, o);
  check_room_options(o);
  const GivenOptions given{cmd.get_name(), [&cmd](std::string_view option) {
                             const CLI::Option *opt = cmd.get_option_no_throw(std::string(option));
                             return opt != nullptr && opt->count() > 0;
                           }};
  print_warnings(check_room_options_apply(given, o));
  o.room.seed = o.simulation.seed;
  if (o.model.kind == sensing::ModelKind::bump || o.model.kind == sensing::ModelKind::depth) {
    if (cmd.get_option("--log-base")->count() == 0) o.sensor.base = mapping::LogBase::ten;
  }
}

}  // namespace

void add_room_command(CLI::App &cli, CommandContext &context) {
  CLI::App *cmd = cli.add_subcommand("room", "a robot in a room or arena maps it onto a numCells grid: waypoints, "
                                             "wavefront to a goal, frontier exploration or wander");
  auto in = std::make_shared<RoomInput>();
  add_room_options(*cmd, *in);
  cmd->callback([&context, in, cmd] {
    const auto started = std::chrono::steady_clock::now();
    finish_options(*in, *cmd);
    const maze::World world = load_world_reporting(in->options.world, with_arena_overrides({}, in->boundary));
    const common::SignalsStopWork stop_signals;  // a signal ends the run at its next control step
    const MetricRunSummary summary = run_metric_and_write(world, in->options, std::cout, started, &common::interrupted);
    context.status = metric_run_exit_status(summary);
  });
}

}  // namespace app
