#include "app/run/run.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "common/standard_streams.hpp"
#include "maze/world/maze.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/simulation.hpp"
#include "maze/world/world.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/walls.hpp"
#include "render/ascii_map.hpp"
#include "robot/progress_printer.hpp"
#include "app/run/plan_path.hpp"
#include "app/run/step_limit.hpp"
#include "app/run/profile_json.hpp"
#include "app/run/console_observers.hpp"
#include "app/run/run_frame.hpp"
#include "app/run/terminal.hpp"

namespace app {
namespace {

mapping::Cell to_mapping(maze::Cell c) { return {c.x, c.y}; }

// The robot's description as the controller gets it (like a URDF): where each bumper and
// range sensor sits and what it sees. Range sensors sit on the body's rim; their value is
// metres, the far end of the lookup table is their max range and its noise their error.
robot::SensingOptions sensing_of(const maze::sim::RobotProfile &profile) {
  robot::SensingOptions s;
  for (const maze::sim::BumperSpec &b : profile.bumpers) {
    s.bumpers.push_back({b.name, b.angle_rad, profile.body_radius_m});
  }
  for (const maze::sim::DistanceSensorSpec &d : profile.distance_sensors) {
    const maze::sim::LookupRow &far = d.lookup_table.back();
    s.ranges.push_back({d.name, d.angle_rad, profile.body_radius_m, far.value, d.aperture_rad,
                        far.noise_fraction, std::nullopt, d.axial});
    if (d.origin_m) s.ranges.back().origin = mapping::Point{(*d.origin_m)[0], (*d.origin_m)[1]};
  }
  return s;
}

// The robot names that have the devices a set-up reads, for the error message.
std::string robots_with(const sensing::SetUp &setup) {
  std::string names;
  for (const maze::sim::RobotProfile &p : maze::sim::profiles()) {
    if (!has_devices(p, setup)) continue;
    if (!names.empty()) names += ", ";
    names += p.name;
  }
  return names;
}

robot::DeviceNames devices_of(const maze::sim::RobotProfile &profile) {
  robot::DeviceNames d;
  d.left_motor = profile.left_motor;
  d.right_motor = profile.right_motor;
  d.left_encoder = profile.left_encoder;
  d.right_encoder = profile.right_encoder;
  d.imu = profile.imu;
  d.gps = profile.gps;
  if (!profile.lidars.empty()) d.lidar = profile.lidars.front().name;
  return d;
}

struct RunState {
  bool quit = false;          // q at a --step prompt
  bool interrupted = false;   // Ctrl-C
  LiveLocalization *localization = nullptr;  // --localize's filter, started
};

void require_inside(const maze::Maze &maze, mapping::Cell c, const char *option) {
  if (c.x < 0 || c.y < 0 || c.x >= maze.width() || c.y >= maze.height()) {
    throw common::InputError(fmt::format("{} {},{} is outside the {}x{} maze", option, c.x, c.y,
                                         maze.width(), maze.height()));
  }
}

// "2 sides of visited cells learned wrong: N of (0,4) a wall that is not there, ..."
std::string describe_wrong_sides(const WrongSides &wrong) {
  std::string named;
  for (const WrongSide &w : wrong.first) {
    const char *what = w.verdict == SideVerdict::phantom   ? "a wall that is not there"
                       : w.verdict == SideVerdict::missed ? "a wall missed"
                                                          : "an opening never seen";
    named += fmt::format("{}{} of ({},{}) {}", named.empty() ? "" : ", ", common::to_char(w.side), w.cell.x,
                         w.cell.y, what);
  }
  const std::size_t n = wrong.count;
  return fmt::format("{} side{} of visited cells learned wrong: {}{}", n, n == 1 ? "" : "s", named,
                     n > wrong.first.size() ? ", ..." : "");
}

// The truth's verdict on a run that believed it was done (the controller never sees the
// maze, so only the composition root can say it got the maze wrong, and must):
//   wrong map   a side of a cell the search visited (and so scanned in) is learned wrong or
//               never learned; whatever the strategy, where the robot looked it must have
//               mapped right (a speed run's cells, driven through unscanned, are not judged);
//   incomplete  dfs and frontier mean to visit every reachable cell (wall followers and
//               floodfill may leave cells by design): reachable cells never visited.
void judge_ending(const RunOptions &options, RunSummary &summary) {
  name_step_limit(options, summary);
  if (summary.reason != robot::EndReason::done && summary.reason != robot::EndReason::incomplete) return;
  const MapScore &score = summary.score;
  const auto add = [&](const std::string &finding) {
    summary.message = summary.message.empty() ? finding : fmt::format("{}; {}", finding, summary.message);
  };
  const bool means_to_cover = options.strategy == explore::StrategyKind::dfs ||
                              options.strategy == explore::StrategyKind::frontier;
  // Floodfill means to reach a goal: done without one (walled off from the start) is not done.
  if (options.strategy == explore::StrategyKind::floodfill && !summary.reached_goal) {
    add("no goal reached");
    summary.reason = robot::EndReason::incomplete;
  }
  if (means_to_cover && score.visited_reachable_cells < score.reachable_cells) {
    const std::size_t missed = score.reachable_cells - score.visited_reachable_cells;
    add(fmt::format("{} of {} reachable cells never visited", missed, score.reachable_cells));
    summary.reason = robot::EndReason::incomplete;
  }
  if (summary.wrong_sides.count > 0) {
    add(describe_wrong_sides(summary.wrong_sides));
    summary.reason = robot::EndReason::wrong_map;
  }
}

}  // namespace

robot::ControllerOptions robot_description(const maze::sim::RobotProfile &profile,
                                           std::optional<double> noise_fraction) {
  robot::ControllerOptions c;
  c.motion.wheel_radius_m = profile.wheel_radius_m;
  c.motion.axle_m = profile.axle_m;
  c.devices = devices_of(profile);
  if (!profile.lidars.empty()) {
    const maze::sim::LidarSpec &lidar = profile.lidars.front();
    // The lidar's data sheet: its noise, so that the scan filter never takes noise for a spike.
    c.scan_filter.range_noise_m = noise_fraction.value_or(lidar.noise) * lidar.max_range_m;
  }
  if (profile.speed_run) {
    c.motion.ramp_acceleration_m_s2 = profile.speed_run->acceleration_m_s2;
    c.motion.ramp_top_speed_m_s = profile.speed_run->top_speed_m_s;
  }
  c.sensing = sensing_of(profile);
  return c;
}

robot::ControllerOptions controller_options(const RunOptions &options, const maze::Maze &maze,
                                            const maze::sim::RobotProfile &profile) {
  robot::ControllerOptions c = robot_description(profile, options.simulation.noise);
  c.geometry.width_cells = maze.width();
  c.geometry.height_cells = maze.height();
  c.geometry.subcells = options.subcells;
  c.geometry.cell_size_m = maze.cell_size_m();
  c.geometry.origin = {maze.origin_x_m(), maze.origin_y_m()};
  c.start = to_mapping(maze.start());
  c.start_heading = maze.start_heading();
  for (const maze::Cell goal : maze.goals()) c.goals.push_back(to_mapping(goal));
  c.sensor = options.sensor;
  c.model = options.model;
  c.strategy = options.strategy;
  c.motion.max_steps = step_limit(options, maze).steps;
  c.speed_run = options.plan.speed_run;
  c.sensing.range_model = options.range_model;
  if (options.threshold) c.occupied_threshold = static_cast<float>(*options.threshold);
  return c;
}

bool has_devices(const maze::sim::RobotProfile &profile, const sensing::SetUp &setup) {
  if (setup.reads_lidar()) return !profile.lidars.empty();
  return setup.reads_bumpers() ? !profile.bumpers.empty() : !profile.distance_sensors.empty();
}

void require_sensors(const RunOptions &options, const maze::sim::RobotProfile &profile) {
  const sensing::SetUp &setup = sensing::setup(options.model.kind);
  if (!has_devices(profile, setup)) {
    throw common::InputError(fmt::format("robot '{}' has no {}, which the '{}' model needs (robots with {}: {})",
                                         profile.name, setup.devices(), setup.name, setup.devices(),
                                         robots_with(setup)));
  }
}

RunSummary run_world(const RunOptions &options, std::ostream &out) {
  return run_world(options, out, RunControls{});
}

RunSummary run_world(const RunOptions &options, std::ostream &out, const RunControls &controls) {
  const maze::World world = maze::load_world(options.world, options.world_overrides);
  const maze::Maze &truth = world.maze();  // an arena is refused here, before its warnings
  for (const std::string &warning : world.warnings) common::print_stderr("{}\n", warning);
  return run_maze(options, truth, out, controls);
}

void check_fit(const RunOptions &options, const maze::Maze &truth, const maze::sim::RobotProfile &profile,
               const robot::ControllerOptions &controller) {
  require_sensors(options, profile);
  mapping::validate(controller.geometry, mapping::kDefaultMaxGridBytes);
  if (options.plan.from) require_inside(truth, *options.plan.from, "--from");
  if (options.plan.to) require_inside(truth, *options.plan.to, options.plan.only ? "--to" : "--plan-to");
  robot::validate(controller);
}

render::MapStyle map_style(const OutputOptions &output, const mapping::SensorModel &model,
                           const robot::ControllerOptions &controller, int terminal_fd) {
  render::MapStyle style;
  style.subcell_columns = subcell_columns(output.subcell_columns, terminal_fd, controller.geometry.width_subcells());
  // A run that prints as it goes shows the part around the robot instead (view_for_terminal).
  if (output.quiet && !output.animate) {
    note_if_too_wide(terminal_fd, controller.geometry.width_subcells(), style.subcell_columns);
  }
  style.ascii = output.ascii;
  style.unknown = output.unknown;
  style.initial_log_odds = static_cast<float>(model.prior_log_odds());
  style.color = output.color;
  style.threshold = controller.occupied_threshold;
  return style;
}

std::function<LearnedSide(maze::Cell, maze::Side)> learned_sides(const robot::RunResult &result,
                                                                 const render::MapStyle &style) {
  return [&result, initial = style.initial_log_odds, threshold = style.threshold](maze::Cell c, maze::Side s) {
    return mapping::side_state(result.grid, initial, to_mapping(c), s, threshold);
  };
}

RunSummary robot_summary(const RunOptions &options, const maze::Maze &truth, const robot::RunResult &result,
                         const render::MapStyle &style) {
  RunSummary summary;
  summary.reason = result.reason;
  summary.message = result.message;
  summary.width = truth.width();
  summary.height = truth.height();
  const StepLimit limit = step_limit(options, truth);
  summary.max_steps = limit.steps;
  summary.max_steps_asked = limit.asked;
  summary.time_limited = limit.time_limited;
  summary.steps = result.steps;
  summary.moves = result.moves;
  summary.visited = result.visited;
  summary.reached_goal = std::any_of(result.path.begin(), result.path.end(), [&](mapping::Cell c) {
    return truth.is_goal(maze::Cell{c.x, c.y});
  });
  summary.score = score_map(truth, visited_cells(result.visits), learned_sides(result, style));
  summary.sim_time_s = result.sim_time_s;
  summary.explore_time_s = result.explore_time_s;
  return summary;
}

namespace {

// The run itself, watched as the options ask: the frame's observers first (the files, the
// progress line), then the console's (printed cells or the animation, --step's prompt); and
// Ctrl-C, polled before each control step, after the step before it is recorded: the trace
// holds every step the run counts.
robot::RunResult drive(const RunOptions &options, const maze::Maze &truth, RunFrame &frame,
                       robot::CellController &controller, const render::MapStyle &style, std::ostream &out,
                       const RunControls &controls, RunState &state) {
  const OutputOptions &o = options.output;
  RunObservers observers;
  observers.add(frame.observer());
  std::optional<ScreenGuard> screen;
  std::optional<Animation> animation;
  if (o.animate) {
    screen.emplace(out);
    observers.add(&animation.emplace(out, style, AnimationOptions{o.fps, o.speed, terminal_size(controls.terminal_fd)}));
  }
  std::optional<PrintedCells> printed;
  if (!o.quiet && !o.animate) {
    const int k = options.subcells;
    observers.add(&printed.emplace(robot::ProgressPrinter(
        out, style, truth.width() * truth.height(),
        view_for_terminal(controls.terminal_fd, k, truth.height() * k, truth.width() * k, style.subcell_columns))));
  }
  if (state.localization != nullptr) observers.add(state.localization);
  std::optional<StepPrompt> prompt;
  if (o.step && controls.in != nullptr) observers.add(&prompt.emplace(*controls.in, controls.prompt));
  // Without the console's, the frame's observers are told directly.
  RunObserver *told = animation || printed || prompt || state.localization ? &observers : frame.observer();
  robot::RunHooks hooks = observed_hooks(told, frame.simulation());
  hooks.stop_requested = controls.interrupted;
  if (prompt) {
    hooks.on_step = [&prompt, told = std::move(hooks.on_step)](const robot::StepReport &step) {
      told(step);
      return !prompt->quit();
    };
  }
  robot::RunResult result = controller.run(hooks);
  state.quit = prompt && prompt->quit();
  state.interrupted = result.reason == robot::EndReason::stopped && !state.quit;
  return result;
}

RunSummary summarize(const RunOptions &options, const maze::Maze &truth, const robot::RunResult &result,
                     const RunState &state, const render::MapStyle &style) {
  RunSummary summary = robot_summary(options, truth, result, style);
  if (result.reason == robot::EndReason::stopped) {
    summary.interrupted = state.interrupted;
    summary.message = state.interrupted ? "interrupted by " + common::interrupt_name() : "quit with q";
  }
  // Where the robot looked: the search's cells (a speed run drives through cells unscanned).
  summary.wrong_sides = wrong_sides_where_looked(truth, visited_cells(result.search_visits.value_or(result.visits)),
                                                 learned_sides(result, style));
  judge_ending(options, summary);
  summary.shortest = result.shortest;
  summary.speed_run = result.speed_run;
  summary.speed_run_asked = options.plan.speed_run;
  if (state.localization != nullptr) summary.localization = state.localization->summary();
  return summary;
}

// The robot drawn where it ended, in colour.
render::RobotMark robot_mark(const robot::RunResult &result, const RunOptions &options) {
  const mapping::Cell last = result.path.back();
  const int mid = options.subcells / 2;
  return render::RobotMark{
      mapping::to_global(last, {mid, mid}, options.subcells),
      render::arrow(result.visits.heading(last).value_or(mapping::Heading::north), options.output.ascii)};
}

}  // namespace

robot::RunHooks observed_hooks(RunObserver *observer, const webots::embedded::Simulation &simulation) {
  robot::RunHooks hooks;
  if (observer == nullptr) return hooks;
  hooks.on_move = [observer, &simulation](const robot::MoveReport &move) {
    RunStep arrival = step_at(move.step, move.sim_time_s, simulation.pose());
    arrival.arrival = &move;
    observer->on_step(arrival);
  };
  hooks.on_step = [observer, &simulation](const robot::StepReport &step) {
    RunStep told = step_at(step.step, step.sim_time_s, simulation.pose());
    told.cell = &step;
    observer->on_step(told);
    return true;
  };
  hooks.grid_changes = observer->grid_changes();
  return hooks;
}

RunSummary run_maze(const RunOptions &options, const maze::Maze &world, std::ostream &out,
                    const RunControls &controls) {
  const auto started = std::chrono::steady_clock::now();
  // Scored on the lattice's truth with its solids in cells (maze::with_solid_sides); simulated on the world.
  const maze::Maze truth = maze::with_solid_sides(world, options.subcells);
  const maze::sim::RobotProfile &profile = robot_profile(options);
  const robot::ControllerOptions controller_opts = controller_options(options, truth, profile);
  check_fit(options, truth, profile, controller_opts);
  RunFrame frame(maze::world_of(world), profile, options.simulation, controls.observer, controls.progress_fd);
  webots::embedded::Simulation &simulation = frame.simulation();
  const mapping::SensorModel model(options.sensor);
  render::MapStyle style = map_style(options.output, model, controller_opts, controls.terminal_fd);
  assert(options.output.out_dir.empty() || controls.observer != nullptr);
  const CellRunStart cell_start{truth, controller_opts, style.initial_log_odds};
  const RunStart start{options, simulation.robot(), &cell_start, nullptr};
  // --localize prints its belief at each cell where the cells are printed; it refuses a robot
  // it cannot read walls with before the files are started.
  std::optional<LiveLocalization> localization;
  if (options.localize.on) {
    const bool printing = !options.output.quiet && !options.output.animate;
    localization.emplace(options.localize, printing ? &out : nullptr).on_start(start);
  }
  frame.start(start);

  robot::CellController controller(simulation.robot(), controller_opts);
  RunState state;
  state.localization = localization ? &*localization : nullptr;
  const robot::RunResult result =
      drive(options, truth, frame, controller, style, out, controls, state);
  RunSummary summary = summarize(options, truth, result, state, style);
  if (options.output.color && !result.path.empty()) style.robot = robot_mark(result, options);
  // The files first, then the maps (a 4096 x 4096 map is gigabytes of text): a run stopped
  // by Ctrl-C writes its files and its summary, without the maps.
  std::ostringstream planned;
  if (options.plan.to) summary.plan = plan_path(options, result, model, style, planned);
  summary.wall_time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  const CellRunEnd cell{truth, summary, result, model, learned_sides(result, style)};
  frame.end(RunEnd{options, &cell, nullptr}, out, [&] {
    if (summary.interrupted) {
      out << "(interrupted: the final map is not printed)\n\n";
    } else {
      if (!options.plan.only) out << render::render_map(result.grid, result.visits, style) << '\n';
      out << planned.str();
    }
    out << format_summary(options, summary);
  });
  frame.close(out, controls.no_space);
  return summary;
}

std::int64_t max_steps_for(const maze::Maze &maze) { return max_steps_for(maze.width(), maze.height()); }

std::int64_t max_steps_for(int width_cells, int height_cells) {
  constexpr std::int64_t kStepsPerCell = 1000;
  constexpr std::int64_t kMinimum = 100'000;
  return std::max(kMinimum, kStepsPerCell * width_cells * height_cells);
}

}  // namespace app
