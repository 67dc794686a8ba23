// maze_mapper room WORLD: a robot in a room, mapping onto a numCells grid (app/room/room_run.hpp);
// its options are described in app/cli/room_options.hpp.

#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli/arena_options.hpp"
#include "app/cli/cli_options.hpp"
#include "app/cli/model_options.hpp"
#include "app/cli/option_binding.hpp"
#include "app/cli/room_options.hpp"
#include "app/cli/run_cli.hpp"
#include "app/room/room_run.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/demo_commands.hpp"

namespace app {
namespace {

struct RoomInput {
  std::string start, boundary;
  RoomRunOptions options;
};

// --start Xm,Ym[,DEG]: metres, as every command spells a point in metres; the old X,Y[,DEG]
// (no unit) is read the same, with a warning.
void read_start(const std::string &text, RoomRunOptions &o) {
  const std::size_t second = text.find(',', text.find(',') + 1);
  const std::string where = text.substr(0, second);
  std::optional<std::array<double, 2>> point = metres_point(where);
  if (!point) {
    const std::vector<double> bare = parse_number_list(where, "--start", 2);
    point = std::array<double, 2>{bare[0], bare[1]};
    fmt::print(stderr, "{}\n", old_spelling_warning(fmt::format("--start {}", where),
                                                    fmt::format("--start {:g}m,{:g}m", bare[0], bare[1])));
  }
  o.start = mapping::Point{(*point)[0], (*point)[1]};
  if (second != std::string::npos) o.start_yaw_deg = parse_number_list(text.substr(second + 1), "--start's DEG", 1)[0];
}

// The options in the order the help shows them (app/cli/help_format.hpp groups them).
void add_room_options(CLI::App &cmd, RoomInput &in) {
  RoomRunOptions &o = in.options;
  o.model.kind = sensing::ModelKind::ray;  // a room's default: the lidar's rays (a maze's is cell)
  accept_shipped_world_names(cmd.add_option("WORLD", o.world, "the world file, or a shipped world's name"))->required();
  add_field_options(cmd, o, {"--strategy", "--model", "--robot", "--cells"});
  add_resolution_option(cmd, o.resolution_m, "0.1");
  add_boundary_option(cmd, in.boundary);
  cmd.add_option("--start", in.start, "POINT[,DEG]: where the robot starts, in metres with the unit (0.5m,1.2m), and its "
                                      "heading, degrees from east (default the world's start)");
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
  RoomRunOptions &o = in.options;
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
    const RoomSummary summary = run_room(world, in->options, std::cout, started, &common::interrupted);
    context.status = room_exit_status(summary);
  });
}

}  // namespace app
