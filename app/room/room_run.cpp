// A robot in a room, in the embedded simulator (app/room_run.hpp).

#include "app/room/room_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <variant>
#include <array>
#include <numbers>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/report/output_dir.hpp"
#include "app/report/outputs.hpp"
#include "app/run/profile_json.hpp"
#include "app/run/run.hpp"
#include "app/run/run_options.hpp"
#include "common/atomic_file.hpp"
#include "common/compass.hpp"
#include "common/error.hpp"
#include "maze/sim/profile.hpp"
#include "maze/arena.hpp"
#include "maze/arena_truth.hpp"
#include "maze/arena_world.hpp"
#include "maze/maze.hpp"
#include "plan/room_wavefront.hpp"

namespace app {
namespace {

using mapping::Point;
using sensing::RoomCell;

constexpr double kDeg = std::numbers::pi / 180.0;

bool is_log_set_up(sensing::ModelKind k) {
  return k == sensing::ModelKind::bump || k == sensing::ModelKind::depth;
}

char arrow_of(double yaw_rad) {
  const double a = std::fmod(std::fmod(yaw_rad, 2 * std::numbers::pi) + 2 * std::numbers::pi, 2 * std::numbers::pi);
  const int q = static_cast<int>(std::lround(a / (std::numbers::pi / 2))) % 4;
  return ">^<v"[q];
}

double threshold_of(const RoomRunOptions &o) {
  return o.threshold.value_or(is_log_set_up(o.model.kind) ? -0.5 : 0.0);
}

// The ASCII map, north row first: W at or above the threshold, . below, blank never observed,
// * the path, the robot's arrow.
std::string ascii_map(const robot::RoomController &c, double threshold) {
  const sensing::RoomMap &map = c.map();
  std::vector<char> on_path(map.size(), 0);
  for (const std::size_t p : c.path()) on_path[p] = 1;
  const auto robot = map.cell_at(c.position());
  std::string out;
  out.reserve(map.size() + static_cast<std::size_t>(map.cells_y()));
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) {
      const std::size_t n = map.index({i, j});
      char ch = ' ';
      if (robot && robot->i == i && robot->j == j) {
        ch = arrow_of(c.yaw_rad());
      } else if (on_path[n] != 0) {
        ch = '*';
      } else if (!map.unobserved_at(n)) {
        ch = map.log_odds_at(n) >= threshold ? 'W' : '.';
      }
      out += ch;
    }
    out += '\n';
  }
  return out;
}

std::string binary_map(const sensing::RoomMap &map, double threshold) {
  std::string out;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) out += map.log_odds({i, j}) >= threshold ? '1' : '0';
    out += '\n';
  }
  return out;
}

std::string wave_numbers(const sensing::RoomMap &map, const std::vector<std::int32_t> &wave) {
  if (wave.empty()) return "";
  const std::int32_t top = *std::max_element(wave.begin(), wave.end());
  const int width = static_cast<int>(fmt::format("{}", top).size()) + 1;
  std::string out;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) out += fmt::format("{:>{}}", wave[map.index({i, j})], width);
    out += '\n';
  }
  return out;
}

void write_outputs(const std::string &dir, const sensing::RoomMap &map, const std::string &trace,
                   const std::string &summary_json, double threshold) {
  std::ostringstream csv;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) csv << (i == 0 ? "" : ",") << fmt::format("{:.6f}", map.log_odds({i, j}));
    csv << '\n';
  }
  std::string pgm = fmt::format("P5\n{} {}\n255\n", map.cells_x(), map.cells_y());
  const auto l0 = static_cast<float>(map.model().prior_log_odds());
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) {
      pgm += static_cast<char>(pgm_pixel(static_cast<float>(map.log_odds({i, j})), l0));
    }
  }
  const std::filesystem::path d(dir);
  common::write_file_atomically((d / "trace.csv").string(), trace);
  common::write_file_atomically((d / "logodds.csv").string(), csv.str());
  common::write_file_atomically((d / "thresholded.txt").string(), binary_map(map, threshold));
  common::write_file_atomically((d / "map.pgm").string(), pgm);
  common::write_file_atomically((d / "map.yaml").string(), map_yaml(map.geometry(), "map.pgm"));
  common::write_file_atomically((d / "summary.json").string(), summary_json);
}

}  // namespace

int room_exit_status(const RoomSummary &s) {
  switch (s.ending) {
    case robot::RoomEnding::done:
    case robot::RoomEnding::goal_reached:
    case robot::RoomEnding::arrived:
    case robot::RoomEnding::time_up: return 0;
    default: return 1;
  }
}

RoomSummary run_room(const RoomRunOptions &options, std::ostream &out) {
  const auto started = std::chrono::steady_clock::now();
  // ---- everything checked before anything runs ----
  maze::ArenaOverrides arena_overrides;
  if (options.boundary) {
    arena_overrides.boundary_m = std::array<double, 4>{options.boundary->x_start_m, options.boundary->x_end_m,
                                                       options.boundary->y_start_m, options.boundary->y_end_m};
  }
  const maze::AnyWorld loaded = maze::load_any_world(options.world, {}, arena_overrides);
  maze::Arena arena;
  if (const auto *a = std::get_if<maze::ArenaWorld>(&loaded)) {
    arena = a->arena;
    for (const std::string &w : a->warnings) std::cerr << w << '\n';
  } else {
    const auto &m = std::get<maze::World>(loaded);
    if (options.boundary) throw common::InputError("--boundary applies to arenas; a maze's map covers the maze");
    arena = maze::arena_from_maze(m.maze);
    for (const std::string &w : m.warnings) std::cerr << w << '\n';
  }
  return run_room_in(arena, options, out, started);
}

RoomSummary run_room_in(const maze::Arena &arena, const RoomRunOptions &options, std::ostream &out,
                        std::chrono::steady_clock::time_point started) {
  const sensing::SetUp &setup = sensing::setup(options.model.kind);
  const std::string robot_name = options.robot.empty() ? std::string(setup.default_robot) : options.robot;
  const maze::sim::RobotProfile profile = resolve_robot(robot_name);
  if (!has_devices(profile, setup)) {
    throw common::InputError(fmt::format("--robot {} has no {}, which --model {} reads", profile.name, setup.devices(),
                                         setup.name));
  }
  robot::validate(options.room);
  maze::ArenaPose start_pose = arena.start();
  if (options.start) {
    start_pose.x_m = options.start->x_m;
    start_pose.y_m = options.start->y_m;
  }
  if (options.start_yaw_deg) start_pose.yaw_rad = *options.start_yaw_deg * kDeg;
  const sensing::RoomBoundary boundary{arena.x_min_m, arena.x_max_m, arena.y_min_m, arena.y_max_m};
  const sensing::RoomGridSpec spec =
      options.cells_x ? sensing::room_grid_from_cells(boundary, *options.cells_x, *options.cells_y)
                      : sensing::room_grid_from_resolution(boundary, options.resolution_m.value_or(0.1));
  sensing::validate(spec);
  const auto inside = [&](Point p) {
    return p.x_m >= spec.boundary.x_start_m && p.x_m < spec.boundary.x_end_m && p.y_m >= spec.boundary.y_start_m &&
           p.y_m < spec.boundary.y_end_m;
  };
  const Point start{start_pose.x_m, start_pose.y_m};
  if (!inside(start)) {
    throw common::InputError(fmt::format("the start ({:g}, {:g}) is outside the boundary {:g},{:g},{:g},{:g}", start.x_m,
                                         start.y_m, spec.boundary.x_start_m, spec.boundary.x_end_m,
                                         spec.boundary.y_start_m, spec.boundary.y_end_m));
  }
  {
    maze::Arena placed = arena;
    placed.starts = {start_pose};
    if (const maze::ArenaCheck bad = maze::check_starts_clear(placed, profile.body_radius_m)) throw *bad;
  }
  if (options.room.goal) {
    if (!inside(*options.room.goal)) {
      throw common::InputError(fmt::format("--goal {:g},{:g} is outside the boundary {:g},{:g},{:g},{:g}",
                                           options.room.goal->x_m, options.room.goal->y_m, spec.boundary.x_start_m,
                                           spec.boundary.x_end_m, spec.boundary.y_start_m, spec.boundary.y_end_m));
    }
  }
  for (const Point &p : options.room.waypoints) {
    if (!inside(p)) throw common::InputError(fmt::format("waypoint {:g},{:g} is outside the boundary", p.x_m, p.y_m));
  }
  RunOptions run_options;
  run_options.sensor = options.sensor;
  run_options.model = options.model;
  run_options.range_model = options.range_model;
  run_options.max_steps = options.max_steps;
  robot::ControllerOptions controller = controller_options(run_options, maze::Maze(1, 1), profile);
  controller.motion.max_steps = options.max_steps.value_or(std::int64_t{2'000'000});
  robot::RoomOptions room = options.room;
  room.start = start;
  room.stop_distance_m = std::max(room.stop_distance_m, profile.body_radius_m + 0.08);
  room.body_radius_m = profile.body_radius_m;
  const mapping::SensorModel model(options.sensor);
  sensing::RoomMap map(spec, model);
  if (!options.out_dir.empty()) {
    prepare_output_dir(options.out_dir);
    refuse_outputs_over_inputs(options.out_dir, {options.world});
  }
  maze::sim::SimulationOptions sim = options.simulation;
  sim.start = maze::sim::Pose{start_pose.x_m, start_pose.y_m, start_pose.yaw_rad};
  // The truth at the map's resolution, over the map's extent (a --resolution that does not
  // divide the boundary reaches past it by less than a cell).
  maze::Arena on_grid = arena;
  on_grid.x_max_m = spec.boundary.x_end_m;
  on_grid.y_max_m = spec.boundary.y_end_m;
  on_grid.starts = {start_pose};
  const maze::ArenaTruth truth = maze::rasterise_arena(on_grid, spec.cells_x, spec.cells_y, profile.body_radius_m);
  webots::embedded::Simulation simulation(arena, profile, sim);

  // ---- the run ----
  const double threshold = threshold_of(options);
  std::vector<double> times = options.snapshots_at_s;
  std::sort(times.begin(), times.end());
  std::size_t next_time = 0;
  std::vector<std::int64_t> steps = options.snapshot_steps;
  std::sort(steps.begin(), steps.end());
  std::size_t next_step = 0;
  std::string trace = "t,x,y,theta";
  if (options.model.kind == sensing::ModelKind::bump) trace += ",bump_right,bump_left,bump_front";
  if (options.model.kind == sensing::ModelKind::depth) {
    for (int n = 1; n <= sensing::kLogDepthRays; ++n) trace += fmt::format(",depth_{}", n);
  }
  trace += '\n';
  const auto snapshot = [&](const robot::RoomController &c, const std::string &when) {
    if (options.quiet) return;
    out << fmt::format("--- {}: step {}, {:.1f} s, at ({:.2f}, {:.2f}) ---\n", when, c.steps(), c.time_s(),
                       c.position().x_m, c.position().y_m);
    out << ascii_map(c, threshold);
    if (options.room.strategy == robot::RoomStrategy::wavefront && !c.wave().empty()) {
      out << "wavefront (obstacles 1, goal 2):\n" << wave_numbers(c.map(), c.wave());
    }
    out << '\n';
  };
  const auto on_step = [&](const robot::RoomController &c) {
    const sensing::LogStep &s = c.senses().log_step();
    std::string line = fmt::format("{},{},{},{}", s.t, s.x_m, s.y_m, s.theta_rad);
    if (options.model.kind == sensing::ModelKind::bump) {
      line += fmt::format(",{},{},{}", s.bump_right ? 1 : 0, s.bump_left ? 1 : 0, s.bump_front ? 1 : 0);
    }
    if (options.model.kind == sensing::ModelKind::depth) {
      for (const double d : s.depth_m) line += fmt::format(",{}", d);
    }
    trace += line;
    trace += '\n';
    while (next_time < times.size() && c.time_s() >= times[next_time] - 1e-9) {
      snapshot(c, fmt::format("t = {:g} s", times[next_time]));
      ++next_time;
    }
    while (next_step < steps.size() && c.steps() >= steps[next_step]) {
      snapshot(c, fmt::format("step {}", steps[next_step]));
      ++next_step;
    }
  };
  robot::RoomController controller_loop(simulation.robot(), controller, room, map, on_step);
  RoomSummary summary;
  summary.ending = controller_loop.run();
  summary.message = controller_loop.message();
  summary.steps = controller_loop.steps();
  summary.sim_time_s = controller_loop.time_s();
  summary.cells_x = spec.cells_x;
  summary.cells_y = spec.cells_y;
  summary.cell_m = spec.cell_m;

  // ---- the score against the truth ----
  summary.cells_total = map.size();
  for (std::size_t n = 0; n < map.size(); ++n) {
    const bool says_occupied = map.log_odds_at(n) >= threshold;
    const bool right = says_occupied == (truth.occupied[n] != 0);
    summary.cells_right += right ? 1 : 0;
    if (!map.unobserved_at(n)) {
      ++summary.observed_cells;
      summary.observed_cells_right += right ? 1 : 0;
    }
  }
  std::size_t first_left = map.size();
  for (std::size_t n = 0; n < map.size(); ++n) {
    if (truth.reachable[n] == 0) continue;
    ++summary.reachable_free;
    if (!map.unobserved_at(n)) {
      ++summary.reachable_free_observed;
    } else if (first_left == map.size()) {
      first_left = n;
    }
  }
  const bool all_seen = summary.reachable_free_observed == summary.reachable_free;
  if (options.room.strategy == robot::RoomStrategy::frontier && summary.ending == robot::RoomEnding::incomplete &&
      all_seen) {
    // What the robot could not observe lies in obstacles or out of reach: the free space is mapped.
    summary.ending = robot::RoomEnding::done;
    summary.message += fmt::format(", none of them reachable free space: every one of the {} reachable free cells "
                                   "is observed", summary.reachable_free);
  }
  if (options.room.strategy == robot::RoomStrategy::frontier && summary.ending == robot::RoomEnding::done &&
      !all_seen) {
    // The controller found no frontier, yet reachable free space is unobserved: not done.
    const Point p = map.centre_of(map.cell_of_index(first_left));
    summary.ending = robot::RoomEnding::incomplete;
    summary.message = fmt::format("{} of {} reachable free cells never observed (the first at {:.2f}, {:.2f})",
                                  summary.reachable_free - summary.reachable_free_observed, summary.reachable_free,
                                  p.x_m, p.y_m);
  }
  summary.wall_time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();

  if (!options.quiet) {
    for (; next_time < times.size(); ++next_time) {
      out << fmt::format("--- t = {:g} s: the run ended at {:.1f} s ---\n\n", times[next_time], summary.sim_time_s);
    }
    for (; next_step < steps.size(); ++next_step) {
      out << fmt::format("--- step {}: the run ended at step {} ---\n\n", steps[next_step], summary.steps);
    }
    snapshot(controller_loop, "end");
    out << "trajectory (x, y every second):\n";
    const auto &traj = controller_loop.trajectory();
    const int time_step = simulation.basic_time_step_ms();
    const std::size_t every = static_cast<std::size_t>(std::max(1, 1000 / std::max(1, time_step)));
    for (std::size_t k = 0; k < traj.size(); k += every) {
      out << fmt::format("{}({:.2f}, {:.2f})", k == 0 ? "" : " ", traj[k].x_m, traj[k].y_m);
    }
    out << "\n\nthresholded map (1: log-odds >= " << fmt::format("{:g}", threshold) << "):\n"
        << binary_map(map, threshold) << '\n';
  }
  const std::string summary_text = fmt::format(
      "world         {}\nstrategy      {}\nrobot         {} ({} set-up)\ngrid          {} x {} cells of {:g} m over "
      "{:g},{:g},{:g},{:g}\nsteps         {}\nsim time      {:.2f} s\nending       {}: {}\ncells right   {} of {} "
      "({:.1f} %); observed {} of {}\nobserved      {:.2f} % of the reachable free area ({} of {} cells)\nwall time   "
      "  {:.0f} ms\n",
      options.world, robot::to_string(options.room.strategy), profile.name, setup.name, spec.cells_x, spec.cells_y,
      spec.cell_m, spec.boundary.x_start_m, spec.boundary.x_end_m, spec.boundary.y_start_m, spec.boundary.y_end_m,
      summary.steps, summary.sim_time_s, robot::to_string(summary.ending), summary.message, summary.cells_right,
      summary.cells_total, 100.0 * static_cast<double>(summary.cells_right) / static_cast<double>(summary.cells_total),
      summary.observed_cells_right, summary.observed_cells, 100.0 * summary.observed_share(),
      summary.reachable_free_observed, summary.reachable_free, summary.wall_time_ms);
  out << summary_text;
  if (!options.out_dir.empty()) {
    nlohmann::ordered_json j;
    j["world"] = options.world;
    j["strategy"] = robot::to_string(options.room.strategy);
    j["robot"] = profile.name;
    j["model"] = setup.name;
    j["cells_x"] = spec.cells_x;
    j["cells_y"] = spec.cells_y;
    j["cell_m"] = spec.cell_m;
    j["boundary_m"] = {spec.boundary.x_start_m, spec.boundary.x_end_m, spec.boundary.y_start_m, spec.boundary.y_end_m};
    j["steps"] = summary.steps;
    j["sim_time_s"] = summary.sim_time_s;
    j["ending"] = robot::to_string(summary.ending);
    j["message"] = summary.message;
    j["cells_right"] = summary.cells_right;
    j["cells_total"] = summary.cells_total;
    j["observed_cells"] = summary.observed_cells;
    j["observed_cells_right"] = summary.observed_cells_right;
    j["reachable_free"] = summary.reachable_free;
    j["reachable_free_observed"] = summary.reachable_free_observed;
    const std::string json = j.dump(2) + "\n";
    write_outputs(options.out_dir, map, trace, json, threshold);
  }
  return summary;
}

}  // namespace app
