#pragma once
// The files of `--out DIR` of a run on the cell lattice (a maze run, `plan`, an mms program's
// run), kept as the run goes (app/report/outputs.hpp lists them): a RunRecorder that prepares
// DIR (an OutputDir) before the robot moves, streams trace.csv and records the grid's history
// (for --snapshots and replay.html) during the run, and writes every file when it ends, with
// what the kind of run adds.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "app/report/grid_history.hpp"
#include "app/report/output_dir.hpp"
#include "app/report/trace_writer.hpp"
#include "app/run/report.hpp"
#include "app/run/run.hpp"
#include "app/run/run_recorder.hpp"

namespace app {

class FilesRecorder final : public RunRecorder {
 public:
  // Writes into options.output.out_dir (which must be set) when the run starts and ends.
  // `program_inputs`: what the kind of run reads besides the world and --robot (an mms
  // program and its arguments); `own_names`: the files it adds (marks.txt).
  explicit FilesRecorder(std::vector<NamedInput> program_inputs = {}, std::vector<std::string> own_names = {});

  // Prepares the directory (an OutputDir: refused when an output would be an input), opens
  // trace.csv (unless --no-trace) and the history (keeps_history()).
  void start(const RunStart &start) override;
  std::vector<std::uint32_t> *grid_changes() override;
  void on_step(const robot::StepReport &step, const maze::sim::Pose &true_pose) override;
  void on_move(const robot::MoveReport &move) override;
  // Before finish(): what the kind of run reports and writes of its own: its report in place
  // of the maze run's (summary.json, replay.html's table) and its files (named in own_names).
  void add_own_files(Report report, std::vector<NamedFile> files);
  // Writes every file (write_outputs, then the kind's own); a stop signal meanwhile ends the
  // process with each file whole or absent.
  void finish(const RunEnd &end) override;

 private:
  std::vector<NamedInput> program_inputs_;
  std::vector<std::string> own_names_;
  std::optional<Report> own_report_;
  std::vector<NamedFile> own_files_;
  std::optional<OutputDir> dir_;
  std::optional<TraceWriter> trace_;
  std::optional<GridHistory> history_;
  std::vector<std::uint32_t> grid_changes_;  // the grid's change log, for the history
};

// run_world() with the files of options.output.out_dir written by a FilesRecorder when it is
// set (and controls has no recorder of its own).
RunSummary run_and_write(const RunOptions &options, std::ostream &out, const RunControls &controls = {});

}  // namespace app
