#pragma once
// The files of `--out DIR` of every kind of run (app/report/outputs.hpp and
// app/report/metres_record.hpp list them), kept as the run goes: the RunObserver that prepares
// DIR (an OutputDir: refused when an output would be an input) before the robot moves, keeps
// what the files need during the run, and writes every file when it ends, with what the kind
// of run adds. A run on the cell lattice streams trace.csv and records the grid's history
// (for --snapshots and replay.html); a run in metres keeps a MetresRecord.

#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "app/report/grid_history.hpp"
#include "app/report/metres_record.hpp"
#include "app/report/output_dir.hpp"
#include "app/report/trace_writer.hpp"
#include "app/run/metric/run.hpp"
#include "app/run/report.hpp"
#include "app/run/run.hpp"
#include "app/run/run_observer.hpp"

namespace app {

class FilesRecorder final : public RunObserver {
 public:
  // Writes into options.output.out_dir (which must be set) when the run starts and ends.
  // `program_inputs`: what the kind of run reads besides the world and --robot (an mms
  // program and its arguments); `own_names`: the files it adds (marks.txt). A room run's own
  // files (metres_own_names) are always among them.
  explicit FilesRecorder(std::vector<NamedInput> program_inputs = {}, std::vector<std::string> own_names = {});

  void on_start(const RunStart &start) override;
  std::vector<std::uint32_t> *grid_changes() override;
  void on_step(const RunStep &step) override;
  // Before on_end(): what the kind of run reports and writes of its own: its report in place
  // of the maze run's (summary.json, replay.html's table) and its files (named in own_names).
  void add_own_files(Report report, std::vector<NamedFile> files);
  // Writes every file, then the kind's own; a stop signal meanwhile ends the process with
  // each file whole or absent.
  void on_end(const RunEnd &end) override;

 private:
  // What a run on the cell lattice keeps for its files.
  struct CellRecord {
    std::optional<TraceWriter> trace;
    std::optional<GridHistory> history;
    std::vector<std::uint32_t> grid_changes;  // the grid's change log, for the history
  };
  void write_cell_files(const RunOptions &options, const CellRunEnd &end);

  std::vector<NamedInput> program_inputs_;
  std::vector<std::string> own_names_;
  std::optional<Report> own_report_;
  std::vector<NamedFile> own_files_;
  std::optional<OutputDir> dir_;
  std::optional<CellRecord> cell_;
  std::optional<MetresRecord> metres_;
};

// run_world() with the files of options.output.out_dir written by a FilesRecorder when it is
// set (and controls has no observer of its own).
RunSummary run_and_write(const RunOptions &options, std::ostream &out, const RunControls &controls = {});
// run_metric_world() with options.output.out_dir's files written by a FilesRecorder when it is
// set, and the progress line on progress_fd when not -1.
MetricRunSummary run_metric_and_write(const maze::World &world, const RunOptions &options, std::ostream &out,
                                      std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now(),
                                      robot::StopPoll interrupted = nullptr, Report *report = nullptr,
                                      int progress_fd = -1);

}  // namespace app
