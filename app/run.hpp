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
#include <string_view>

#include "app/evaluation.hpp"
#include "common/random.hpp"
#include "maze/maze.hpp"
#include "maze/sim/profile.hpp"
#include "maze/world.hpp"
#include "explore/strategies.hpp"
#include "sensing/setups.hpp"
#include "sensing/range_models.hpp"
#include "mapping/sensor_model.hpp"
#include "robot/cell_controller.hpp"

namespace app {

struct RunOptions {
  std::string world;                    // the path as the user gave it
  maze::WorldOverrides world_overrides; // --cell-size, --start, --goal
  int subcells = 3;                     // --subcells K
  sensing::ModelKind model = sensing::ModelKind::cell;
  int hit_depth = 0;                    // --hit-depth (ray model)
  bool ignore_no_return = false;        // --ignore-no-return (ray model)
  std::optional<double> threshold;      // --threshold L: occupied when log-odds >= L
  sensing::RangeModelOptions range_model;  // --pie-beta, --pie-alpha (pie model)
  explore::StrategyKind strategy = explore::StrategyKind::dfs;
  std::string robot = "hambot";         // --robot: a built-in profile's name or a FILE.json
  std::uint64_t seed = common::kDefaultSeed;
  std::optional<double> noise;          // --noise: lidar noise as a fraction of max range
  mapping::SensorModelOptions sensor;
  bool ascii = false;
  std::optional<char> unknown;
  bool quiet = false;                   // final map and summary only
  // --max-steps: control steps before the run stops; none: max_steps_for(maze), which no
  // complete exploration reaches (dfs and frontier take about 200 steps a cell).
  std::optional<std::int64_t> max_steps;
  std::string out_dir;                  // --out DIR: map.pgm, map.yaml, map.png, summary.json, trace.csv
  bool color = false;                   // ANSI colours in the map (a terminal, no --no-color)
  bool animate = false;                 // --animate: the map redrawn in place
  double fps = 30.0;                    // --fps
  double speed = 10.0;                  // --speed: simulated seconds per wall-clock second
  bool step = false;                    // --step: wait for Enter (or q) after each cell
  // Wavefront planning on the learned grid after the run (--plan-to; `plan` sets both ends):
  // from plan_from (default: where the robot ended) to plan_to.
  std::optional<mapping::Cell> plan_from;
  std::optional<mapping::Cell> plan_to;
  int dilate = 0;                       // --dilate N sub-cells
  bool plan_only = false;               // `plan`: print only the planned map and the summary
  bool speed_run = false;               // --speed-run: drive the planned path back to the start
  // Simulated faults (maze::sim::SimulationOptions has their meaning); validated there.
  double dropout = 0.0;      // --dropout
  double spikes = 0.0;       // --spikes
  std::string stuck_bumper;  // --stuck-bumper
  double wheel_slip = 0.0;   // --wheel-slip
};

// The robot a model runs on when --robot is not given: its set-up's default robot.
std::string_view default_robot(sensing::ModelKind model);

// What a run reads besides its options (all optional).
struct RunControls {
  std::istream *in = nullptr;           // --step reads lines here
  std::ostream *prompt = nullptr;       // --step's prompt, when set
  bool (*interrupted)() = nullptr;      // polled every step: true stops the run (Ctrl-C)
  int terminal_fd = -1;                 // --animate: the screen size comes from here
};

// What the planner found, for the summary.
struct PlanSummary {
  mapping::Cell from;
  mapping::Cell to;
  bool found = false;
  int length_subcells = 0;
  int length_cells = 0;
};

struct RunSummary {
  robot::EndReason reason = robot::EndReason::done;
  std::string message;
  int width = 0;
  int height = 0;
  std::int64_t steps = 0;
  int moves = 0;
  int visited = 0;
  bool reached_goal = false;  // the robot stood on one of the maze's goal cells
  MapScore score;
  double sim_time_s = 0.0;
  double wall_time_ms = 0.0;
  bool interrupted = false;             // stopped by Ctrl-C (not by q)
  std::optional<PlanSummary> plan;
  double explore_time_s = 0.0;
  std::optional<double> speed_run_time_s;
  int speed_run_cells = 0;
};

// Loads options.world with options.world_overrides (its warnings go to stderr) and runs it with run_maze().
// Throws common::InputError for unusable options or world files.
RunSummary run_world(const RunOptions &options, std::ostream &out);
// Likewise, with --step input, Ctrl-C and --animate. With out_dir set, the directory is
// prepared (prepare_output_dir) after the world and options are checked and before the
// robot moves, and the files are written when the run ends, however it ends.
RunSummary run_world(const RunOptions &options, std::ostream &out, const RunControls &controls);

// Runs one maze and writes the progress (unless quiet), the final map and the summary
// block to out; options.world only names it in the summary. Throws common::InputError for
// unusable options.
RunSummary run_maze(const RunOptions &options, const maze::Maze &truth, std::ostream &out,
                    const RunControls &controls = {});

// What a maze lab tells the robot's programmer (DESIGN §2), as run_maze gives it to the
// controller and a .wbt's controllerArgs carry it: the maze's size, cell size, origin, start
// and goals, the run's mapping options and the robot's description from its profile (wheels,
// device names, sensor mounts) - never the walls. Not validated.
robot::ControllerOptions controller_options(const RunOptions &options, const maze::Maze &maze,
                                            const maze::sim::RobotProfile &profile);

// True when the robot has the devices the set-up reads (a lidar, bumpers, range sensors).
bool has_devices(const maze::sim::RobotProfile &profile, const sensing::SetUp &setup);

// Throws common::InputError when the robot lacks what options.model reads (a lidar, bumpers
// or range sensors), naming the robots that have it.
void require_sensors(const RunOptions &options, const maze::sim::RobotProfile &profile);

// The step limit of a run without --max-steps: 1,000 control steps a cell, at least 100,000.
std::int64_t max_steps_for(const maze::Maze &maze);

// The summary block (DESIGN §9), one `key: value` a line.
std::string format_summary(const RunOptions &options, const RunSummary &summary);

// The exit status a run ends with: 0 when it ended as planned (done, or stopped at
// --max-steps, or quit with q), 130 when stopped by Ctrl-C (as a shell reports SIGINT), 1 when
// the robot could not make progress or the simulation ended first.
int exit_status(const RunSummary &summary);

}  // namespace app
