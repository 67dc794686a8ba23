#pragma once
// The robot's controller: a Webots-style loop that moves cell by cell, maps with the lidar
// into the 4D log-odds grid and asks a strategy where to go next. It sees the world only
// through the webots:: device API (public members only), so this file and its source
// compile unchanged against a real Webots installation.
//
// Each move: turn in place to the heading (IMU yaw, proportional control slowing near the
// target), drive one cell (encoders; GPS when the robot has one corrects the distance and
// the lateral drift), stop at the cell centre and take one step to come to rest (a rotating
// lidar, Lidar::getFrequency() > 0: ceil(period / step) more steps at rest, so that its
// range image is one whole revolution read from here); then read the sensors (the lidar, or the range sensors / bumpers of SensingOptions), update the grid,
// and ask the strategy. With the bump model the robot first probes each side of the cell
// whose state is unknown: it turns to it and creeps forward until a bumper presses or its
// centre is half a sub-cell into the neighbouring cell, then backs to the centre. Each pass
// (forward, back) is one scan: bump readings of every step gathered, applied once. The controller is told the maze size,
// cell size, origin, K, start cell and heading, and goal cells - never the walls.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "explore/strategies.hpp"
#include "explore/visits.hpp"
#include "mapping/grid_types.hpp"
#include "sensing/setups.hpp"
#include "mapping/occupancy_grid.hpp"
#include "sensing/range_models.hpp"
#include "sensing/scan_filter.hpp"
#include "mapping/sensor_model.hpp"

namespace webots {
class Robot;
}

namespace robot {

// Device names, as a robot profile gives them (the hambot's by default).
struct DeviceNames {
  std::string left_motor = "left motor";
  std::string right_motor = "right motor";
  std::string left_encoder = "left wheel encoder";  // FAIRIS-Lite HamBot's names
  std::string right_encoder = "right wheel encoder";
  std::string imu = "imu";
  std::string gps = "gps";      // optional device: used when the robot has it
  std::string lidar = "lidar";
};

struct MotionOptions {
  int time_step_ms = 0;               // 0: the world's basic time step
  double wheel_radius_m = 0.045;      // hambot
  double axle_m = 0.184;              // distance between the wheels, hambot
  double cruise_speed_rad_s = 10.0;   // wheel speed driving (capped by the motor's maximum)
  double turn_speed_rad_s = 5.0;      // wheel speed turning in place (capped likewise)
  double yaw_tolerance_rad = 0.002;   // a turn ends within this of the target yaw
  double position_tolerance_m = 0.002;  // a drive ends within this of the cell centre
  // Proportional gains as the fraction of the remaining error to close in one time step
  // (0, 1]: smaller is smoother, 1 would aim to arrive in one step.
  double turn_gain = 0.5;
  double drive_gain = 0.5;
  // Steering while driving, rad of heading correction per metre of lateral offset (GPS).
  double lateral_gain = 2.0;
  // No progress: a move whose distance (m) or yaw (rad) changes by less than
  // stall_epsilon over stall_steps consecutive steps is reported as a failure.
  int stall_steps = 60;
  double stall_epsilon = 1e-4;
  std::int64_t max_steps = 2'000'000;  // --max-steps: control steps, the whole run
  double creep_speed_m_s = 0.1;       // bump probing: forward speed while feeling for a wall
};

// Where a range sensor sits and what it can see, as a robot's description (URDF-like) gives
// it: the composition root fills this in, the controller never asks the world.
struct RangeSensorMount {
  std::string name;              // a webots::DistanceSensor whose value is metres
  double angle_rad = 0.0;        // direction relative to the heading, counter-clockwise positive
  double offset_m = 0.0;         // from the robot's centre along that direction
  double max_range_m = 0.0;      // a value at or beyond this saw nothing
  double aperture_rad = 0.0;     // full beam width (cone model)
  double range_error = 0.0;      // relative distance error (cone model)
};

struct BumperMount {
  std::string name;              // a webots::TouchSensor, 1 when pressed
  double angle_rad = 0.0;        // centre of its arc relative to the heading
  double offset_m = 0.0;         // contact point: this far from the centre along angle_rad
};

// The sensing step of the non-lidar models (bump, depth, pie, cone).
struct SensingOptions {
  std::vector<RangeSensorMount> ranges;
  std::vector<BumperMount> bumpers;
  sensing::RangeModelOptions range_model;
};

struct ControllerOptions {
  mapping::GridGeometry geometry;      // W, H, K, cell size, origin (what the lab gives)
  mapping::Cell start;
  mapping::Heading start_heading = mapping::Heading::north;
  std::vector<mapping::Cell> goals;    // micromouse-style targets (floodfill)
  mapping::SensorModelOptions sensor;
  sensing::ModelOptions model;
  // Lidar models: what each scan goes through before it is marked (spikes and dropped
  // beams become "no information"; mapping/scan_filter.hpp).
  sensing::ScanFilterOptions scan_filter;
  // Lidar models and range rings (pie, cone): scans taken again, one control step apart,
  // while a side of the robot's cell is still unknown after arriving (a reading the filter or
  // the pie model left without information); then the robot faces each side still unknown
  // and scans up to as many times again. Only a side with evidence counts as a wall: one
  // still unknown after that, leading to a cell never visited, makes the run end incomplete.
  int max_rescans = 3;
  explore::StrategyKind strategy = explore::StrategyKind::dfs;
  MotionOptions motion;
  DeviceNames devices;
  SensingOptions sensing;            // used by the bump, depth, pie and cone models
  // --threshold: a sub-cell is occupied when its log-odds >= this (walls the explorer reads);
  // none: occupied when > 0.
  std::optional<float> occupied_threshold;
  // After exploring (ended "done"), plan a wavefront path on the learned grid from where the
  // robot is back to the start and drive it (a micromouse speed run; floodfill's use).
  bool speed_run = false;
};

// Throws common::InputError when an option is unusable (each concern's own validate, then
// the motion numbers: positive sizes and speeds, gains in (0, 1], max_steps >= 1).
void validate(const ControllerOptions &options);

// incomplete: the strategy had nothing left to do, but a side of a visited cell leading to a
// cell never visited stayed unknown however the robot looked at it (the controller's own
// finding), or - set by the composition root, which holds the truth - reachable cells were
// never visited.
enum class EndReason { done, max_steps, no_progress, simulation_ended, stopped, incomplete };
// "done", "max steps", "no progress", "simulation ended", "stopped", "incomplete"
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

// What the controller was doing in a control step.
enum class Action { start, turn, drive, rest, probe };
std::string_view to_string(Action action);  // "start", "turn", "drive", "rest", "probe" (bump)

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
};

struct RunResult {
  EndReason reason = EndReason::done;
  std::string message;        // for no_progress: what stalled, where; for stopped: why;
                              // for incomplete: the sides left unknown
  std::int64_t steps = 0;
  int moves = 0;
  int visited = 0;
  double sim_time_s = 0.0;
  mapping::OccupancyGrid grid;
  explore::Visits visits;
  std::vector<mapping::Cell> path;  // cells in order of arrival, start first
  double explore_time_s = 0.0;       // simulated time when exploring ended
  // Speed run: simulated seconds and cells driven; nothing when none was made (not asked,
  // exploring did not end "done", or no path back on the learned grid).
  std::optional<double> speed_run_time_s;
  int speed_run_cells = 0;
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
