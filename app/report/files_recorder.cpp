#include "app/report/files_recorder.hpp"

#include "app/report/output_dir.hpp"
#include "app/report/outputs.hpp"
#include "app/report/truth_picture.hpp"

namespace app {

FilesRecorder::FilesRecorder(std::vector<NamedInput> program_inputs, std::vector<std::string> own_names)
    : program_inputs_(std::move(program_inputs)), own_names_(std::move(own_names)) {}

void FilesRecorder::on_start(const RunStart &start) {
  const RunOptions &options = start.options;
  std::vector<NamedInput> inputs = run_inputs(options);
  inputs.insert(inputs.end(), program_inputs_.begin(), program_inputs_.end());
  std::vector<std::string> own_names = own_names_;
  if (start.metres != nullptr) own_names.insert(own_names.end(), metres_own_names().begin(), metres_own_names().end());
  dir_.emplace(options.output.out_dir, inputs, own_names);
  if (start.metres != nullptr) metres_.emplace(options, *start.metres);
  if (start.cell == nullptr) return;
  CellRecord &cell = cell_.emplace();
  if (options.output.trace) {
    cell.trace.emplace(options.output.out_dir, start.robot, start.cell->controller, trace_every_step(options));
  }
  if (keeps_history(options, start.cell->controller.geometry)) {
    cell.history.emplace(start.cell->controller.geometry, start.cell->initial_log_odds);
  }
}

std::vector<std::uint32_t> *FilesRecorder::grid_changes() {
  return cell_ && cell_->history ? &cell_->grid_changes : nullptr;
}

void FilesRecorder::on_step(const RunStep &step) {
  if (metres_) metres_->on_step(step);
  if (!cell_) return;
  if (step.cell != nullptr) {
    if (cell_->trace) cell_->trace->on_step(*step.cell, step.true_pose);
    if (cell_->history && !cell_->grid_changes.empty()) {
      cell_->history->record(step.step, *step.cell->grid, cell_->grid_changes);
    }
  }
  if (step.arrival != nullptr && cell_->history) {
    const robot::MoveReport &move = *step.arrival;
    cell_->history->record(move.step, *move.grid, cell_->grid_changes);
    cell_->history->arrived(move.step, move.cell, move.heading);
  }
}

void FilesRecorder::add_own_files(Report report, std::vector<NamedFile> files) {
  own_report_ = std::move(report);
  own_files_ = std::move(files);
}

void FilesRecorder::write_cell_files(const RunOptions &options, const CellRunEnd &end) {
  if (cell_->trace) cell_->trace->finish();
  RunFiles files{&end.result.grid, &end.model, &end.result.path, cell_->trace ? &cell_->trace->file() : nullptr, {},
                 &end.truth, &end.result.visits, end.learned, cell_->history ? &*cell_->history : nullptr,
                 landmark_marks(end.truth), own_report_};
  for (const maze::Cell goal : end.truth.goals()) files.goals.push_back({goal.x, goal.y});
  write_outputs(*dir_, options, end.summary, files);
}

void FilesRecorder::on_end(const RunEnd &end) {
  if (end.cell != nullptr) write_cell_files(end.options, *end.cell);
  if (end.metres != nullptr) metres_->write(*dir_, *end.metres);
  for (const NamedFile &file : own_files_) dir_->write(file.name, file.bytes);
  dir_->finish();
}

RunSummary run_and_write(const RunOptions &options, std::ostream &out, const RunControls &controls) {
  if (options.output.out_dir.empty() || controls.observer != nullptr) return run_world(options, out, controls);
  FilesRecorder recorder;
  RunControls with_files = controls;
  with_files.observer = &recorder;
  return run_world(options, out, with_files);
}

MetricRunSummary run_metric_and_write(const maze::World &world, const RunOptions &options, std::ostream &out,
                                      std::chrono::steady_clock::time_point started, robot::StopPoll interrupted,
                                      Report *report, int progress_fd) {
  if (options.output.out_dir.empty()) {
    return run_metric_world(world, options, out, started, interrupted, report, nullptr, progress_fd);
  }
  FilesRecorder recorder;
  return run_metric_world(world, options, out, started, interrupted, report, &recorder, progress_fd);
}

}  // namespace app
