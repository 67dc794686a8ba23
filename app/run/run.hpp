#pragma once
// `maze_mapper run`: one world, one simulated robot, one controller, printed as it goes.
//
// This is the composition root of a run: it loads the true maze, builds the embedded
// simulator around it, tells the controller only what a maze lab tells a student (size, cell
// size, origin, start, goals — never the walls), runs it, and scores the learned map
// against the truth.

#include <cstdint>
#include <exception>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/run/evaluation.hpp"
#include "app/run/live_localization.hpp"
#include "app/run/run_options.hpp"
#include "app/run/run_observer.hpp"
#include "maze/world/maze.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/simulation.hpp"
#include "mapping/sensor_model.hpp"
#include "render/ascii_map.hpp"
#include "robot/cell/controller.hpp"

namespace app {

// What a run reads besides its options (all optional).
struct RunControls {
  std::istream *in = nullptr;           // --step reads lines here
  std::ostream *prompt = nullptr;       // --step's prompt, when set
  bool (*interrupted)() = nullptr;      // polled every step: true stops the run (Ctrl-C)
  int terminal_fd = -1;                 // the terminal: --animate's screen size, the map's width (app/run/terminal.hpp)
  int progress_fd = -1;                 // where a one-line progress is drawn (app/run/terminal.hpp), -1: none
  // Watches the run (app/run/run_observer.hpp); required when options.output.out_dir is set:
  // report/'s run_and_write() gives a FilesRecorder.
  RunObserver *observer = nullptr;
  // When set, a full disk while the observer writes is kept here (common::NoSpaceError) and
  // the run returns its summary; when null it is thrown after the summary is printed.
  std::exception_ptr *no_space = nullptr;
};

// The controller's hooks that tell `observer` (none when null) each control step and each
// arrival in a cell, with the simulator's true pose, and hand it the grid's change log.
robot::RunHooks observed_hooks(RunObserver *observer, const webots::embedded::Simulation &simulation);

// What the planner found, for the summary.
struct PlanSummary {
  mapping::Cell from;
  mapping::Cell to;
  int dilate = 0;
  bool found = false;
  int length_subcells = 0;
  int length_cells = 0;
  std::vector<mapping::SubCell> path;  // the planned sub-cells, from's centre first (when found)
};

struct RunSummary {
  robot::EndReason reason = robot::EndReason::done;
  std::string message;
  int width = 0;
  int height = 0;
  std::int64_t max_steps = 0;           // the step limit in effect (--max-steps or max_steps_for)
  bool max_steps_asked = false;         // the limit is the user's (--max-steps, --time-limit), not max_steps_for's
  bool time_limited = false;            // the limit in effect is --time-limit's
  std::int64_t steps = 0;
  int moves = 0;
  int visited = 0;
  bool reached_goal = false;  // the robot stood on one of the maze's goal cells
  MapScore score;
  WrongSides wrong_sides;  // sides learned wrong where the robot looked (the verdict "wrong map")
  double sim_time_s = 0.0;
  double wall_time_ms = 0.0;
  bool interrupted = false;             // stopped by Ctrl-C (not by q)
  std::optional<PlanSummary> plan;
  double explore_time_s = 0.0;          // simulated time when the search ended
  std::optional<explore::ShortestPathProof> shortest;  // start to goal, when the maze has goals
  robot::SpeedRun speed_run;
  bool speed_run_asked = false;         // --speed-run: speed_run.time_s must then hold one
  std::optional<LocalizationSummary> localization;  // --localize: the filter's run
};

// What the summary says of the known shortest path ("105 cells start to goal, proven").
std::string describe_shortest(const explore::ShortestPathProof &proof);

// Loads options.world with options.world_overrides (its warnings go to stderr) and runs it
// with run_maze(). The options must be valid (validate()); throws common::InputError for a
// world file, or options that do not fit the world (see run_maze).
RunSummary run_world(const RunOptions &options, std::ostream &out);
// Likewise, with --step input, Ctrl-C, --animate and an observer: the observer is told the
// start after the world and options are checked and before the robot moves, and the end
// however the run ends.
RunSummary run_world(const RunOptions &options, std::ostream &out, const RunControls &controls);

// Runs one maze and writes the progress (unless quiet), the final map and the summary
// block to out; options.world only names it in the summary. The options must be valid
// (validate()); throws common::InputError when they do not fit this maze or robot: a robot
// without the sensors the model reads, a grid too large, a plan cell outside the maze, a
// stuck bumper the robot lacks. The map is scored on maze::with_solid_sides(world, K): a
// landmark standing in a cell walls the sides whose band it reaches.
RunSummary run_maze(const RunOptions &options, const maze::Maze &world, std::ostream &out,
                    const RunControls &controls = {});

// What a maze lab tells the robot's programmer (ARCHITECTURE.md), as run_maze gives it to the
// controller and a .wbt's controllerArgs carry it: the maze's size, cell size, origin, start
// and goals, the run's mapping options and the robot's description from its profile (wheels,
// device names, sensor mounts) - never the walls. Not validated.
robot::ControllerOptions controller_options(const RunOptions &options, const maze::Maze &maze,
                                            const maze::sim::RobotProfile &profile);

// The robot's description from its profile, the part of controller_options() that needs no
// maze: wheels (and a speed run's ramp), device names, sensor mounts, and the scan filter's
// range noise (noise_fraction, else the lidar's data sheet). Every other field is default.
robot::ControllerOptions robot_description(const maze::sim::RobotProfile &profile,
                                           std::optional<double> noise_fraction);

// True when the robot has the devices the set-up reads (a lidar, bumpers, range sensors).
bool has_devices(const maze::sim::RobotProfile &profile, const sensing::SetUp &setup);

// Throws common::InputError when the robot lacks what options.model reads (a lidar, bumpers
// or range sensors), naming the robots that have it.
void require_sensors(const RunOptions &options, const maze::sim::RobotProfile &profile);

// ---- the parts every driver of the cell controller shares (a maze run, an mms program's) ----

// What valid options must still fit: the robot reads what the model needs, the grid of this
// maze fits in memory, the plan's cells lie in the maze. Throws common::InputError.
void check_fit(const RunOptions &options, const maze::Maze &truth, const maze::sim::RobotProfile &profile,
               const robot::ControllerOptions &controller);
// How the maps are drawn: --subcell-columns on the terminal's width (a quiet run notes a map
// wider than the terminal), --ascii, --unknown, colour, l(prior) and --threshold.
render::MapStyle map_style(const OutputOptions &output, const mapping::SensorModel &model,
                           const robot::ControllerOptions &controller, int terminal_fd);
// The controller's belief about each side of the maze, read from the grid of `result` (which
// must outlive the function).
std::function<LearnedSide(maze::Cell, maze::Side)> learned_sides(const robot::RunResult &result,
                                                                 const render::MapStyle &style);
// The robot's side of the summary: how the run ended, its counts, the step limit in effect,
// the goal reached or not, its map scored against the truth, its times.
RunSummary robot_summary(const RunOptions &options, const maze::Maze &truth, const robot::RunResult &result,
                         const render::MapStyle &style);

// The step limit of a run without --max-steps: 1,000 control steps a cell, at least 100,000.
std::int64_t max_steps_for(const maze::Maze &maze);
std::int64_t max_steps_for(int width_cells, int height_cells);

// The summary block (docs/output.md), one `key: value` a line. Every key it prints is a key of
// summary.json (app/report/outputs.hpp).
std::string format_summary(const RunOptions &options, const RunSummary &summary);

// The exit status a run ends with: 0 when it ended as planned (done, or stopped at
// --max-steps, or quit with q), 130 when stopped by Ctrl-C (as a shell reports SIGINT), 1 when
// the robot could not make progress or the simulation ended first, or when a path was asked
// for (plan, run --plan-to) and none was found, or a --speed-run was asked and none was made.
int exit_status(const RunSummary &summary);

}  // namespace app
