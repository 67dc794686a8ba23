#include "robot/cell/controller.hpp"

#include <cassert>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include <webots/Robot.hpp>

#include "explore/shortest_path.hpp"
#include "mapping/walls.hpp"
#include "robot/cell/robot.hpp"

namespace robot {

using mapping::Cell;
using mapping::Heading;

struct CellController::Impl {
  Impl(webots::Robot &r, const ControllerOptions &o)
      : body(r, o),
        explorer(explore::ExplorerOptions{o.strategy, o.geometry.width_cells, o.geometry.height_cells, o.start, o.goals}) {}

  // Turns to heading h, leaving the cell facing it, and drives into the neighbour.
  Motion explore_towards(Heading h) {
    if (const Motion s = body.turn_to(h); s != Motion::ok) return s;
    return body.drive_ahead();
  }

  EndReason explore() {
    if (const Motion s = body.start(); s != Motion::ok) return body.ended(s);
    for (;;) {
      const auto next = explorer.next(body.cell, body.heading, body.walls);
      if (!next) {
        if (!body.flush_step()) return EndReason::stopped;
        body.message = body.arrival.unresolved_sides();
        return body.message.empty() ? EndReason::done : EndReason::incomplete;
      }
      if (const Motion s = explore_towards(*next); s != Motion::ok) return body.ended(s);
      ++body.moves;
      const bool new_cell = !body.visits.visited(body.cell);
      body.visits.record(body.cell, body.heading);
      if (const Motion s = body.arrive(new_cell); s != Motion::ok) return body.ended(s);
    }
  }

  // Drives a route without mapping, each straight in one ramped leg; counts the cells driven.
  Motion follow_ramped(const std::vector<Heading> &route, int &cells) {
    const double cell_m = body.options.geometry.cell_size_m;
    for (std::size_t i = 0; i < route.size();) {
      const Heading h = route[i];
      std::size_t end = i;
      while (end < route.size() && route[end] == h) ++end;
      Motion m = body.drive.turn_to(h);
      body.heading = h;
      body.visits.record(body.cell, body.heading);
      Cell last = body.cell;
      for (std::size_t k = i; k < end; ++k) last = mapping::neighbour(last, h);
      const int straight = static_cast<int>(end - i);
      if (m == Motion::ok) {
        m = body.drive.drive_ramped(body.grid.centre_of(last), h, straight * cell_m, fmt::format("cell ({},{})", last.x, last.y));
      }
      if (m != Motion::ok) return m;
      for (std::size_t k = i; k < end; ++k) {
        body.cell = mapping::neighbour(body.cell, h);
        body.path.push_back(body.cell);
        body.visits.record(body.cell, body.heading);
      }
      cells += straight;
      i = end;
    }
    return Motion::ok;
  }

  bool ramped() const { return has_ramp(body.options.motion); }

  // Drives a route cell by cell, without mapping; counts the cells driven.
  Motion follow(const std::vector<Heading> &route, int &cells) {
    if (ramped()) return follow_ramped(route, cells);
    for (const Heading h : route) {
      Motion m = body.drive.turn_to(h);
      body.heading = h;
      body.visits.record(body.cell, body.heading);  // the map's arrows show the way the speed run went
      if (m == Motion::ok) m = body.drive_ahead();
      if (m != Motion::ok) return m;
      ++cells;
      body.visits.record(body.cell, body.heading);
    }
    return Motion::ok;
  }

  // The micromouse speed run (options.hpp): back to the start, then the known shortest path
  // to the goal. Nothing is driven when there is no known path.
  EndReason speed_run() {
    const ControllerOptions &options = body.options;
    const explore::MazeSize size{options.geometry.width_cells, options.geometry.height_cells};
    const auto back =
        explore::shortest_route(size, body.cell, {options.start}, body.walls, explore::UnknownSides::closed, body.heading);
    const auto run = explore::shortest_route(size, options.start, options.goals, body.walls, explore::UnknownSides::closed,
                                             back && !back->empty() ? back->back() : body.heading);
    if (!back || !run) return EndReason::done;
    if (const Motion m = follow(*back, speed_result.return_cells); m != Motion::ok) return body.ended(m);
    const double started = body.robot.getTime();
    int cells = 0;
    if (const Motion m = follow(*run, cells); m != Motion::ok) return body.ended(m);
    speed_result.cells = cells;
    speed_result.turns = explore::turns(*run);
    speed_result.time_s = body.robot.getTime() - started;
    return EndReason::done;
  }

  CellRobot body;
  explore::Explorer explorer;
  SpeedRun speed_result;
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
  CellRobot &b = s.body;
  assert(!s.ran && "CellController::run is called once");
  s.ran = true;
  b.hooks = hooks;
  b.loop.poll_for_stop(hooks.stop_requested);
  b.grid.set_change_log(hooks.grid_changes);
  EndReason reason = s.explore();
  const double explore_time_s = b.robot.getTime();
  const int search_visited = b.visits.count();
  std::optional<explore::ShortestPathProof> proof;
  if (!b.options.goals.empty()) {
    proof = explore::prove_shortest_path(explore::ExplorerOptions{b.options.strategy, b.options.geometry.width_cells,
                                                                  b.options.geometry.height_cells, b.options.start,
                                                                  b.options.goals},
                                         b.walls);
  }
  std::optional<explore::Visits> search_visits;
  if (reason == EndReason::done && b.options.speed_run) {
    search_visits = b.visits;
    reason = s.speed_run();
  }
  if (reason != EndReason::stopped) b.flush_step();
  return RunResult{reason,        std::move(b.message), b.loop.steps(),          b.moves,          search_visited,
                   b.robot.getTime(), std::move(b.grid), std::move(b.visits), std::move(b.path), explore_time_s,
                   proof,         s.speed_result,       std::move(search_visits)};
}

}  // namespace robot
