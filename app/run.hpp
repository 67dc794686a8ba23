#pragma once
// `maze_mapper run`: one world, one simulated robot, one controller, printed as it goes.
//
// This is the composition root of a run: it loads the true maze, builds the embedded
// simulator around it, tells the controller only what a maze lab tells a student (size, cell
// size, origin, start, goals — never the walls), runs it, and scores the learned map
// against the truth.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

#include "app/evaluation.hpp"
#include "common/random.hpp"
#include "maze/maze.hpp"
#include "explore/strategies.hpp"
#include "mapping/models.hpp"
#include "mapping/sensor_model.hpp"
#include "robot/cell_controller.hpp"

namespace app {

struct RunOptions {
  std::string world;                    // the path as the user gave it
  int subcells = 3;                     // --subcells K
  mapping::ModelKind model = mapping::ModelKind::cell;
  int hit_depth = 0;                    // --hit-depth (ray model)
  bool ignore_no_return = false;        // --ignore-no-return (ray model)
  explore::StrategyKind strategy = explore::StrategyKind::dfs;
  std::string robot = "hambot";
  std::uint64_t seed = common::kDefaultSeed;
  std::optional<double> noise;          // --noise: lidar noise as a fraction of max range
  mapping::SensorModelOptions sensor;
  bool ascii = false;
  std::optional<char> unknown;
  bool quiet = false;                   // final map and summary only
  std::int64_t max_steps = 2'000'000;
  // Simulated faults (maze::sim::SimulationOptions has their meaning); validated there.
  double dropout = 0.0;      // --dropout
  double spikes = 0.0;       // --spikes
  std::string stuck_bumper;  // --stuck-bumper
  double wheel_slip = 0.0;   // --wheel-slip
};

struct RunSummary {
  robot::EndReason reason = robot::EndReason::done;
  std::string message;
  int width = 0;
  int height = 0;
  std::int64_t steps = 0;
  int moves = 0;
  int visited = 0;
  bool reached_goal = false;  // the run ended on one of the maze's goal cells
  MapScore score;
  double sim_time_s = 0.0;
  double wall_time_ms = 0.0;
};

// Loads options.world (its warnings go to stderr) and runs it with run_maze().
// Throws common::InputError for unusable options or world files.
RunSummary run_world(const RunOptions &options, std::ostream &out);

// Runs one maze and writes the progress (unless quiet), the final map and the summary
// block to out; options.world only names it in the summary. Throws common::InputError for
// unusable options.
RunSummary run_maze(const RunOptions &options, const maze::Maze &truth, std::ostream &out);

// The summary block (DESIGN §9), one `key: value` a line.
std::string format_summary(const RunOptions &options, const RunSummary &summary);

// The exit status a run ends with: 0 when it ended as planned (done, or stopped at
// --max-steps), 1 when the robot could not make progress or the simulation ended first.
int exit_status(const RunSummary &summary);

}  // namespace app
