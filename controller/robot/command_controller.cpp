#include "robot/command_controller.hpp"

#include <string>
#include <utility>

#include <fmt/format.h>

#include <webots/Robot.hpp>

#include "explore/shortest_path.hpp"
#include "robot/cell/robot.hpp"

namespace robot {

using mapping::Cell;
using mapping::Heading;
using mapping::SideState;

CommandController::CommandController(webots::Robot &robot, const ControllerOptions &options)
    : body_(std::make_unique<CellRobot>(robot, options)) {}

CommandController::~CommandController() = default;

Motion CommandController::start(const RunHooks &hooks) {
  body_->hooks = hooks;
  body_->loop.poll_for_stop(hooks.stop_requested);
  return body_->start();
}

Cell CommandController::cell() const { return body_->cell; }

SideState CommandController::side(Cell c, Heading h) const { return body_->walls(c, h); }

int CommandController::open_ahead(Heading h, int most) const {
  const CellRobot &b = *body_;
  int cells = 0;
  for (Cell c = b.cell; cells < most && b.grid.contains(mapping::neighbour(c, h)); c = mapping::neighbour(c, h)) {
    const SideState held = b.walls(c, h);
    const SideState seen = b.senses.sees_side_ahead(b.cell, c, h);
    const bool open = (held == SideState::open || seen == SideState::open) && held != SideState::wall && seen != SideState::wall;
    if (!open) break;
    ++cells;
  }
  return cells;
}

Motion CommandController::look(Heading h, SideState &state) {
  CellRobot &b = *body_;
  state = b.walls(b.cell, h);
  if (state != SideState::unknown) return Motion::ok;
  if (const Motion s = b.turn_to(h); s != Motion::ok) return s;
  for (int attempt = 0; attempt <= b.options.max_rescans && state == SideState::unknown; ++attempt) {
    if (const Motion s = b.drive.come_to_rest(); s != Motion::ok) return s;
    for (int i = 0; i < b.senses.revolution_steps(); ++i) {
      if (const Motion s = b.drive.come_to_rest(); s != Motion::ok) return s;
    }
    b.senses.scan(b.cell, b.loop.steps());
    state = b.walls(b.cell, h);
  }
  return Motion::ok;
}

Motion CommandController::turn_to(Heading h) {
  if (body_->heading == h) return Motion::ok;
  return body_->turn_to(h);
}

Motion CommandController::move(Heading h) {
  CellRobot &b = *body_;
  if (const Motion s = turn_to(h); s != Motion::ok) return s;
  if (const Motion s = b.drive_ahead(); s != Motion::ok) return s;
  ++b.moves;
  const bool new_cell = !b.visits.visited(b.cell);
  b.visits.record(b.cell, b.heading);
  return b.arrive(new_cell);
}

Motion CommandController::move_straight(Heading h, int cells) {
  CellRobot &b = *body_;
  const bool ramped = has_ramp(b.options.motion);
  if (cells < 1) return Motion::ok;
  if (cells == 1 && !ramped) return move(h);
  if (const Motion s = turn_to(h); s != Motion::ok) return s;
  Cell last = b.cell;
  for (int i = 0; i < cells; ++i) last = mapping::neighbour(last, h);
  const mapping::Point target = b.grid.centre_of(last);
  const double distance_m = cells * b.options.geometry.cell_size_m;
  const std::string what = fmt::format("cell ({},{})", last.x, last.y);
  if (const Motion s = ramped ? b.drive.drive_ramped(target, h, distance_m, what) : b.drive.drive_to(target, h, distance_m, what);
      s != Motion::ok) {
    return s;
  }
  const bool new_cell = !b.visits.visited(last);
  for (int i = 0; i < cells; ++i) {
    b.cell = mapping::neighbour(b.cell, h);
    b.path.push_back(b.cell);
    b.visits.record(b.cell, b.heading);
    ++b.moves;
  }
  return b.arrive(new_cell);
}

Motion CommandController::return_to_start(bool &found) {
  CellRobot &b = *body_;
  const explore::MazeSize size{b.options.geometry.width_cells, b.options.geometry.height_cells};
  const auto route = explore::shortest_route(size, b.cell, {b.options.start}, b.walls, explore::UnknownSides::closed, b.heading);
  found = route.has_value();
  if (!found) return Motion::ok;
  for (const Heading h : *route) {
    if (const Motion s = turn_to(h); s != Motion::ok) return s;
    if (const Motion s = b.drive_ahead(); s != Motion::ok) return s;
    b.visits.record(b.cell, b.heading);
  }
  return turn_to(b.options.start_heading);
}

const mapping::OccupancyGrid &CommandController::grid() const { return body_->grid; }
const explore::Visits &CommandController::visits() const { return body_->visits; }
std::int64_t CommandController::steps() const { return body_->loop.steps(); }
double CommandController::time_s() const { return body_->robot.getTime(); }

EndReason CommandController::ended(Motion s, std::string &message) {
  const EndReason reason = body_->ended(s);
  message = body_->message;
  return reason;
}

RunResult CommandController::finish(EndReason reason, std::string message) {
  CellRobot &b = *body_;
  if (reason != EndReason::stopped) b.flush_step();
  const int visited = b.visits.count();
  const double time_s = b.robot.getTime();
  return RunResult{reason, std::move(message), b.loop.steps(), b.moves, visited, time_s, std::move(b.grid), std::move(b.visits),
                   std::move(b.path), time_s, std::nullopt, SpeedRun{}, std::nullopt};
}

}  // namespace robot
