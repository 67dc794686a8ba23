// maze_mapper room WORLD: a robot in a room, mapping onto a numCells grid (app/room_run.hpp).

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
#include "app/room/room_run.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/demo_commands.hpp"

namespace app {
namespace {

struct RoomInput {
  std::string strategy = "frontier";
  std::string model = "ray";
  std::string cells, resolution, boundary, waypoints, goal, start, snapshots_at, snapshot_steps;
  std::string depth_reading = "range", depth_origin;
  RoomRunOptions options;
};

mapping::Point point_of(const std::string &text, const std::string &option) {
  const std::vector<double> v = parse_number_list(text, option, 2);
  return {v[0], v[1]};
}

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

void build(RoomInput &in, const CLI::App &cmd) {
  RoomRunOptions &o = in.options;
  o.room.strategy = robot::parse_room_strategy(in.strategy);
  if (in.model == "cell") {
    throw common::InputError("--model cell reads a maze's cell sides; in a room the lidar marks with --model ray");
  }
  o.model.kind = sensing::parse_model(in.model);
  if (!in.cells.empty() && !in.resolution.empty()) throw common::InputError("give --cells or --resolution, not both");
  if (!in.cells.empty()) {
    const std::vector<double> c = parse_number_list(in.cells, "--cells", 2);
    for (const double v : c) {
      if (!(v >= 1 && v <= sensing::kMaxRoomCellsPerSide && v == std::floor(v))) {
        throw common::InputError(fmt::format("--cells must be X,Y with each a whole number 1 to {} (got {})",
                                             sensing::kMaxRoomCellsPerSide, in.cells));
      }
    }
    o.cells_x = static_cast<int>(c[0]);
    o.cells_y = static_cast<int>(c[1]);
  }
  if (!in.resolution.empty()) o.resolution_m = parse_number_list(in.resolution, "--resolution", 1)[0];
  if (!in.waypoints.empty()) {
    std::string text = in.waypoints;
    std::size_t start = 0;
    for (;;) {
      const std::size_t semi = text.find(';', start);
      o.room.waypoints.push_back(point_of(text.substr(start, semi == std::string::npos ? std::string::npos : semi - start),
                                          "--waypoints"));
      if (semi == std::string::npos) break;
      start = semi + 1;
    }
  }
  if (!in.goal.empty()) o.room.goal = point_of(in.goal, "--goal");
  if (!in.start.empty()) read_start(in.start, o);
  if (!in.snapshots_at.empty()) o.snapshots_at_s = parse_number_list(in.snapshots_at, "--snapshots-at");
  if (!in.snapshot_steps.empty()) {
    for (const double v : parse_number_list(in.snapshot_steps, "--snapshot-steps")) {
      if (!(v >= 1 && v == std::floor(v))) throw common::InputError("--snapshot-steps must be whole numbers >= 1");
      o.snapshot_steps.push_back(static_cast<std::int64_t>(v));
    }
  }
  if (in.depth_reading != "range" && in.depth_reading != "axial") {
    throw common::InputError("--depth-reading must be range or axial (got " + in.depth_reading + ")");
  }
  o.depth_reading = in.depth_reading == "axial" ? sensing::DepthReading::axial : sensing::DepthReading::range;
  if (!in.depth_origin.empty()) o.depth_origin = point_of(in.depth_origin, "--depth-origin");
  if (o.threshold && !std::isfinite(*o.threshold)) {
    throw common::InputError(fmt::format("--threshold must be a finite log-odds value (got {})", *o.threshold));
  }
  // Options of one strategy given to another are refused, not ignored.
  const auto given = [&cmd](const char *name) { return cmd.get_option(name)->count() > 0; };
  using robot::RoomStrategy;
  if (given("--waypoints") && o.room.strategy != RoomStrategy::waypoints) {
    throw common::InputError("--waypoints applies to --strategy waypoints only");
  }
  if (given("--laps") && o.room.strategy != RoomStrategy::waypoints) {
    throw common::InputError("--laps applies to --strategy waypoints only");
  }
  if ((given("--depth-reading") || given("--depth-origin")) && o.model.kind != sensing::ModelKind::depth) {
    throw common::InputError(fmt::format("--depth-reading and --depth-origin apply to --model depth only (got --model {})",
                                         in.model));
  }
  if (given("--goal") && o.room.strategy != RoomStrategy::wavefront) {
    throw common::InputError("--goal applies to --strategy wavefront only");
  }
  if (given("--dilate") && o.room.strategy != RoomStrategy::wavefront) {
    throw common::InputError("--dilate applies to --strategy wavefront only (frontier keeps the body's radius clear)");
  }
}

}  // namespace

void add_room_command(CLI::App &cli, CommandContext &context) {
  CLI::App *cmd = cli.add_subcommand("room", "a robot in a room or arena maps it onto a numCells grid: waypoints, "
                                             "wavefront to a goal, frontier exploration or wander");
  auto in = std::make_shared<RoomInput>();
  RoomRunOptions &o = in->options;
  accept_shipped_world_names(cmd->add_option("WORLD", o.world, "the world file, or a shipped world's name"))->required();
  cmd->add_option("--strategy", in->strategy, "waypoints, wavefront, frontier or wander (default frontier)");
  cmd->add_option("--model", in->model, "ray (lidar), pie or cone (IR/sonar ring), bump or depth (default ray)");
  cmd->add_option("--robot", o.robot, "a robot profile or JSON file (default the set-up's robot)");
  cmd->add_option("--cells", in->cells, "X,Y: numCells over the boundary (square cells)");
  cmd->add_option("--resolution", in->resolution, "M: cell size, m (default 0.1)");
  add_boundary_option(*cmd, in->boundary);
  cmd->add_option("--start", in->start, "POINT[,DEG]: where the robot starts, in metres with the unit (0.5m,1.2m), and its heading, degrees "
                                     "from east (default the world's start)");
  cmd->add_option("--waypoints", in->waypoints, "X,Y;X,Y;...: the points to visit, m (waypoints)");
  cmd->add_option("--laps", o.room.laps, "N: drive the waypoints N times over; 0: until --time-limit (default 1)");
  cmd->add_option("--goal", in->goal, "X,Y: the goal, m, of wavefront (default the world file's first goal)");
  cmd->add_option("--dilate", o.room.dilate, "N: wavefront: obstacles grown by N cells for planning (default 1)");
  cmd->add_option("--time-limit", o.room.time_limit_s, "S: stop after S simulated seconds; wander needs it (default none)");
  add_old_spelling(*cmd, "--time", "--time-limit", [in](const std::string &text) {
    in->options.room.time_limit_s = parse_number_list(text, "--time-limit", 1)[0];
  });
  cmd->add_option("--snapshots-at", in->snapshots_at, "T1,T2,...: print the map at these simulated seconds");
  cmd->add_option("--snapshot-steps", in->snapshot_steps, "N1,N2,...: print the map at these control steps");
  cmd->add_option("--threshold", o.threshold, "log-odds drawn W at or above (default 0; bump and depth -0.5)");
  cmd->add_option("--max-steps", o.max_steps, "control steps at most (default 2000000)");
  cmd->add_option("--depth-reading", in->depth_reading,
                  "range or axial (--model depth): the depth rays report the range along the ray, or the depth along "
                  "the heading from --depth-origin, as a depth camera and the homework's simulator do (default range)");
  cmd->add_option("--depth-origin", in->depth_origin,
                  "X,Y (--model depth): the depth rays leave this point of the robot, m, x forward, y left (default "
                  "none: each from the rim, trace.csv's depths from the centre)");
  add_seed_option(*cmd, o.simulation.seed, "the simulation's noise and wander's turns");
  add_model_options(*cmd, o.sensor);
  cmd->add_flag("--quiet", o.quiet, "print the summary only");
  cmd->add_option("-o,--out", o.out_dir, "DIR: trace.csv, logodds.csv, thresholded.txt, map.pgm + map.yaml, summary.json, map.png, "
                                     "truth.png, replay.html (wavefront: wave.png), snapshots/*.png");
  cmd->callback([&context, in, cmd] {
    const auto started = std::chrono::steady_clock::now();
    build(*in, *cmd);
    in->options.room.seed = in->options.simulation.seed;
    if (in->options.model.kind == sensing::ModelKind::bump || in->options.model.kind == sensing::ModelKind::depth) {
      if (cmd->get_option("--log-base")->count() == 0) in->options.sensor.base = mapping::LogBase::ten;
    }
    const maze::AnyWorld world = load_any_world_reporting(in->options.world, {}, arena_overrides(in->boundary));
    const common::SignalsStopWork stop_signals;  // a signal ends the run at its next control step
    const RoomSummary summary = run_room(world, in->options, std::cout, started, &common::interrupted);
    context.status = room_exit_status(summary);
  });
}

}  // namespace app
