#include "robot/cell_controller.hpp"

#include <cassert>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include <webots/Robot.hpp>

#include "explore/shortest_path.hpp"
#include "mapping/walls.hpp"
#include "robot/arrival.hpp"
#include "robot/senses.hpp"

namespace robot {
namespace {

using mapping::Cell;
using mapping::Heading;

int time_step_of(webots::Robot &robot, const MotionOptions &m) {
  return m.time_step_ms > 0 ? m.time_step_ms : static_cast<int>(std::lround(robot.getBasicTimeStep()));
}

EndReason to_reason(Motion s) {
  switch (s) {
    case Motion::max_steps: return EndReason::max_steps;
    case Motion::no_progress: return EndReason::no_progress;
    case Motion::ended: return EndReason::simulation_ended;
    case Motion::stopped: return EndReason::stopped;
    case Motion::ok: break;
  }
  assert(false && "not an ending");
  return EndReason::done;
}

}  // namespace

struct CellController::Impl {
  Impl(webots::Robot &r, const ControllerOptions &o)
      : robot(r),
        options((validate(o), o)),
        model(o.sensor),
        initial(static_cast<float>(model.prior_log_odds())),
        grid(o.geometry, initial),
        visits(o.geometry.width_cells, o.geometry.height_cells),
        explorer(explore::ExplorerOptions{o.strategy, o.geometry.width_cells, o.geometry.height_cells, o.start, o.goals}),
        chassis(r, options.devices),
        time_step_ms(time_step_of(r, options.motion)),
        drive(chassis, options.motion, time_step_ms, [this](Action a) { return step(a); }),
        senses(r, options, drive, grid, model),
        walls([this](Cell c, Heading h) { return mapping::side_state(grid, initial, c, h, options.occupied_threshold); }),
        arrival(options, drive, senses, grid, visits, walls, [this] { return steps; }) {}

  // One control step; the step before it is reported first (once its scans are done).
  Motion step(Action action) {
    if (!flush_step()) return Motion::stopped;
    if (steps >= options.motion.max_steps) return Motion::max_steps;
    if (robot.step(time_step_ms) == -1) return Motion::ended;
    ++steps;
    senses.take_lidar_updates();
    if (hooks.on_step) {
      pending = StepReport{steps, robot.getTime(), cell, heading, action, 0, &grid, &visits};
      has_pending = true;
    }
    return Motion::ok;
  }

  // Reports the last step; false when the observer stops the run.
  bool flush_step() {
    if (!has_pending) return true;
    has_pending = false;
    pending.subcells_updated = senses.take_lidar_updates();
    pending.cell = cell;  // the cell arrived in at this step, as on_move reported it
    return hooks.on_step(pending);
  }

  // Arrives in the robot's cell and reports it.
  Motion arrive(bool new_cell) {
    const Motion s = arrival.arrive(cell, heading, new_cell);
    if (hooks.on_move) hooks.on_move(MoveReport{steps, moves, robot.getTime(), cell, heading, new_cell, &grid, &visits});
    return s;
  }

  // Drives along the heading into the neighbouring cell.
  Motion drive_ahead() {
    const Cell next = mapping::neighbour(cell, heading);
    if (const Motion s = drive.drive_to(grid.centre_of(next), heading, options.geometry.cell_size_m,
                                        fmt::format("cell ({},{})", next.x, next.y));
        s != Motion::ok) {
      return s;
    }
    cell = next;
    path.push_back(cell);
    return Motion::ok;
  }

  // Turns to heading h, leaving the cell facing it, and drives into the neighbour.
  Motion explore_towards(Heading h) {
    if (const Motion s = drive.turn_to(h); s != Motion::ok) return s;
    heading = h;
    visits.record(cell, heading);
    return drive_ahead();
  }

  EndReason ended(Motion s) {
    if (s == Motion::no_progress) message = drive.failure();
    return to_reason(s);
  }

  EndReason explore() {
    chassis.enable(time_step_ms);
    senses.enable(time_step_ms);
    cell = options.start;
    heading = options.start_heading;
    if (const Motion s = step(Action::start); s != Motion::ok) return ended(s);
    path.push_back(cell);
    visits.record(cell, heading);
    if (const Motion s = arrive(true); s != Motion::ok) return ended(s);
    for (;;) {
      const auto next = explorer.next(cell, heading, walls);
      if (!next) {
        if (!flush_step()) return EndReason::stopped;
        message = arrival.unresolved_sides();
        return message.empty() ? EndReason::done : EndReason::incomplete;
      }
      if (const Motion s = explore_towards(*next); s != Motion::ok) return ended(s);
      ++moves;
      const bool new_cell = !visits.visited(cell);
      visits.record(cell, heading);
      if (const Motion s = arrive(new_cell); s != Motion::ok) return ended(s);
    }
  }

  // Drives a route cell by cell, without mapping; counts the cells driven.
  Motion follow(const std::vector<Heading> &route, int &cells) {
    for (const Heading h : route) {
      Motion m = drive.turn_to(h);
      heading = h;
      visits.record(cell, heading);  // the map's arrows show the way the speed run went
      if (m == Motion::ok) m = drive_ahead();
      if (m != Motion::ok) return m;
      ++cells;
      visits.record(cell, heading);
    }
    return Motion::ok;
  }

  // The micromouse speed run (options.hpp): back to the start, then the known shortest path
  // to the goal. Nothing is driven when there is no known path.
  EndReason speed_run() {
    const explore::MazeSize size{options.geometry.width_cells, options.geometry.height_cells};
    const auto back = explore::shortest_route(size, cell, {options.start}, walls, explore::UnknownSides::closed, heading);
    const auto run = explore::shortest_route(size, options.start, options.goals, walls, explore::UnknownSides::closed,
                                             back && !back->empty() ? back->back() : heading);
    if (!back || !run) return EndReason::done;
    if (const Motion m = follow(*back, speed_result.return_cells); m != Motion::ok) return ended(m);
    const double started = robot.getTime();
    int cells = 0;
    if (const Motion m = follow(*run, cells); m != Motion::ok) return ended(m);
    speed_result.cells = cells;
    speed_result.turns = explore::turns(*run);
    speed_result.time_s = robot.getTime() - started;
    return EndReason::done;
  }

  webots::Robot &robot;
  ControllerOptions options;
  mapping::SensorModel model;
  float initial;
  mapping::OccupancyGrid grid;
  explore::Visits visits;
  explore::Explorer explorer;
  WebotsChassis chassis;
  int time_step_ms;
  Drive drive;
  Senses senses;
  explore::WallQuery walls;
  Arrival arrival;

  RunHooks hooks;
  StepReport pending;
  bool has_pending = false;
  Cell cell;  // where the robot is (the cell it left, while it moves)
  Heading heading = Heading::north;
  std::int64_t steps = 0;
  int moves = 0;
  SpeedRun speed_result;
  std::vector<Cell> path;
  std::string message;
  bool ran = false;
};

CellController::CellController(webots::Robot &robot, const ControllerOptions &options)
    : impl_(std::make_unique<Impl>(robot, options)) {}

CellController::~CellController() = default;

RunResult CellController::run(const Observer &observer) {
  RunHooks hooks;
  hooks.on_move = observer;
  return run(hooks);
}

RunResult CellController::run(const RunHooks &hooks) {
  Impl &s = *impl_;
  assert(!s.ran && "CellController::run is called once");
  s.ran = true;
  s.hooks = hooks;
  s.grid.set_change_log(hooks.grid_changes);
  EndReason reason = s.explore();
  const double explore_time_s = s.robot.getTime();
  const int search_visited = s.visits.count();
  std::optional<explore::ShortestPathProof> proof;
  if (!s.options.goals.empty()) {
    proof = explore::prove_shortest_path(explore::ExplorerOptions{s.options.strategy, s.options.geometry.width_cells,
                                                                  s.options.geometry.height_cells, s.options.start,
                                                                  s.options.goals},
                                         s.walls);
  }
  std::optional<explore::Visits> search_visits;
  if (reason == EndReason::done && s.options.speed_run) {
    search_visits = s.visits;
    reason = s.speed_run();
  }
  if (reason != EndReason::stopped) s.flush_step();
  return RunResult{reason,        std::move(s.message), s.steps,          s.moves,          search_visited,
                   s.robot.getTime(), std::move(s.grid), std::move(s.visits), std::move(s.path), explore_time_s,
                   proof,         s.speed_result,       std::move(search_visits)};
}

}  // namespace robot
