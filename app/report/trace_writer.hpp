#pragma once
// trace.csv of `run --out DIR`, written as the run goes: its rows go through a 1 MiB buffer
// to a temporary beside DIR/trace.csv, renamed by commit() when the run ends (a run that
// throws, or a stop signal that ends the process, leaves no temporary). Which steps get a
// row: app/report/outputs.hpp's trace_every_step(); the row's columns: trace_header() and
// app/report/trace_sensors.hpp.

#include <optional>
#include <string>

#include "app/report/trace_sensors.hpp"
#include "common/atomic_file.hpp"
#include "maze/sim/sensors.hpp"
#include "robot/cell/controller.hpp"

namespace webots {
class Robot;
}

namespace app {

class TraceWriter {
 public:
  // Opens DIR/trace.csv's temporary and writes the header. The robot must outlive this.
  TraceWriter(const std::string &dir, webots::Robot &robot, const robot::ControllerOptions &controller,
              bool every_step);

  // The row of one step, with the simulator's true pose at it, when it is due: every step,
  // or (the default form) the first step and each step whose action or cell differs from
  // the step before or whose scan updated the grid. A step left out is kept until the next.
  void on_step(const robot::StepReport &step, const maze::sim::Pose &pose);
  // Writes the last step's row when it was left out (called once the run is over).
  void finish();
  common::OutputFile &file() { return file_; }

 private:
  void write_row(const robot::StepReport &step, const maze::sim::Pose &pose);

  TraceSensors sensors_;
  common::OutputFile file_;
  bool every_step_;
  std::optional<robot::Action> last_action_;  // of the step before
  mapping::Cell last_cell_;
  // The last step and its pose when its row was left out (its readings are the devices'
  // when finish() writes it, as no step came after it).
  std::optional<robot::StepReport> skipped_step_;
  maze::sim::Pose skipped_pose_;
  std::string row_;     // one row (reused)
  std::string values_;  // its readings (reused)
};

}  // namespace app
