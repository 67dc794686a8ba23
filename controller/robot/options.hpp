#pragma once
// What the controller is told: the maze's geometry, start and goals (never the walls), the
// set-up and its options, the robot's description (wheels, device names, sensor mounts),
// as the composition root or a .wbt's controllerArgs give them.

#include <optional>
#include <string>
#include <vector>

#include "explore/strategies.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "robot/drive.hpp"
#include "sensing/range_models.hpp"
#include "sensing/scan_filter.hpp"
#include "sensing/setups.hpp"

namespace robot {

// Where a range sensor sits and what it can see, as a robot's description (URDF-like) gives
// it: the composition root fills this in, the controller never asks the world.
struct RangeSensorMount {
  std::string name;              // a webots::DistanceSensor whose value is metres
  double angle_rad = 0.0;        // direction relative to the heading, counter-clockwise positive
  double offset_m = 0.0;         // from the robot's centre along that direction
  double max_range_m = 0.0;      // a value at or beyond this saw nothing
  double aperture_rad = 0.0;     // full beam width (cone model)
  double range_error = 0.0;      // relative distance error (cone model)
  // A depth camera's pixel (room --model depth): the ray leaves this point of the robot's
  // frame (x forward, y left, m) instead of the rim, and with axial the value is the depth
  // along the heading (range cos angle_rad), a value at max range still nothing seen.
  std::optional<mapping::Point> origin = std::nullopt;
  bool axial = false;
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
  // After exploring (ended "done"), the micromouse speed run: back to the start if the
  // search ended elsewhere, then from the start to the nearest goal on the shortest path
  // through known-open sides (explore/shortest_path.hpp), without mapping. Needs a goal.
  bool speed_run = false;
};

// Throws common::InputError when an option is unusable: each concern's own validate, and
// the devices the set-up reads (bumpers, range sensors) present in the description, and a
// goal for the speed run.
void validate(const ControllerOptions &options);

}  // namespace robot
