#include "robot/control_loop.hpp"

#include <cmath>

#include <webots/Robot.hpp>

namespace robot {
namespace {

int control_time_step_ms(webots::Robot &robot, const MotionOptions &m) {
  return m.time_step_ms > 0 ? m.time_step_ms : static_cast<int>(std::lround(robot.getBasicTimeStep()));
}

}  // namespace

ControlLoop::ControlLoop(webots::Robot &robot, const MotionOptions &motion, StopPoll stop_requested,
                         double time_limit_s)
    : robot_(robot),
      time_step_ms_(control_time_step_ms(robot, motion)),
      max_steps_(motion.max_steps),
      stop_requested_(stop_requested),
      time_limit_s_(time_limit_s) {}

Motion ControlLoop::step() {
  if (steps_ >= max_steps_) return Motion::max_steps;
  if (stop_requested_ != nullptr && stop_requested_()) return Motion::stopped;
  if (time_limit_s_ > 0.0 && robot_.getTime() >= time_limit_s_) {
    time_up_ = true;
    return Motion::stopped;
  }
  if (robot_.step(time_step_ms_) == -1) return Motion::ended;
  ++steps_;
  return Motion::ok;
}

double ControlLoop::time_s() const { return robot_.getTime(); }

}  // namespace robot
