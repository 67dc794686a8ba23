#pragma once
// What watches a run as it goes (ninja's Status): the run tells its observer once before the
// robot moves, after every control step, and once at the end, however the run ends. The run
// itself writes no file and draws no progress: report/'s FilesRecorder writes `--out DIR`
// (app/report/files_recorder.hpp) for every kind of run. What every kind tells is one event
// with a part for its kind: a run on the cell lattice (`run`, `plan`, an mms program) fills
// `cell`, a run in metres (`room`) fills `metres`; an observer reads the part it draws.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/run/evaluation.hpp"
#include "app/run/report.hpp"
#include "app/run/run_options.hpp"
#include "mapping/sensor_model.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/world/geometry.hpp"
#include "maze/world/maze.hpp"
#include "maze/world/truth_raster.hpp"
#include "robot/cell/controller.hpp"
#include "robot/metric/controller.hpp"
#include "robot/options.hpp"
#include "sensing/setups.hpp"

namespace webots {
class Robot;
}  // namespace webots

namespace app {

struct RunSummary;

// ---- the run as it starts: the world and the options checked, the robot placed ----

struct CellRunStart {
  const maze::Maze &truth;
  const robot::ControllerOptions &controller;  // what the controller was told
  float initial_log_odds = 0.0F;               // l(prior): the grid before any reading
};

struct MetresRunStart {
  const sensing::SetUp &setup;
  const robot::MetricOptions &strategy;  // as the run uses them (strategy, time limit, seed set)
  const maze::Arena &arena;
  const sensing::MetricMap &map;         // the map the run fills; outlives the run
  const maze::ArenaPose &start;
  const maze::TruthRaster &truth;        // at the map's resolution: what the map is scored against
  double threshold = 0.0;                // log-odds drawn occupied at or above
};

struct RunStart {
  const RunOptions &options;
  webots::Robot &robot;  // its devices, as the controller reads them
  const CellRunStart *cell = nullptr;
  const MetresRunStart *metres = nullptr;
};

// ---- each control step ----

struct RunStep {
  std::int64_t step = 0;       // 1-based, as the console's "step N"
  double time_s = 0.0;         // simulated
  maze::sim::Pose true_pose;   // the simulator's
  const robot::StepReport *cell = nullptr;       // a cell controller's step
  const robot::MoveReport *arrival = nullptr;    // ... that ended a move into a cell (or the start scan)
  const robot::MetricController *metres = nullptr;
  // The snapshots due at this step ("snapshots/t15s" for --snapshot-at 15, "snapshots/step50").
  std::vector<std::string> snapshots;
};

// A step's event with no kind's part yet.
inline RunStep step_at(std::int64_t step, double time_s, const maze::sim::Pose &true_pose) {
  RunStep at;
  at.step = step;
  at.time_s = time_s;
  at.true_pose = true_pose;
  return at;
}

// ---- the run as it ended, summarised ----

struct CellRunEnd {
  const maze::Maze &truth;
  const RunSummary &summary;
  const robot::RunResult &result;
  const mapping::SensorModel &model;
  std::function<LearnedSide(maze::Cell, maze::Side)> learned;  // the controller's belief per side
};

struct MetresRunEnd {
  const robot::MetricController &controller;
  const maze::TruthRaster &truth;  // at the map's resolution
  const Report &report;
};

struct RunEnd {
  const RunOptions &options;
  const CellRunEnd *cell = nullptr;
  const MetresRunEnd *metres = nullptr;
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  // Before the robot moves. Throws common::InputError when the observer cannot do its part (an
  // output directory that cannot be made, an output that is one of the inputs).
  virtual void on_start(const RunStart &start) = 0;
  // Where a cell run's grid logs every sub-cell it writes (the observer consumes the log), or
  // nullptr when the observer does not need it. Asked once, after on_start().
  virtual std::vector<std::uint32_t> *grid_changes() { return nullptr; }
  virtual void on_step(const RunStep &step) = 0;
  // Once, when the run has ended and been summarised. Throws common::NoSpaceError when the
  // disk is full, which the run reports after its summary.
  virtual void on_end(const RunEnd &end) = 0;
};

}  // namespace app
