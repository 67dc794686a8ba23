// Options of the cell controller and their validation, apart from the control loop so that
// they are usable (and testable) without a simulation.

#include <cmath>

#include <fmt/format.h>

#include "common/error.hpp"
#include "robot/cell/controller.hpp"
#include "robot/drive.hpp"
#include "robot/options.hpp"

namespace robot {
namespace {

void require_positive(const char *what, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw common::InputError(fmt::format("{} must be a positive number (got {})", what, value));
  }
}

void require_gain(const char *what, double value) {
  if (!std::isfinite(value) || value <= 0.0 || value > 1.0) {
    throw common::InputError(fmt::format("{} must be in (0, 1] (got {})", what, value));
  }
}

}  // namespace

void validate(const MotionOptions &m) {
  if (m.time_step_ms < 0) {
    throw common::InputError(fmt::format("time step must be 0 (the world's) or positive ms (got {})",
                                         m.time_step_ms));
  }
  require_positive("wheel radius", m.wheel_radius_m);
  require_positive("axle length", m.axle_m);
  require_positive("cruise speed", m.cruise_speed_rad_s);
  require_positive("turn speed", m.turn_speed_rad_s);
  require_positive("yaw tolerance", m.yaw_tolerance_rad);
  require_positive("position tolerance", m.position_tolerance_m);
  require_positive("lateral gain", m.lateral_gain);
  require_positive("stall epsilon", m.stall_epsilon);
  require_gain("turn gain", m.turn_gain);
  require_gain("drive gain", m.drive_gain);
  if (m.stall_steps < 1) {
    throw common::InputError(fmt::format("stall steps must be at least 1 (got {})", m.stall_steps));
  }
  require_positive("creep speed", m.creep_speed_m_s);
  if (m.max_steps < 1) {
    throw common::InputError(fmt::format("--max-steps must be at least 1 (got {})", m.max_steps));
  }
}


std::string_view to_string(EndReason reason) {
  switch (reason) {
    case EndReason::done: return "done";
    case EndReason::max_steps: return "max steps";
    case EndReason::no_progress: return "no progress";
    case EndReason::simulation_ended: return "simulation ended";
    case EndReason::stopped: return "stopped";
    case EndReason::incomplete: return "incomplete";
    case EndReason::wrong_map: return "wrong map";
  }
  return "?";
}

std::string_view to_string(Action action) {
  switch (action) {
    case Action::start: return "start";
    case Action::turn: return "turn";
    case Action::drive: return "drive";
    case Action::rest: return "rest";
    case Action::probe: return "probe";
  }
  return "?";
}

void validate(const ControllerOptions &options) {
  mapping::validate(options.geometry, mapping::kDefaultMaxGridBytes);
  mapping::validate(options.sensor);
  sensing::validate(options.model);
  sensing::validate(options.scan_filter);
  if (options.max_rescans < 0 || options.max_rescans > 100) {
    throw common::InputError(fmt::format("rescans must be 0 to 100 (got {})", options.max_rescans));
  }
  explore::validate(explore::ExplorerOptions{options.strategy, options.geometry.width_cells,
                                             options.geometry.height_cells, options.start,
                                             options.goals});
  if (options.speed_run && options.goals.empty()) {
    throw common::InputError(
        "--speed-run drives from the start to a goal (the world has none: no G in a text map, none in a num file): "
        "give --goal X,Y, or --goal centre for the maze's centre cells");
  }
  validate(options.motion);
  sensing::validate(options.sensing.range_model);
  if (options.occupied_threshold && !std::isfinite(*options.occupied_threshold)) {
    throw common::InputError("--threshold must be a finite log-odds value");
  }
  const sensing::SetUp &setup = sensing::setup(options.model.kind);
  if ((setup.reads_bumpers() && options.sensing.bumpers.empty()) ||
      (setup.reads_ranges() && options.sensing.ranges.empty())) {
    throw common::InputError(fmt::format("the {} model needs a robot with {}", setup.name, setup.devices()));
  }
}

}  // namespace robot
