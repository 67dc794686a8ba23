// A robot in a room, in the embedded simulator (app/run/metric/run.hpp).

#include "app/run/metric/run.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <variant>
#include <numbers>
#include <ostream>

#include <fmt/format.h>

#include "app/run/metric/map_text.hpp"
#include "app/run/metric/run_report.hpp"
#include "app/run/metric/coverage_clock.hpp"
#include "app/run/metric/evaluation.hpp"
#include "app/run/profile_json.hpp"
#include "app/run/run_frame.hpp"
#include "app/run/run.hpp"
#include "common/compass.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "maze/sim/profile.hpp"
#include "maze/world/geometry.hpp"
#include "maze/world/truth_raster.hpp"
#include "maze/world/world.hpp"
#include "maze/world/maze.hpp"
#include "plan/metric/wavefront.hpp"

namespace app {
namespace {

using mapping::Point;
using sensing::MetricCell;

constexpr double kDeg = std::numbers::pi / 180.0;

bool is_log_set_up(sensing::ModelKind k) {
  return k == sensing::ModelKind::bump || k == sensing::ModelKind::depth;
}

double threshold_of(const RunOptions &o) {
  return o.threshold.value_or(is_log_set_up(o.model.kind) ? -0.5 : 0.0);
}

// --depth-reading and --depth-origin: the depth rays leave one origin in the robot's frame
// and, axial, report the depth along the heading (a depth camera, the homework's simulator).
// Another set-up's range sensors keep their own (the command warns that the options do nothing).
void with_depth_convention(maze::sim::RobotProfile &profile, const RunOptions &options) {
  if (options.metres.depth_reading == sensing::DepthReading::range && !options.metres.depth_origin) return;
  if (options.model.kind != sensing::ModelKind::depth) return;
  const mapping::Point o = options.metres.depth_origin.value_or(mapping::Point{});
  if (!(std::isfinite(o.x_m) && std::isfinite(o.y_m) && std::hypot(o.x_m, o.y_m) <= profile.body_radius_m)) {
    throw common::InputError(fmt::format("--depth-origin must lie on the robot, within its {:g} m radius (got {:g},{:g})",
                                         profile.body_radius_m, o.x_m, o.y_m));
  }
  for (maze::sim::DistanceSensorSpec &d : profile.distance_sensors) {
    d.origin_m = std::array<double, 2>{o.x_m, o.y_m};
    d.axial = options.metres.depth_reading == sensing::DepthReading::axial;
  }
  maze::sim::validate_profile(profile);
}

// The set-up's robot (--robot, else the set-up's own); refused when it lacks the set-up's devices.
maze::sim::RobotProfile robot_for(const sensing::SetUp &setup, const RunOptions &options) {
  const std::string robot_name = options.robot.empty() ? std::string(setup.default_robot) : options.robot;
  maze::sim::RobotProfile profile = resolve_robot(robot_name);
  if (!has_devices(profile, setup)) {
    throw common::InputError(fmt::format("--robot {} has no {}, which --model {} reads", profile.name, setup.devices(),
                                         setup.name));
  }
  with_depth_convention(profile, options);
  return profile;
}

// The arena's start, moved by --start and turned by --start-yaw.
maze::ArenaPose start_pose_of(const maze::Arena &arena, const RunOptions &options) {
  maze::ArenaPose start_pose = arena.start();
  if (options.metres.start) {
    start_pose.x_m = options.metres.start->x_m;
    start_pose.y_m = options.metres.start->y_m;
  }
  if (options.metres.start_yaw_deg) start_pose.yaw_rad = *options.metres.start_yaw_deg * kDeg;
  return start_pose;
}

// The map's grid over the arena's extent: --cells, else --resolution (0.1 m); checked.
sensing::MetricGridSpec grid_of(const maze::Arena &arena, const RunOptions &options) {
  const sensing::MetricBoundary boundary{arena.x_min_m, arena.x_max_m, arena.y_min_m, arena.y_max_m};
  const sensing::MetricGridSpec spec =
      options.metres.cells_x ? sensing::metric_grid_from_cells(boundary, *options.metres.cells_x, *options.metres.cells_y)
                      : sensing::metric_grid_from_resolution(boundary, options.metres.resolution_m.value_or(0.1));
  sensing::validate(spec);
  return spec;
}

// Refuses, in this order: a start outside the grid, a start touching a solid, a goal outside
// the grid, a waypoint outside it.
void check_places(const maze::Arena &arena, const RunOptions &options, const sensing::MetricGridSpec &spec,
                  const maze::ArenaPose &start_pose, double body_radius_m) {
  const auto inside = [&spec](Point p) {
    return p.x_m >= spec.boundary.x_start_m && p.x_m < spec.boundary.x_end_m && p.y_m >= spec.boundary.y_start_m &&
           p.y_m < spec.boundary.y_end_m;
  };
  const Point start{start_pose.x_m, start_pose.y_m};
  if (!inside(start)) {
    throw common::InputError(fmt::format("the start ({:g}, {:g}) is outside the boundary {:g},{:g},{:g},{:g}", start.x_m,
                                         start.y_m, spec.boundary.x_start_m, spec.boundary.x_end_m,
                                         spec.boundary.y_start_m, spec.boundary.y_end_m));
  }
  maze::Arena placed = arena;
  placed.starts = {start_pose};
  if (const maze::ArenaCheck bad = maze::check_starts_clear(placed, body_radius_m)) throw *bad;
  if (options.metres.controller.goal && !inside(*options.metres.controller.goal)) {
    throw common::InputError(fmt::format("--goal {:g},{:g} is outside the boundary {:g},{:g},{:g},{:g}",
                                         options.metres.controller.goal->x_m, options.metres.controller.goal->y_m, spec.boundary.x_start_m,
                                         spec.boundary.x_end_m, spec.boundary.y_start_m, spec.boundary.y_end_m));
  }
  for (const Point &p : options.metres.controller.waypoints) {
    if (!inside(p)) throw common::InputError(fmt::format("waypoint {:g},{:g} is outside the boundary", p.x_m, p.y_m));
  }
}

// The controller's options: the robot's description (the scan filter's range noise --noise,
// else the lidar's data sheet), the set-up, at most --max-steps (2 000 000) steps.
robot::ControllerOptions room_controller_options(const RunOptions &options,
                                                 const maze::sim::RobotProfile &profile) {
  robot::ControllerOptions controller = robot_description(profile, options.simulation.noise);
  controller.sensor = options.sensor;
  controller.model = options.model;
  controller.sensing.range_model = options.range_model;
  controller.motion.max_steps = options.max_steps.value_or(std::int64_t{2'000'000});
  return controller;
}

// The strategy's options, from the start, stopping no nearer than the body's radius + 8 cm:
// the run's strategy, time limit (none: 0) and seed, and its own options as the run uses
// them: wavefront without --goal heads for the world's first goal, when its file gives one.
robot::MetricOptions room_options_of(const RunOptions &options, const maze::Arena &arena, Point start,
                                   double body_radius_m) {
  robot::MetricOptions room = options.metres.controller;
  room.strategy = options.strategy;
  room.time_limit_s = options.time_limit_s.value_or(0.0);
  room.seed = options.simulation.seed;
  if (room.strategy == explore::StrategyKind::wavefront && !room.goal && !arena.goals.empty()) {
    room.goal = Point{arena.goals.front().x_m, arena.goals.front().y_m};
  }
  room.start = start;
  room.stop_distance_m = std::max(room.stop_distance_m, body_radius_m + 0.08);
  room.body_radius_m = body_radius_m;
  return room;
}

// The truth at the map's resolution, over the map's extent (a --resolution that does not
// divide the boundary reaches past it by less than a cell): reachable where a body clear of
// the occupied cells can go, the frontier planner's rule on a perfect map.
maze::TruthRaster truth_on_grid(const maze::Arena &arena, const sensing::MetricGridSpec &spec,
                               const maze::ArenaPose &start_pose, double body_radius_m) {
  maze::Arena on_grid = arena;
  on_grid.x_max_m = spec.boundary.x_end_m;
  on_grid.y_max_m = spec.boundary.y_end_m;
  on_grid.starts = {start_pose};
  return maze::rasterise_truth(on_grid, spec.cells_x, spec.cells_y, body_radius_m,
                               maze::TruthClearance::to_occupied_cells);
}

// What the run prints as it goes: the snapshots (the map, with the wave for wavefront) at the
// asked simulated times and control steps, printed unless quiet and told to the observer.
class RoomLog {
 public:
  RoomLog(const RunOptions &options, double threshold, std::ostream &out)
      : options_(options), threshold_(threshold), out_(out), times_(options.metres.snapshots_at_s),
        steps_(options.metres.snapshot_steps) {
    std::sort(times_.begin(), times_.end());
    std::sort(steps_.begin(), steps_.end());
  }

  // Each control step: the snapshots due by its time, then by its step, printed; their
  // files' names ("snapshots/t15s", "snapshots/step50") into `names`.
  void on_step(const robot::MetricController &c, std::vector<std::string> &names) {
    while (next_time_ < times_.size() && c.time_s() >= times_[next_time_] - 1e-9) {
      snapshot(c, fmt::format("t = {:g} s", times_[next_time_]));
      names.push_back(fmt::format("snapshots/t{:g}s", times_[next_time_]));
      ++next_time_;
    }
    while (next_step_ < steps_.size() && c.steps() >= steps_[next_step_]) {
      snapshot(c, fmt::format("step {}", steps_[next_step_]));
      names.push_back(fmt::format("snapshots/step{}", steps_[next_step_]));
      ++next_step_;
    }
  }

  // The map now (and the wave), headed by `when`; nothing when quiet.
  void snapshot(const robot::MetricController &c, const std::string &when) const {
    if (options_.output.quiet) return;
    out_ << fmt::format("--- {}: step {}, {:.1f} s, at ({:.2f}, {:.2f}) ---\n", when, c.steps(), c.time_s(),
                        c.position().x_m, c.position().y_m);
    out_ << metric_ascii_map(c, threshold_);
    if (options_.strategy == explore::StrategyKind::wavefront && !c.wave().empty()) {
      out_ << "wavefront (obstacles 1, goal 2):\n" << metric_wave_numbers(c.map(), c.wave());
    }
    out_ << '\n' << std::flush;  // seen as the run goes, also through a pipe or in a file
  }

  // After the run: says of each snapshot it never reached that the run ended first.
  void say_missed(const MetricRunSummary &summary) {
    for (; next_time_ < times_.size(); ++next_time_) {
      out_ << fmt::format("--- t = {:g} s: the run ended at {:.1f} s ---\n\n", times_[next_time_], summary.sim_time_s);
    }
    for (; next_step_ < steps_.size(); ++next_step_) {
      out_ << fmt::format("--- step {}: the run ended at step {} ---\n\n", steps_[next_step_], summary.steps);
    }
  }

 private:
  const RunOptions &options_;
  double threshold_;
  std::ostream &out_;
  std::vector<double> times_;  // sorted
  std::size_t next_time_ = 0;
  std::vector<std::int64_t> steps_;  // sorted
  std::size_t next_step_ = 0;
};

// What the controller says of its run, on the grid `spec`.
MetricRunSummary summary_of(const robot::MetricController &c, robot::MetricEnding ending, const sensing::MetricGridSpec &spec,
                            bool frontier) {
  MetricRunSummary summary;
  summary.ending = ending;
  summary.message = c.message();
  summary.steps = c.steps();
  summary.sim_time_s = c.time_s();
  summary.cells_x = spec.cells_x;
  summary.cells_y = spec.cells_y;
  summary.cell_m = spec.cell_m;
  if (frontier) summary.frontier = MetricRunSummary::FrontierEnd{c.message(), c.frontier_left(), c.frontier_set_aside()};
  if (c.body_observes()) summary.sweep = MetricRunSummary::BodySweep{c.sweep_legs(), c.probe_legs(), c.map().body_observed()};
  return summary;
}

// After the run (not quiet): the missed snapshots, the map at the end, the trajectory every
// second of simulated time and the thresholded map.
void print_end(std::ostream &out, RoomLog &log, const robot::MetricController &c, int time_step_ms,
               double threshold, const MetricRunSummary &summary) {
  log.say_missed(summary);
  log.snapshot(c, "end");
  out << "trajectory (x, y every second):\n";
  const auto &traj = c.trajectory();
  const std::size_t every = static_cast<std::size_t>(std::max(1, 1000 / std::max(1, time_step_ms)));
  for (std::size_t k = 0; k < traj.size(); k += every) {
    out << fmt::format("{}({:.2f}, {:.2f})", k == 0 ? "" : " ", traj[k].x_m, traj[k].y_m);
  }
  out << "\n\nthresholded map (1: log-odds >= " << fmt::format("{:g}", threshold) << "):\n"
      << metric_binary_map(c.map(), threshold) << '\n';
}

}  // namespace

int metric_run_exit_status(const MetricRunSummary &s) {
  if (s.interrupted) return common::interrupted_exit_status();
  switch (s.ending) {
    case robot::MetricEnding::done:
    case robot::MetricEnding::goal_reached:
    case robot::MetricEnding::arrived:
    case robot::MetricEnding::time_up: return 0;
    default: return 1;
  }
}

MetricRunSummary run_metric_world(const maze::World &world, const RunOptions &options, std::ostream &out,
                     std::chrono::steady_clock::time_point started, robot::StopPoll interrupted,
                     Report *report, RunObserver *observer, int progress_fd) {
  return run_metric_arena(world.geometry(), options, out, started, interrupted, report, observer, progress_fd);
}

MetricRunSummary run_metric_arena(const maze::Arena &arena, const RunOptions &options, std::ostream &out,
                        std::chrono::steady_clock::time_point started, robot::StopPoll interrupted,
                        Report *report_out, RunObserver *observer, int progress_fd) {
  // ---- everything checked before anything runs ----
  const sensing::SetUp &setup = sensing::setup(options.model.kind);
  const maze::sim::RobotProfile profile = robot_for(setup, options);
  const maze::ArenaPose start_pose = start_pose_of(arena, options);
  const robot::MetricOptions room =
      room_options_of(options, arena, {start_pose.x_m, start_pose.y_m}, profile.body_radius_m);
  robot::validate(room);
  const sensing::MetricGridSpec spec = grid_of(arena, options);
  check_places(arena, options, spec, start_pose, profile.body_radius_m);
  const robot::ControllerOptions controller = room_controller_options(options, profile);
  const mapping::SensorModel model(options.sensor);
  sensing::MetricMap map(spec, model);
  const double threshold = threshold_of(options);
  maze::sim::SimulationOptions sim = options.simulation;
  sim.start = maze::sim::Pose{start_pose.x_m, start_pose.y_m, start_pose.yaw_rad};
  const maze::TruthRaster truth = truth_on_grid(arena, spec, start_pose, profile.body_radius_m);
  // Free geometry: on SolidGeometry, a maze's geometry too (run_metric_world), never on a WallGrid.
  RunFrame frame(maze::world_of(arena), profile, sim, observer, progress_fd);
  webots::embedded::Simulation &simulation = frame.simulation();
  const MetresRunStart metres{setup, room, arena, map, start_pose, truth, threshold};
  frame.start(RunStart{options, simulation.robot(), nullptr, &metres});

  // ---- the run ----
  RoomLog log(options, threshold, out);
  CoverageClock clock(map, truth, *sim.start);
  robot::MetricController controller_loop(simulation.robot(), controller, room, map,
                                          [&](const robot::MetricController &c) {
                                            RunStep step = step_at(c.steps(), c.time_s(), simulation.pose());
                                            step.metres = &c;
                                            clock.on_step(c.steps(), simulation.pose());
                                            log.on_step(c, step.snapshots);
                                            frame.step(step);
                                          },
                                          interrupted);
  MetricRunSummary summary = summary_of(controller_loop, controller_loop.run(), spec,
                                        options.strategy == explore::StrategyKind::frontier);
  summary.path_length_m = clock.path_length_m();
  summary.coverage_final_step = clock.coverage_final_step();
  if (summary.ending == robot::MetricEnding::stopped && interrupted != nullptr && interrupted()) {
    summary.interrupted = true;
    summary.message = "interrupted by " + common::interrupt_name();
  }

  // ---- the score against the truth ----
  const std::size_t first_left = score_metric_map(map, truth, threshold, summary);
  if (options.strategy == explore::StrategyKind::frontier) settle_frontier_ending(map, first_left, summary);
  summary.wall_time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();

  const Report report = metric_run_report(options, profile.name, setup, spec, summary);
  const MetresRunEnd ended{controller_loop, truth, report};
  frame.end(RunEnd{options, nullptr, &ended}, out, [&] {
    if (!options.output.quiet) print_end(out, log, controller_loop, simulation.basic_time_step_ms(), threshold, summary);
    if (!options.output.quiet) out << '\n';
    out << format_summary(report);
  });
  frame.close(out);
  if (report_out != nullptr) *report_out = report;
  return summary;
}

}  // namespace app
