// A robot in a room, in the embedded simulator (app/room/room_run.hpp).

#include "app/room/room_run.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <variant>
#include <filesystem>
#include <numbers>
#include <ostream>

#include <fmt/format.h>

#include "app/report/output_dir.hpp"
#include "app/report/outputs.hpp"
#include "app/report/truth_picture.hpp"
#include "app/room/room_outputs.hpp"
#include "app/room/room_pictures.hpp"
#include "app/room/room_replay.hpp"
#include "app/room/room_report.hpp"
#include "app/room/room_score.hpp"
#include "app/run/profile_json.hpp"
#include "app/run/run.hpp"
#include "common/compass.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "maze/sim/profile.hpp"
#include "maze/world/arena.hpp"
#include "maze/world/truth_raster.hpp"
#include "maze/world/world.hpp"
#include "maze/world/maze.hpp"
#include "plan/metric_wavefront.hpp"

namespace app {
namespace {

using mapping::Point;
using sensing::MetricCell;

constexpr double kDeg = std::numbers::pi / 180.0;

bool is_log_set_up(sensing::ModelKind k) {
  return k == sensing::ModelKind::bump || k == sensing::ModelKind::depth;
}

double threshold_of(const RoomRunOptions &o) {
  return o.threshold.value_or(is_log_set_up(o.model.kind) ? -0.5 : 0.0);
}

// --depth-reading and --depth-origin: the depth rays leave one origin in the robot's frame
// and, axial, report the depth along the heading (a depth camera, the homework's simulator).
// Another set-up's range sensors keep their own (the command warns that the options do nothing).
void with_depth_convention(maze::sim::RobotProfile &profile, const RoomRunOptions &options) {
  if (options.depth_reading == sensing::DepthReading::range && !options.depth_origin) return;
  if (options.model.kind != sensing::ModelKind::depth) return;
  const mapping::Point o = options.depth_origin.value_or(mapping::Point{});
  if (!(std::isfinite(o.x_m) && std::isfinite(o.y_m) && std::hypot(o.x_m, o.y_m) <= profile.body_radius_m)) {
    throw common::InputError(fmt::format("--depth-origin must lie on the robot, within its {:g} m radius (got {:g},{:g})",
                                         profile.body_radius_m, o.x_m, o.y_m));
  }
  for (maze::sim::DistanceSensorSpec &d : profile.distance_sensors) {
    d.origin_m = std::array<double, 2>{o.x_m, o.y_m};
    d.axial = options.depth_reading == sensing::DepthReading::axial;
  }
  maze::sim::validate_profile(profile);
}

// The set-up's robot (--robot, else the set-up's own); refused when it lacks the set-up's devices.
maze::sim::RobotProfile robot_for(const sensing::SetUp &setup, const RoomRunOptions &options) {
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
maze::ArenaPose start_pose_of(const maze::Arena &arena, const RoomRunOptions &options) {
  maze::ArenaPose start_pose = arena.start();
  if (options.start) {
    start_pose.x_m = options.start->x_m;
    start_pose.y_m = options.start->y_m;
  }
  if (options.start_yaw_deg) start_pose.yaw_rad = *options.start_yaw_deg * kDeg;
  return start_pose;
}

// The map's grid over the arena's extent: --cells, else --resolution (0.1 m); checked.
sensing::MetricGridSpec grid_of(const maze::Arena &arena, const RoomRunOptions &options) {
  const sensing::MetricBoundary boundary{arena.x_min_m, arena.x_max_m, arena.y_min_m, arena.y_max_m};
  const sensing::MetricGridSpec spec =
      options.cells_x ? sensing::metric_grid_from_cells(boundary, *options.cells_x, *options.cells_y)
                      : sensing::metric_grid_from_resolution(boundary, options.resolution_m.value_or(0.1));
  sensing::validate(spec);
  return spec;
}

// Refuses, in this order: a start outside the grid, a start touching a solid, a goal outside
// the grid, a waypoint outside it.
void check_places(const maze::Arena &arena, const RoomRunOptions &options, const sensing::MetricGridSpec &spec,
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
  if (options.room.goal && !inside(*options.room.goal)) {
    throw common::InputError(fmt::format("--goal {:g},{:g} is outside the boundary {:g},{:g},{:g},{:g}",
                                         options.room.goal->x_m, options.room.goal->y_m, spec.boundary.x_start_m,
                                         spec.boundary.x_end_m, spec.boundary.y_start_m, spec.boundary.y_end_m));
  }
  for (const Point &p : options.room.waypoints) {
    if (!inside(p)) throw common::InputError(fmt::format("waypoint {:g},{:g} is outside the boundary", p.x_m, p.y_m));
  }
}

// The controller's options: the robot's description (the room command has no --noise: the
// scan filter takes the lidar's data sheet), the set-up, at most --max-steps (2 000 000) steps.
robot::ControllerOptions room_controller_options(const RoomRunOptions &options,
                                                 const maze::sim::RobotProfile &profile) {
  robot::ControllerOptions controller = robot_description(profile, std::nullopt);
  controller.sensor = options.sensor;
  controller.model = options.model;
  controller.sensing.range_model = options.range_model;
  controller.motion.max_steps = options.max_steps.value_or(std::int64_t{2'000'000});
  return controller;
}

// The strategy's options, from the start, stopping no nearer than the body's radius + 8 cm.
// The room options as the run uses them: wavefront without --goal heads for the world's
// first goal, when its file gives one.
robot::MetricOptions room_options_of(const RoomRunOptions &options, const maze::Arena &arena, Point start,
                                   double body_radius_m) {
  robot::MetricOptions room = options.room;
  if (room.strategy == robot::MetricStrategy::wavefront && !room.goal && !arena.goals.empty()) {
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

// What the run prints and records as it goes: trace.csv's text, and the snapshots (the map,
// with the wave for wavefront) at the asked simulated times and control steps: printed unless
// quiet, drawn (snapshots/NAME.png, NAME_wave.png) with --out.
class RoomLog {
 public:
  RoomLog(const RoomRunOptions &options, double threshold, const MapTones &tones, RoomPictureMarks marks,
          std::ostream &out)
      : options_(options), threshold_(threshold), tones_(tones), marks_(std::move(marks)), out_(out),
        times_(options.snapshots_at_s), steps_(options.snapshot_steps) {
    std::sort(times_.begin(), times_.end());
    std::sort(steps_.begin(), steps_.end());
    trace_ = "t,x,y,theta";
    if (options.model.kind == sensing::ModelKind::bump) trace_ += ",bump_right,bump_left,bump_front";
    if (options.model.kind == sensing::ModelKind::depth) {
      for (int n = 1; n <= sensing::kLogDepthRays; ++n) trace_ += fmt::format(",depth_{}", n);
    }
    trace_ += '\n';
  }

  // Each control step: its trace line, then the snapshots due by its time, then by its step.
  void on_step(const robot::MetricController &c) {
    const sensing::LogStep &s = c.senses().log_step();
    std::string line = fmt::format("{},{},{},{}", s.t, s.x_m, s.y_m, s.theta_rad);
    if (options_.model.kind == sensing::ModelKind::bump) {
      line += fmt::format(",{},{},{}", s.bump_right ? 1 : 0, s.bump_left ? 1 : 0, s.bump_front ? 1 : 0);
    }
    if (options_.model.kind == sensing::ModelKind::depth) {
      for (const double d : s.depth_m) line += fmt::format(",{}", d);
    }
    trace_ += line;
    trace_ += '\n';
    while (next_time_ < times_.size() && c.time_s() >= times_[next_time_] - 1e-9) {
      snapshot(c, fmt::format("t = {:g} s", times_[next_time_]));
      const std::string name = fmt::format("snapshots/t{:g}s", times_[next_time_]);
      draw(c, name, name + "_wave");
      ++next_time_;
    }
    while (next_step_ < steps_.size() && c.steps() >= steps_[next_step_]) {
      snapshot(c, fmt::format("step {}", steps_[next_step_]));
      const std::string name = fmt::format("snapshots/step{}", steps_[next_step_]);
      draw(c, name, name + "_wave");
      ++next_step_;
    }
  }

  // With --out: the map's picture now as MAP.png (and the wave's, when there is one, as
  // WAVE.png), kept until the run's files are written.
  void draw(const robot::MetricController &c, const std::string &map, const std::string &wave) {
    if (options_.out_dir.empty()) return;
    RoomPictureMarks marks = marks_;
    marks.when = fmt::format("step {}, {:.1f} s", c.steps(), c.time_s());
    pictures_.push_back({map + ".png", room_map_picture(c, tones_, marks)});
    if (options_.room.strategy == robot::MetricStrategy::wavefront && !c.wave().empty()) {
      pictures_.push_back({wave + ".png", room_wave_picture(c, marks)});
    }
  }

  // The map now (and the wave), headed by `when`; nothing when quiet.
  void snapshot(const robot::MetricController &c, const std::string &when) const {
    if (options_.quiet) return;
    out_ << fmt::format("--- {}: step {}, {:.1f} s, at ({:.2f}, {:.2f}) ---\n", when, c.steps(), c.time_s(),
                        c.position().x_m, c.position().y_m);
    out_ << room_ascii_map(c, threshold_);
    if (options_.room.strategy == robot::MetricStrategy::wavefront && !c.wave().empty()) {
      out_ << "wavefront (obstacles 1, goal 2):\n" << room_wave_numbers(c.map(), c.wave());
    }
    out_ << '\n' << std::flush;  // seen as the run goes, also through a pipe or in a file
  }

  // After the run: says of each snapshot it never reached that the run ended first.
  void say_missed(const RoomSummary &summary) {
    for (; next_time_ < times_.size(); ++next_time_) {
      out_ << fmt::format("--- t = {:g} s: the run ended at {:.1f} s ---\n\n", times_[next_time_], summary.sim_time_s);
    }
    for (; next_step_ < steps_.size(); ++next_step_) {
      out_ << fmt::format("--- step {}: the run ended at step {} ---\n\n", steps_[next_step_], summary.steps);
    }
  }

  const std::string &trace() const { return trace_; }
  const std::vector<RoomFile> &pictures() const { return pictures_; }

 private:
  const RoomRunOptions &options_;
  double threshold_;
  const MapTones &tones_;
  RoomPictureMarks marks_;
  std::vector<RoomFile> pictures_;  // (name in the output folder, bytes)
  std::ostream &out_;
  std::vector<double> times_;  // sorted
  std::size_t next_time_ = 0;
  std::vector<std::int64_t> steps_;  // sorted
  std::size_t next_step_ = 0;
  std::string trace_;
};

// What the pictures mark besides the controller's state: the start, the goal, the arena's
// boundary, the landmarks, the caption.
RoomPictureMarks picture_marks(const RoomRunOptions &options, const sensing::SetUp &setup,
                               const robot::MetricOptions &room, const maze::Arena &arena,
                               std::vector<LandmarkMark> landmarks) {
  RoomPictureMarks marks;
  marks.start = room.start;
  marks.goal = room.goal;
  marks.boundary = PlainGridBounds{arena.x_min_m, arena.x_max_m, arena.y_min_m, arena.y_max_m};
  marks.landmarks = std::move(landmarks);
  marks.caption = fmt::format("room {}, {}, --model {}", std::filesystem::path(options.world).filename().string(),
                              robot::to_string(room.strategy), setup.name);
  return marks;
}

// What replay.html shows besides the frames: the pictures' caption, the summary's lines.
RoomReplayText replay_text(const RoomRunOptions &options, const RoomPictureMarks &marks, const robot::MetricOptions &room,
                           const Report &report) {
  RoomReplayText text;
  text.title = options.world;
  text.caption = marks.caption;
  text.goal = marks.goal;
  text.landmarks = marks.landmarks;
  text.boundary = marks.boundary;
  text.body_radius_m = room.body_radius_m;
  for (auto &[key, value] : summary_pairs(report)) {
    if (key != "wall_time_ms") text.summary.emplace_back(key, value);
  }
  return text;
}

// What the controller says of its run, on the grid `spec`.
RoomSummary summary_of(const robot::MetricController &c, robot::MetricEnding ending, const sensing::MetricGridSpec &spec) {
  RoomSummary summary;
  summary.ending = ending;
  summary.message = c.message();
  summary.steps = c.steps();
  summary.sim_time_s = c.time_s();
  summary.cells_x = spec.cells_x;
  summary.cells_y = spec.cells_y;
  summary.cell_m = spec.cell_m;
  if (c.body_observes()) summary.sweep = RoomSummary::BodySweep{c.sweep_legs(), c.probe_legs(), c.map().body_observed()};
  return summary;
}

// After the run (not quiet): the missed snapshots, the map at the end, the trajectory every
// second of simulated time and the thresholded map.
void print_end(std::ostream &out, RoomLog &log, const robot::MetricController &c, int time_step_ms,
               double threshold, const RoomSummary &summary) {
  log.say_missed(summary);
  log.snapshot(c, "end");
  out << "trajectory (x, y every second):\n";
  const auto &traj = c.trajectory();
  const std::size_t every = static_cast<std::size_t>(std::max(1, 1000 / std::max(1, time_step_ms)));
  for (std::size_t k = 0; k < traj.size(); k += every) {
    out << fmt::format("{}({:.2f}, {:.2f})", k == 0 ? "" : " ", traj[k].x_m, traj[k].y_m);
  }
  out << "\n\nthresholded map (1: log-odds >= " << fmt::format("{:g}", threshold) << "):\n"
      << room_binary_map(c.map(), threshold) << '\n';
}

}  // namespace

int room_exit_status(const RoomSummary &s) {
  if (s.interrupted) return common::interrupted_exit_status();
  switch (s.ending) {
    case robot::MetricEnding::done:
    case robot::MetricEnding::goal_reached:
    case robot::MetricEnding::arrived:
    case robot::MetricEnding::time_up: return 0;
    default: return 1;
  }
}

RoomSummary run_room(const maze::World &world, const RoomRunOptions &options, std::ostream &out,
                     std::chrono::steady_clock::time_point started, robot::MetricStopPoll interrupted,
                     Report *report) {
  return run_room_in(world.geometry(), options, out, started, interrupted, report);
}

RoomSummary run_room_in(const maze::Arena &arena, const RoomRunOptions &options, std::ostream &out,
                        std::chrono::steady_clock::time_point started, robot::MetricStopPoll interrupted,
                        Report *report_out) {
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
  if (!options.out_dir.empty()) {
    prepare_output_dir(options.out_dir);
    refuse_outputs_over_inputs(options.out_dir, room_output_names(),
                               {{"the world", options.world}, {"--robot", options.robot}});
  }
  maze::sim::SimulationOptions sim = options.simulation;
  sim.start = maze::sim::Pose{start_pose.x_m, start_pose.y_m, start_pose.yaw_rad};
  const maze::TruthRaster truth = truth_on_grid(arena, spec, start_pose, profile.body_radius_m);
  webots::embedded::Simulation simulation(arena, profile, sim);

  // ---- the run ----
  const double threshold = threshold_of(options);
  const MapTones tones = room_map_tones(map, sensing::probabilities_in_effect(setup, options.sensor), threshold);
  const RoomPictureMarks marks = picture_marks(options, setup, room, arena, landmark_marks(arena));
  RoomLog log(options, threshold, tones, marks, out);
  std::optional<RoomReplay> replay;
  if (!options.out_dir.empty()) replay.emplace(map, tones, ReplayPose{0, {start_pose.x_m, start_pose.y_m}, start_pose.yaw_rad});
  robot::MetricController controller_loop(simulation.robot(), controller, room, map,
                                          [&log, &replay](const robot::MetricController &c) {
                                          log.on_step(c);
                                          if (replay) replay->on_step(c);
                                        },
                                        interrupted);
  RoomSummary summary = summary_of(controller_loop, controller_loop.run(), spec);
  if (summary.ending == robot::MetricEnding::stopped && interrupted != nullptr && interrupted()) {
    summary.interrupted = true;
    summary.message = "interrupted by " + common::interrupt_name();
  }

  // ---- the score against the truth ----
  const std::size_t first_left = score_room_map(map, truth, threshold, summary);
  if (options.room.strategy == robot::MetricStrategy::frontier) settle_frontier_ending(map, first_left, summary);
  summary.wall_time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();

  if (!options.quiet) print_end(out, log, controller_loop, simulation.basic_time_step_ms(), threshold, summary);
  const Report report = room_report(options, profile.name, setup, spec, summary);
  if (!options.quiet) out << '\n';
  out << format_summary(report);
  if (!options.out_dir.empty()) {
    log.draw(controller_loop, "map", "wave");
    std::vector<RoomFile> files = log.pictures();
    const RoomTruthScores scores{report.text("cell_accuracy"), report.text("coverage")};
    files.push_back({"truth.png", room_truth_picture(controller_loop, truth, threshold, marks, scores)});
    replay->finish(controller_loop);
    if (std::optional<Replay> page = replay_html(replay->input(replay_text(options, marks, room, report)))) {
      files.push_back({"replay.html", std::move(page->html)});
    }
    write_room_outputs(options.out_dir, map, log.trace(), report_json(report).dump(2) + "\n", threshold, files);
  }
  if (report_out != nullptr) *report_out = report;
  return summary;
}

}  // namespace app
