#pragma once
// What keeps a record of a run as it goes (ninja's Status, for files): the run tells it when
// the robot is about to move, after every control step and every move, and once at the end,
// however the run ends. The run itself writes no file; report/'s FilesRecorder is the one
// that writes `--out DIR` (app/report/files_recorder.hpp).

#include <cstdint>
#include <functional>
#include <vector>

#include "app/run/evaluation.hpp"
#include "app/run/run_options.hpp"
#include "mapping/sensor_model.hpp"
#include "maze/world/maze.hpp"
#include "maze/sim/sensors.hpp"
#include "robot/cell_controller.hpp"
#include "robot/options.hpp"

namespace webots {
class Robot;
}  // namespace webots

namespace app {

struct RunSummary;

// The run as it starts: the world and the options checked, the robot placed, nothing moved.
struct RunStart {
  const RunOptions &options;
  const maze::Maze &truth;
  webots::Robot &robot;                        // its devices, as the controller reads them
  const robot::ControllerOptions &controller;  // what the controller was told
  float initial_log_odds = 0.0F;               // l(prior): the grid before any reading
};

// The run as it ended: everything a file of it shows.
struct RunEnd {
  const RunOptions &options;
  const maze::Maze &truth;
  const RunSummary &summary;
  const robot::RunResult &result;
  const mapping::SensorModel &model;
  std::function<LearnedSide(maze::Cell, maze::Side)> learned;  // the controller's belief per side
};

class RunRecorder {
 public:
  virtual ~RunRecorder() = default;
  // Before the robot moves. Throws common::InputError when the record cannot be kept (an
  // output directory that cannot be made, an output that is one of the inputs).
  virtual void start(const RunStart &start) = 0;
  // Where the run's grid logs every sub-cell it writes (the recorder consumes the log), or
  // nullptr when the recorder does not need it. Asked once, after start().
  virtual std::vector<std::uint32_t> *grid_changes() { return nullptr; }
  // After every control step, with the simulator's true pose.
  virtual void on_step(const robot::StepReport &step, const maze::sim::Pose &true_pose) = 0;
  // After the start scan and after every move into a cell.
  virtual void on_move(const robot::MoveReport &move) = 0;
  // Once, when the run has ended and been summarised. Throws common::NoSpaceError when the
  // disk is full, which the run reports after its summary.
  virtual void finish(const RunEnd &end) = 0;
};

}  // namespace app
