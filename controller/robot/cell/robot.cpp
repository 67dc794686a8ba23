#include "robot/cell/robot.hpp"

#include <cassert>
#include <cmath>

#include <fmt/format.h>

#include <webots/Robot.hpp>

#include "mapping/walls.hpp"

namespace robot {
namespace {

using mapping::Cell;
using mapping::Heading;

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

CellRobot::CellRobot(webots::Robot &r, const ControllerOptions &o)
    : robot(r),
      options((validate(o), o)),
      model(o.sensor),
      initial(static_cast<float>(model.prior_log_odds())),
      grid(o.geometry, initial),
      visits(o.geometry.width_cells, o.geometry.height_cells),
      chassis(r, options.devices),
      loop(r, options.motion),
      drive(chassis, options.motion, loop.time_step_ms(), [this](Action a) { return step(a); }),
      senses(r, options, drive, grid, model),
      walls([this](Cell c, Heading h) { return mapping::side_state(grid, initial, c, h, options.occupied_threshold); }),
      arrival(options, drive, senses, grid, visits, walls, [this] { return loop.steps(); }) {}

Motion CellRobot::start() {
  chassis.enable(loop.time_step_ms());
  senses.enable(loop.time_step_ms());
  cell = options.start;
  heading = options.start_heading;
  if (const Motion s = step(Action::start); s != Motion::ok) return s;
  path.push_back(cell);
  visits.record(cell, heading);
  return arrive(true);
}

Motion CellRobot::step(Action action) {
  if (!flush_step()) return Motion::stopped;
  if (const Motion m = loop.step(); m != Motion::ok) return m;
  senses.take_lidar_updates();
  if (hooks.on_step) {
    pending = StepReport{loop.steps(), loop.time_s(), cell, heading, action, 0, &grid, &visits};
    has_pending = true;
  }
  return Motion::ok;
}

bool CellRobot::flush_step() {
  if (!has_pending) return true;
  has_pending = false;
  pending.subcells_updated = senses.take_lidar_updates();
  pending.cell = cell;  // the cell arrived in at this step, as on_move reported it
  return hooks.on_step(pending);
}

Motion CellRobot::arrive(bool new_cell) {
  const Motion s = arrival.arrive(cell, heading, new_cell);
  if (hooks.on_move) hooks.on_move(MoveReport{loop.steps(), moves, loop.time_s(), cell, heading, new_cell, &grid, &visits});
  return s;
}

Motion CellRobot::turn_to(Heading h) {
  if (const Motion s = drive.turn_to(h); s != Motion::ok) return s;
  heading = h;
  visits.record(cell, heading);
  return Motion::ok;
}

Motion CellRobot::drive_ahead() {
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

EndReason CellRobot::ended(Motion s) {
  if (s == Motion::no_progress) message = drive.failure();
  return to_reason(s);
}

}  // namespace robot
