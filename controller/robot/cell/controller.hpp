#pragma once
// The robot's controller: a Webots-style loop that moves cell by cell, maps into the 4D
// log-odds grid and asks a strategy where to go next. It sees the world only through the
// webots:: device API (public members only), so it compiles unchanged against a real Webots.
//
// The loop: scan on arrival and do what the set-up does on arriving (robot/arrival.hpp),
// report the move, ask the strategy for a heading, turn to it and drive one cell
// (robot/drive.hpp), again until the strategy has nothing left; then, when asked, the speed
// run (robot/options.hpp). What it senses with and how a scan reaches the grid: robot/senses.hpp. The
// controller is told the maze size, cell size, origin, K, start cell and heading, and goal
// cells - never the walls.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "explore/shortest_path.hpp"
#include "explore/visits.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "robot/control_loop.hpp"
#include "robot/drive.hpp"
#include "robot/options.hpp"

namespace webots {
class Robot;
}

namespace robot {

// incomplete: the strategy had nothing left to do, but a side of a visited cell leading to a
// cell never visited stayed unknown however the robot looked at it (the controller's own
// finding), or - set by the composition root, which holds the truth - reachable cells were
// never visited.
// wrong_map: set by the composition root only: the controller believed it was done, but a
// side of a cell it visited is learned otherwise than the truth has it.
enum class EndReason { done, max_steps, no_progress, simulation_ended, stopped, incomplete, wrong_map };
// "done", "max steps", "no progress", "simulation ended", "stopped", "incomplete", "wrong map"
std::string_view to_string(EndReason reason);

// What the observer sees after the start scan and after every move into a cell.
struct MoveReport {
  std::int64_t step = 0;      // control steps so far
  int moves = 0;              // cell-to-cell moves so far (0 at the start)
  double sim_time_s = 0.0;
  mapping::Cell cell;
  mapping::Heading heading = mapping::Heading::north;
  bool new_cell = false;      // first time in this cell (always true at the start)
  const mapping::OccupancyGrid *grid = nullptr;
  const explore::Visits *visits = nullptr;
};

using Observer = std::function<void(const MoveReport &)>;

// What the step observer sees once per control step, after robot.step() returned and after
// the scan that step ended with (so subcells_updated counts that scan's updates).
struct StepReport {
  std::int64_t step = 0;       // 1-based control step
  double sim_time_s = 0.0;
  mapping::Cell cell;          // the cell the robot is in (the one it left, until it arrives)
  mapping::Heading heading = mapping::Heading::north;  // last heading reached (the old one while turning)
  Action action = Action::start;
  std::size_t subcells_updated = 0;  // by the scan at the end of this step (0: no scan)
  const mapping::OccupancyGrid *grid = nullptr;
  const explore::Visits *visits = nullptr;
};

// Returns false to stop the run: it then ends with EndReason::stopped before the next step.
using StepObserver = std::function<bool(const StepReport &)>;

// Optional hooks of a run; an empty hook costs one test per step.
struct RunHooks {
  Observer on_move;        // after the start scan and after every move into a cell
  StepObserver on_step;    // after every control step
  StopPoll stop_requested = nullptr;  // before every control step (ControlLoop): true stops the run
  // When set: the grid logs every sub-cell it writes here during the run
  // (OccupancyGrid::set_change_log), for the observer to read and empty.
  std::vector<std::uint32_t> *grid_changes = nullptr;
};

// The speed run, when one was made (cells > 0 or time_s set).
struct SpeedRun {
  int return_cells = 0;          // driven back to the start first (the search ended elsewhere)
  int cells = 0;                 // from the start to the goal
  int turns = 0;                 // changes of heading on that path (explore::turns)
  std::optional<double> time_s;  // simulated seconds from the start to the goal
};

struct RunResult {
  EndReason reason = EndReason::done;
  std::string message;        // for no_progress: what stalled, where; for stopped: why;
                              // for incomplete: the sides left unknown
  std::int64_t steps = 0;
  int moves = 0;
  int visited = 0;                   // cells visited by the search (the speed run maps nothing)
  double sim_time_s = 0.0;
  mapping::OccupancyGrid grid;
  explore::Visits visits;
  std::vector<mapping::Cell> path;  // cells in order of arrival, start first
  double explore_time_s = 0.0;       // simulated time when exploring (the search) ended
  // When the robot was given goals: the start-to-goal shortest paths on the walls learned
  // when the search ended, known and optimistic (explore/shortest_path.hpp).
  std::optional<explore::ShortestPathProof> shortest;
  // Speed run: time_s is nothing when none was made (not asked, exploring did not end
  // "done", or no known path to the goal).
  SpeedRun speed_run;
  // When a speed run followed the search: the cells the search visited (and so scanned in);
  // `visits` then holds the speed run's cells too, which it drives through without looking.
  std::optional<explore::Visits> search_visits;
};

class CellController {
 public:
  // Validates the options (common::InputError) and finds the devices; throws
  // common::InputError naming a required device the robot lacks. The robot must outlive
  // the controller.
  CellController(webots::Robot &robot, const ControllerOptions &options);
  ~CellController();
  CellController(const CellController &) = delete;
  CellController &operator=(const CellController &) = delete;

  // Runs until the strategy is done, max_steps, no progress, or the simulation ends.
  // Call once.
  RunResult run(const Observer &observer = {});
  RunResult run(const RunHooks &hooks);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace robot
