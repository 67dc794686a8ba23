// maze_mapper room WORLD: a robot in a room, mapping onto a numCells grid (app/run/metric/run.hpp);
// it takes the run's options (app/run/option_fields.hpp) that a run in metres uses, with the
// same words as run and mms, and a run in metres' own.

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
#include "app/cli/run_cli.hpp"
#include "app/report/files_recorder.hpp"
#include "app/run/terminal.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/demo_commands.hpp"

namespace app {
namespace {

struct RoomInput {
  std::string start, boundary;
  RunOptions options = metres_run_options();
};

// --start Xm,Ym[,YAW]: a pose as every command spells it (app/run/option_values.hpp); the old
// X,Y[,DEG] (no unit) is read the same, with a warning.
void read_start(const std::string &text, MetresOptions &o) {
  std::vector<std::string> warnings;
  const PoseArgument pose = parse_pose(text, "--start", warnings, PoseYaw::optional);
  print_warnings(warnings);
  o.start = mapping::Point{pose.x_m, pose.y_m};
  if (pose.yaw_given) o.start_yaw_deg = pose.yaw_deg;
}

// The options in the order the help shows them (app/cli/help_format.hpp groups them).
void add_room_options(CLI::App &cmd, RoomInput &in) {
  RunOptions &o = in.options;
  accept_shipped_world_names(cmd.add_option("WORLD", o.world, "the world file, or a shipped world's name"))->required();
  add_strategy_option(cmd, o, explore::StrategySpace::metres);
  add_field_option(cmd, o.model, "--model");
  add_field_option(cmd, o, "--robot");
  add_field_option(cmd, o.metres, "--cells");
  add_resolution_option(cmd, o.metres.resolution_m, "0.1");
  add_boundary_option(cmd, in.boundary);
  cmd.add_option("--start", in.start, "X,Y[,YAW]: where the robot starts, X and Y with their unit m (0.5m,1.2m), and "
                                      "its heading, degrees from east or N, E, S, W (default the world's start)");
  add_field_options(cmd, o.metres, {"--waypoints", "--laps", "--goal", "--dilate"});
  add_field_option(cmd, o, "--time-limit");
  add_old_spelling(cmd, "--time", "--time-limit", [&o](const std::string &text) {
    o.time_limit_s = parse_number_list(text, "--time-limit", 1)[0];
  });
  add_field_options(cmd, o.metres, {"--snapshots-at", "--snapshot-steps"});
  add_field_option(cmd, o, "--threshold");
  add_max_steps_option(cmd, o);
  add_field_options(cmd, o.metres, {"--depth-reading", "--depth-origin"});
  add_run_seed_option(cmd, o.simulation.seed);
  add_field_option(cmd, o.simulation, "--noise");
  add_model_options(cmd, o.sensor);
  add_clamp_option(cmd, o.sensor);
  add_field_option(cmd, o.output, "--quiet");
  add_field_options(cmd, o.metres, {"--verbose"});
  add_out_option(cmd, o.output.out_dir);
}

// The options once all are read: checked together, the ones that do nothing warned about.
void finish_options(RoomInput &in, const CLI::App &cmd) {
  RunOptions &o = in.options;
  if (!in.start.empty()) read_start(in.start, o.metres);
  validate_metres(o);
  const GivenOptions given{cmd.get_name(), [&cmd](std::string_view option) {
                             const CLI::Option *opt = cmd.get_option_no_throw(std::string(option));
                             return opt != nullptr && opt->count() > 0;
                           }};
  print_warnings(check_metres_options_apply(given, o));
  if (o.model.kind == sensing::ModelKind::bump || o.model.kind == sensing::ModelKind::depth) {
    if (cmd.get_option("--log-base")->count() == 0) o.sensor.base = mapping::LogBase::ten;
  }
  if (cmd.get_option("--robot")->count() == 0) o.robot = std::string(default_robot(o.model.kind));
  validate(o);
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
    const int progress = progress_fd(in->options.output.quiet, false);
    const MetricRunSummary summary =
        run_metric_and_write(world, in->options, std::cout, started, &common::interrupted, nullptr, progress);
    context.status = metric_run_exit_status(summary);
  });
}

}  // namespace app
