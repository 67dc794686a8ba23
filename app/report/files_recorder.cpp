#include "app/report/files_recorder.hpp"

#include "app/report/output_dir.hpp"
#include "app/report/outputs.hpp"
#include "app/report/truth_picture.hpp"

namespace app {

FilesRecorder::FilesRecorder(std::vector<NamedInput> program_inputs, std::vector<std::string> own_names)
    : program_inputs_(std::move(program_inputs)), own_names_(std::move(own_names)) {}

void FilesRecorder::start(const RunStart &start) {
  const std::string &dir = start.options.output.out_dir;
  std::vector<NamedInput> inputs = run_inputs(start.options);
  inputs.insert(inputs.end(), program_inputs_.begin(), program_inputs_.end());
  dir_.emplace(dir, inputs, own_names_);
  if (start.options.output.trace) {
    trace_.emplace(dir, start.robot, start.controller, trace_every_step(start.options));
  }
  if (keeps_history(start.options, start.controller.geometry)) {
    history_.emplace(start.controller.geometry, start.initial_log_odds);
  }
}

std::vector<std::uint32_t> *FilesRecorder::grid_changes() { return history_ ? &grid_changes_ : nullptr; }

void FilesRecorder::on_step(const robot::StepReport &step, const maze::sim::Pose &true_pose) {
  if (trace_) trace_->on_step(step, true_pose);
  if (history_ && !grid_changes_.empty()) history_->record(step.step, *step.grid, grid_changes_);
}

void FilesRecorder::on_move(const robot::MoveReport &move) {
  if (!history_) return;
  history_->record(move.step, *move.grid, grid_changes_);
  history_->arrived(move.step, move.cell, move.heading);
}

void FilesRecorder::add_own_files(Report report, std::vector<NamedFile> files) {
  own_report_ = std::move(report);
  own_files_ = std::move(files);
}

void FilesRecorder::finish(const RunEnd &end) {
  if (trace_) trace_->finish();
  RunFiles files{&end.result.grid, &end.model, &end.result.path, trace_ ? &trace_->file() : nullptr, {},
                 &end.truth, &end.result.visits, end.learned, history_ ? &*history_ : nullptr,
                 landmark_marks(end.truth), own_report_};
  for (const maze::Cell goal : end.truth.goals()) files.goals.push_back({goal.x, goal.y});
  write_outputs(*dir_, end.options, end.summary, files);
  for (const NamedFile &file : own_files_) dir_->write(file.name, file.bytes);
  dir_->finish();
}

RunSummary run_and_write(const RunOptions &options, std::ostream &out, const RunControls &controls) {
  if (options.output.out_dir.empty() || controls.recorder != nullptr) return run_world(options, out, controls);
  FilesRecorder recorder;
  RunControls with_files = controls;
  with_files.recorder = &recorder;
  return run_world(options, out, with_files);
}

}  // namespace app
