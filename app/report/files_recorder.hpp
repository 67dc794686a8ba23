#pragma once
// The files of `run --out DIR` kept as the run goes (app/report/outputs.hpp lists them): a
// RunRecorder that prepares DIR before the robot moves, streams trace.csv and records the
// grid's history (for --snapshots and replay.html) during the run, and writes every file
// when it ends.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <vector>

#include "app/report/grid_history.hpp"
#include "app/report/trace_writer.hpp"
#include "app/run/run.hpp"
#include "app/run/run_recorder.hpp"

namespace app {

class FilesRecorder final : public RunRecorder {
 public:
  // Writes into options.output.out_dir (which must be set) when the run starts and ends.
  FilesRecorder() = default;

  // Prepares the directory (prepare_output_dir), refuses it when an output would be the
  // world file, opens trace.csv (unless --no-trace) and the history (keeps_history()).
  void start(const RunStart &start) override;
  std::vector<std::uint32_t> *grid_changes() override;
  void on_step(const robot::StepReport &step, const maze::sim::Pose &true_pose) override;
  void on_move(const robot::MoveReport &move) override;
  // Writes every file (write_outputs); a stop signal meanwhile ends the process with each
  // file whole or absent.
  void finish(const RunEnd &end) override;

 private:
  std::optional<TraceWriter> trace_;
  std::optional<GridHistory> history_;
  std::vector<std::uint32_t> grid_changes_;  // the grid's change log, for the history
};

// run_world() with the files of options.output.out_dir written by a FilesRecorder when it is
// set (and controls has no recorder of its own).
RunSummary run_and_write(const RunOptions &options, std::ostream &out, const RunControls &controls = {});

}  // namespace app
