#include "app/run.hpp"

#include <chrono>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "maze/maze.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/simulation.hpp"
#include "maze/world.hpp"
#include "mapping/walls.hpp"
#include "render/ascii_map.hpp"

namespace app {
namespace {

mapping::Cell to_mapping(maze::Cell c) { return {c.x, c.y}; }

mapping::Heading to_heading(maze::Side s) {
  switch (s) {
    case maze::Side::north: return mapping::Heading::north;
    case maze::Side::east: return mapping::Heading::east;
    case maze::Side::south: return mapping::Heading::south;
    case maze::Side::west: return mapping::Heading::west;
  }
  return mapping::Heading::north;
}

// What a maze lab tells the robot's programmer: never the walls.
robot::ControllerOptions controller_options(const RunOptions &options, const maze::Maze &maze,
                                            const maze::sim::RobotProfile &profile) {
  robot::ControllerOptions c;
  c.geometry.width_cells = maze.width();
  c.geometry.height_cells = maze.height();
  c.geometry.subcells = options.subcells;
  c.geometry.cell_size_m = maze.cell_size_m();
  c.geometry.origin = {maze.origin_x_m(), maze.origin_y_m()};
  c.start = to_mapping(maze.start());
  c.start_heading = to_heading(maze.start_heading());
  for (const maze::Cell goal : maze.goals()) c.goals.push_back(to_mapping(goal));
  c.sensor = options.sensor;
  c.mapping.kind = options.model;
  c.mapping.hit_depth = options.hit_depth;
  c.mapping.ignore_no_return = options.ignore_no_return;
  c.strategy = options.strategy;
  c.motion.wheel_radius_m = profile.wheel_radius_m;
  c.motion.axle_m = profile.axle_m;
  c.motion.max_steps = options.max_steps;
  if (!profile.lidars.empty()) c.devices.lidar = profile.lidars.front().name;
  return c;
}

void require_lidar(const RunOptions &options, const maze::sim::RobotProfile &profile) {
  if (profile.lidars.empty()) {
    throw common::InputError(fmt::format(
        "robot '{}' has no lidar, which the '{}' model needs (robots with a lidar: hambot)",
        profile.name, mapping::to_string(options.model)));
  }
}

class ProgressPrinter {
 public:
  ProgressPrinter(std::ostream &out, const render::MapStyle &style, int total_cells)
      : out_(out), style_(style), total_cells_(total_cells) {}

  void operator()(const robot::MoveReport &report) {
    std::string text = render::format_status(static_cast<long>(report.step), report.cell,
                                             report.heading, report.visits->count(), total_cells_);
    text += '\n';
    text += render::render_map(*report.grid, *report.visits, style_);
    if (report.new_cell) {
      text += fmt::format("cell ({},{}) log-odds, north row first:\n", report.cell.x, report.cell.y);
      text += render::format_cell_matrix(*report.grid, report.cell);
    }
    text += '\n';
    out_ << text;
  }

 private:
  std::ostream &out_;
  render::MapStyle style_;
  int total_cells_;
};

LearnedSide to_learned(mapping::SideState s) {
  switch (s) {
    case mapping::SideState::open: return LearnedSide::open;
    case mapping::SideState::wall: return LearnedSide::wall;
    case mapping::SideState::unknown: return LearnedSide::unknown;
  }
  return LearnedSide::unknown;
}

MapScore score(const maze::Maze &truth, const robot::RunResult &result, float initial_log_odds) {
  std::vector<bool> visited(static_cast<std::size_t>(truth.width()) *
                            static_cast<std::size_t>(truth.height()));
  for (int y = 0; y < truth.height(); ++y) {
    for (int x = 0; x < truth.width(); ++x) {
      visited[static_cast<std::size_t>(y) * static_cast<std::size_t>(truth.width()) +
              static_cast<std::size_t>(x)] = result.visits.visited({x, y});
    }
  }
  const auto learned = [&](maze::Cell c, maze::Side s) {
    return to_learned(mapping::side_state(result.grid, initial_log_odds, to_mapping(c), to_heading(s)));
  };
  return score_map(truth, visited, learned);
}

std::string percent(double value) { return fmt::format("{:.2f}%", value); }

}  // namespace

RunSummary run_world(const RunOptions &options, std::ostream &out) {
  const maze::World world = maze::load_world(options.world);
  for (const std::string &warning : world.warnings) fmt::print(stderr, "{}\n", warning);
  return run_maze(options, world.maze, out);
}

RunSummary run_maze(const RunOptions &options, const maze::Maze &truth, std::ostream &out) {
  const auto started = std::chrono::steady_clock::now();
  const maze::sim::RobotProfile &profile = maze::sim::find_profile(options.robot);
  require_lidar(options, profile);

  const robot::ControllerOptions controller_opts = controller_options(options, truth, profile);
  robot::validate(controller_opts);

  maze::sim::SimulationOptions sim_opts;
  sim_opts.seed = options.seed;
  sim_opts.noise = options.noise;
  sim_opts.dropout = options.dropout;
  sim_opts.spikes = options.spikes;
  sim_opts.stuck_bumper = options.stuck_bumper;
  sim_opts.wheel_slip = options.wheel_slip;
  webots::embedded::Simulation simulation(truth, profile, sim_opts);

  const mapping::SensorModel model(options.sensor);
  render::MapStyle style;
  style.ascii = options.ascii;
  style.unknown = options.unknown;
  style.initial_log_odds = static_cast<float>(model.prior_log_odds());

  robot::CellController controller(simulation.robot(), controller_opts);
  robot::Observer observer;
  if (!options.quiet) observer = ProgressPrinter(out, style, truth.width() * truth.height());
  const robot::RunResult result = controller.run(observer);

  RunSummary summary;
  summary.reason = result.reason;
  summary.message = result.message;
  summary.width = truth.width();
  summary.height = truth.height();
  summary.steps = result.steps;
  summary.moves = result.moves;
  summary.visited = result.visited;
  if (!result.path.empty()) {
    const mapping::Cell last = result.path.back();
    summary.reached_goal = truth.is_goal(maze::Cell{last.x, last.y});
  }
  summary.score = score(truth, result, style.initial_log_odds);
  summary.sim_time_s = result.sim_time_s;

  out << render::render_map(result.grid, result.visits, style) << '\n';
  summary.wall_time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  out << format_summary(options, summary);
  return summary;
}

std::string format_summary(const RunOptions &options, const RunSummary &s) {
  std::string text;
  auto line = [&text](std::string_view key, const std::string &value) {
    text += fmt::format("{}: {}\n", key, value);
  };
  line("world", options.world);
  line("size", fmt::format("{}x{}", s.width, s.height));
  line("subcells", std::to_string(options.subcells));
  line("model", std::string(mapping::to_string(options.model)));
  line("strategy", std::string(explore::to_string(options.strategy)));
  line("robot", options.robot);
  line("seed", std::to_string(options.seed));
  line("end", s.message.empty() ? std::string(robot::to_string(s.reason))
                                : fmt::format("{} ({})", robot::to_string(s.reason), s.message));
  line("steps", std::to_string(s.steps));
  line("moves", std::to_string(s.moves));
  line("visited", std::to_string(s.visited));
  if (options.strategy == explore::StrategyKind::floodfill) {
    line("goal", s.reached_goal ? "reached" : "not reached");
  }
  line("reachable", std::to_string(s.score.reachable_cells));
  line("coverage", percent(s.score.coverage_percent()));
  line("wall_accuracy", percent(s.score.wall_accuracy_percent()));
  line("sim_time_s", fmt::format("{:.3f}", s.sim_time_s));
  line("wall_time_ms", fmt::format("{:.0f}", s.wall_time_ms));
  return text;
}

int exit_status(const RunSummary &summary) {
  switch (summary.reason) {
    case robot::EndReason::done:
    case robot::EndReason::max_steps: return 0;
    case robot::EndReason::no_progress:
    case robot::EndReason::simulation_ended: return 1;
  }
  return 1;
}

}  // namespace app
