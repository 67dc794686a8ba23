#include "app/report/trace_writer.hpp"

#include <filesystem>

#include "app/report/outputs.hpp"

namespace app {

TraceWriter::TraceWriter(const std::string &dir, webots::Robot &robot, const robot::ControllerOptions &controller,
                         bool every_step)
    : sensors_(robot, controller), file_((std::filesystem::path(dir) / "trace.csv").string()), every_step_(every_step) {
  file_.write(trace_header(sensors_.header()));
}

void TraceWriter::on_step(const robot::StepReport &step, const maze::sim::Pose &pose) {
  // Decided before formatting: formatting every row only to drop most cost as much as the run.
  const bool due = every_step_ || !last_action_ || step.action != *last_action_ || !(step.cell == last_cell_) ||
                   step.subcells_updated > 0;
  last_action_ = step.action;
  last_cell_ = step.cell;
  if (due) {
    write_row(step, pose);
    skipped_step_.reset();
  } else {
    skipped_step_ = step;
    skipped_pose_ = pose;
  }
}

void TraceWriter::finish() {
  if (skipped_step_) write_row(*skipped_step_, skipped_pose_);
  skipped_step_.reset();
}

void TraceWriter::write_row(const robot::StepReport &step, const maze::sim::Pose &pose) {
  row_.clear();
  values_.clear();
  sensors_.append_values(values_);
  append_trace_row(row_, step, pose.x_m, pose.y_m, pose.yaw_rad, values_);
  file_.write(row_);
}

}  // namespace app
