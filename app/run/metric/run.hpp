#pragma once
// `maze_mapper room WORLD`: a robot in a room (robot/metric/controller.hpp) mapping onto a
// numCells grid (sensing/metric/map.hpp) in the embedded simulator, and what people look at:
// the ASCII map (W occupied, . free, blank never observed, * the last planned path, the
// robot's arrow), snapshots at simulated times and at control steps, the wavefront's numbers,
// the trajectory, the thresholded binary map and the summary, which scores the map against
// the truth rasterised at the map's resolution. The run itself writes no file: it
// tells a RunObserver (app/run/run_observer.hpp), as every kind of run does, and report/'s
// FilesRecorder writes --out DIR.
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
#include "app/run/run_observer.hpp"
#include "app/run/run_options.hpp"
#include "mapping/sensor_model.hpp"
#include "maze/world/geometry.hpp"
#include "maze/world/truth_raster.hpp"
#include "maze/world/world.hpp"
#include "maze/sim/simulation.hpp"
#include "explore/metric/frontier_groups.hpp"
#include "robot/metric/controller.hpp"
#include "sensing/bump_depth_marks.hpp"
#include "sensing/range_models.hpp"
#include "sensing/metric/map.hpp"
#include "sensing/setups.hpp"

namespace app {

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
  double path_length_m = 0.0;            // the robot's true centre, step to step
  std::int64_t coverage_final_step = 0;  // the step the last reachable free cell observed was first observed
  // Set-ups whose nothing-seen marks nothing (the sonar cone): frontier's sweep legs, the
  // probes among them, and the cells first observed by the robot's body.
  struct BodySweep {
    std::size_t legs = 0, probes = 0, body_observed = 0;
  };
  std::optional<BodySweep> sweep;
  // frontier: what its controller said when it ended (the frontier left, why; summary.json's
  // and --verbose's, the end line says the coverage), and the groups it set aside then.
  struct FrontierEnd {
    std::string detail;
    std::size_t left_cells = 0;
    explore::FrontierSetAside set_aside;
  };
  std::optional<FrontierEnd> frontier;
  double observed_share() const {
    return reachable_free == 0 ? 1.0 : static_cast<double>(reachable_free_observed) / static_cast<double>(reachable_free);
  }
};

// The run in a loaded world (maze::load_world, --boundary already the arena's; a maze runs on
// its geometry; options.world names it): checks everything (common::InputError,
// before anything runs), runs, prints on `out`. `interrupted`, polled every control step,
// ends the run `stopped`, "interrupted by SIGINT", its summary and files written as ever.
// `report`, when not null, receives the run's report (the summary block's and summary.json's
// entries: a batch row's columns). `observer`, when not null, is told the run as it goes
// (options.output.out_dir is a FilesRecorder's: the run itself writes no file). `progress_fd`,
// when not -1, shows the progress line there (app/run/progress_line.hpp) until the run ends.
MetricRunSummary run_metric_world(const maze::World &world, const RunOptions &options, std::ostream &out,
                     std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now(),
                     robot::StopPoll interrupted = nullptr, Report *report = nullptr,
                     RunObserver *observer = nullptr, int progress_fd = -1);
// The same in an arena given in code.
MetricRunSummary run_metric_arena(const maze::Arena &arena, const RunOptions &options, std::ostream &out,
                        std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now(),
                        robot::StopPoll interrupted = nullptr, Report *report = nullptr,
                        RunObserver *observer = nullptr, int progress_fd = -1);
// 0: done, goal reached, every waypoint reached, wander's time limit; 128 + the signal when
// interrupted; 1 otherwise.
int metric_run_exit_status(const MetricRunSummary &summary);

}  // namespace app
