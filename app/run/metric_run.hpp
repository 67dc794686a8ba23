#pragma once
// `maze_mapper room WORLD`: a robot in a room (robot/metric_controller.hpp) mapping onto a
// numCells grid (sensing/metric_map.hpp) in the embedded simulator, and what people look at:
// the ASCII map (W occupied, . free, blank never observed, * the last planned path, the
// robot's arrow), snapshots at simulated times and at control steps, the wavefront's numbers,
// the trajectory, the thresholded binary map and the summary, which scores the map against
// the truth rasterised at the map's resolution. The run itself writes no file: a
// MetricRunRecorder keeps the record (report/'s MetricFilesRecorder writes --out DIR:
// app/report/metric_files_recorder.hpp), as a RunRecorder does for a run on the cell lattice.
//
// The truth of a cell is its centre: inside a solid (a wall, an obstacle) or outside the
// world is occupied, else free; the reachable free cells are the free cells 4-connected to
// the start's.

#include <chrono>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "app/run/report.hpp"
#include "mapping/sensor_model.hpp"
#include "maze/world/arena.hpp"
#include "maze/world/truth_raster.hpp"
#include "maze/world/world.hpp"
#include "maze/sim/simulation.hpp"
#include "robot/metric_controller.hpp"
#include "sensing/bump_depth_marks.hpp"
#include "sensing/range_models.hpp"
#include "sensing/metric_map.hpp"
#include "sensing/setups.hpp"

namespace app {

struct MetricRunOptions {
  std::string world;
  robot::MetricOptions room;
  std::optional<int> cells_x, cells_y;        // --cells X,Y
  std::optional<double> resolution_m;         // --resolution M (default 0.1)
  std::string robot;                          // --robot (default: the set-up's robot)
  std::optional<mapping::Point> start;        // --start X,Y (default: the world's start)
  std::optional<double> start_yaw_deg;
  mapping::SensorModelOptions sensor;
  sensing::ModelOptions model;                // kind: --model (default ray)
  sensing::RangeModelOptions range_model;
  // --model depth: how the depth rays report (range along the ray, or axial depth along the
  // heading) and where they leave from (robot frame, m; none: the rim, the range from the centre).
  sensing::DepthReading depth_reading = sensing::DepthReading::range;
  std::optional<mapping::Point> depth_origin;
  std::optional<double> threshold;            // log-odds drawn W at or above (default 0; bump/depth -0.5)
  std::vector<double> snapshots_at_s;
  std::vector<std::int64_t> snapshot_steps;
  std::string out_dir;                        // --out DIR: MetricFilesRecorder writes it (run_metric_and_write)
  bool quiet = false;                         // no maps, the summary only
  maze::sim::SimulationOptions simulation;
  std::optional<std::int64_t> max_steps;
};

// The run as it starts: everything checked, the map empty, nothing moved.
struct MetricRunStart {
  const MetricRunOptions &options;
  const sensing::SetUp &setup;
  const robot::MetricOptions &room;  // the strategy's options as the run uses them
  const maze::Arena &arena;
  const sensing::MetricMap &map;     // the map the run fills; outlives the recorder's use
  const maze::ArenaPose &start;
  double threshold = 0.0;            // log-odds drawn occupied at or above
};

// The run as it ended, scored and summarised.
struct MetricRunEnd {
  const robot::MetricController &controller;
  const maze::TruthRaster &truth;  // at the map's resolution
  const Report &report;
};

// What keeps a record of a run in metres as it goes: told once before the robot moves, after
// every control step, at each snapshot the run prints, and once at the end.
class MetricRunRecorder {
 public:
  virtual ~MetricRunRecorder() = default;
  // Throws common::InputError when the record cannot be kept (an output folder that cannot
  // be made, an output that is one of the inputs), before the robot moves.
  virtual void start(const MetricRunStart &start) = 0;
  virtual void on_step(const robot::MetricController &c) = 0;
  // `name`: "snapshots/t15s" (--snapshot-at), "snapshots/step50" (--snapshot-steps).
  virtual void on_snapshot(const robot::MetricController &c, const std::string &name) = 0;
  // After the summary is printed. Throws common::NoSpaceError when the disk is full.
  virtual void finish(const MetricRunEnd &end) = 0;
};

struct MetricRunSummary {
  robot::MetricEnding ending = robot::MetricEnding::done;
  bool interrupted = false;  // stopped by a signal
  std::string message;
  std::int64_t steps = 0;
  double sim_time_s = 0.0;
  double wall_time_ms = 0.0;
  int cells_x = 0, cells_y = 0;
  double cell_m = 0.0;
  std::size_t cells_right = 0, cells_total = 0;  // thresholded map against the truth, every cell
  std::size_t observed_cells_right = 0, observed_cells = 0;
  std::size_t reachable_free = 0, reachable_free_observed = 0;
  // Set-ups whose nothing-seen marks nothing (the sonar cone): frontier's sweep legs, the
  // probes among them, and the cells first observed by the robot's body.
  struct BodySweep {
    std::size_t legs = 0, probes = 0, body_observed = 0;
  };
  std::optional<BodySweep> sweep;
  double observed_share() const {
    return reachable_free == 0 ? 1.0 : static_cast<double>(reachable_free_observed) / static_cast<double>(reachable_free);
  }
};

// The run in a loaded world (maze::load_world, --boundary already the arena's; a maze runs on
// its geometry; options.world names it): checks everything (common::InputError,
// before anything runs), runs, prints on `out`. `interrupted`, polled every control step,
// ends the run `stopped`, "interrupted by SIGINT", its summary and files written as ever.
// `report`, when not null, receives the run's report (the summary block's and summary.json's
// entries: a batch row's columns). `recorder`, when not null, is told the run as it goes
// (options.out_dir is the recorder's: the run itself writes no file).
MetricRunSummary run_metric_world(const maze::World &world, const MetricRunOptions &options, std::ostream &out,
                     std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now(),
                     robot::StopPoll interrupted = nullptr, Report *report = nullptr,
                     MetricRunRecorder *recorder = nullptr);
// The same in an arena given in code.
MetricRunSummary run_metric_arena(const maze::Arena &arena, const MetricRunOptions &options, std::ostream &out,
                        std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now(),
                        robot::StopPoll interrupted = nullptr, Report *report = nullptr,
                        MetricRunRecorder *recorder = nullptr);
// 0: done, goal reached, every waypoint reached, wander's time limit; 128 + the signal when
// interrupted; 1 otherwise.
int metric_run_exit_status(const MetricRunSummary &summary);

}  // namespace app
