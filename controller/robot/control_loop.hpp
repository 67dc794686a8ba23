#pragma once
// The one control loop every controller kind steps through, as a Webots controller steps
// with `while (robot.step(timeStep) != -1)`: a control step is one Robot::step of the
// controller's time step (MotionOptions::time_step_ms, else the world's basic time step),
// counted, within the step budget (MotionOptions::max_steps), until a stop is asked and
// until the time limit. The cell explorer's strategies and an mms program's commands
// (CellRobot) and the room strategies (MetricController) take every step here; what each
// senses and reports after a step is its own. A Python controller calls Robot::step itself,
// as in Webots; the simulator's own time limit (maze::sim::SimulationOptions) then ends it.

#include <cstdint>

#include "robot/drive.hpp"

namespace webots {
class Robot;
}

namespace robot {

// Polled before each control step: true stops the run (Ctrl-C); nullptr: never asked.
using StopPoll = bool (*)();

class ControlLoop {
 public:
  // time_limit_s: simulated seconds after which no step is taken (0: none). The robot must
  // outlive this.
  ControlLoop(webots::Robot &robot, const MotionOptions &motion, StopPoll stop_requested = nullptr,
              double time_limit_s = 0.0);

  // One control step. Before it, in this order: Motion::max_steps once max_steps are spent,
  // Motion::stopped when stop_requested() says so, Motion::stopped with time_up() once the
  // simulated time reaches the time limit. Motion::ended when the simulation ends
  // (Robot::step returns -1). Else Motion::ok: the step taken and counted.
  Motion step();
  // From the next step on, stop_requested is polled before each (nullptr: never).
  void poll_for_stop(StopPoll stop_requested) { stop_requested_ = stop_requested; }

  std::int64_t steps() const { return steps_; }  // control steps taken
  int time_step_ms() const { return time_step_ms_; }
  double time_s() const;                          // simulated time (Robot::getTime)
  bool time_up() const { return time_up_; }       // a step was refused at the time limit

 private:
  webots::Robot &robot_;
  int time_step_ms_;
  std::int64_t max_steps_;
  StopPoll stop_requested_;
  double time_limit_s_;
  std::int64_t steps_ = 0;
  bool time_up_ = false;
};

}  // namespace robot
