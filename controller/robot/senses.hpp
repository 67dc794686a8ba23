#pragma once
// What the robot senses with, as its set-up's row says (sensing/setups.hpp): a lidar,
// bumpers or a ring of range sensors, and one scan of them into the grid. A lidar scan is
// read from Lidar::getRangeImage into a sensing::LidarScan taken where the robot is (GPS,
// else the cell's centre) facing its IMU yaw, filtered (sensing::ScanFilter, against the
// scan before it when that was taken at an earlier step), marked by the set-up's model and
// applied with the sensor model's increments. Range and bump readings go to the world frame
// through their mounts (RangeSensorMount, BumperMount) and are marked and applied likewise.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "robot/drive.hpp"
#include "robot/options.hpp"
#include "robot/sensor_devices.hpp"
#include "sensing/range_models.hpp"
#include "sensing/scan.hpp"
#include "sensing/scan_filter.hpp"
#include "sensing/setups.hpp"

namespace robot {

class Senses {
 public:
  // Finds the devices the set-up reads (common::InputError naming one the robot lacks). The
  // robot, drive, grid and model must outlive the Senses.
  Senses(webots::Robot &robot, const ControllerOptions &options, const Drive &drive, mapping::OccupancyGrid &grid,
         const mapping::SensorModel &model);

  void enable(int time_step_ms);
  // Control steps a whole revolution of a rotating lidar takes (0 for a fixed one, or none).
  int revolution_steps() const { return revolution_steps_; }

  // One scan from cell c at control step `step`: read, mark, apply.
  void scan(mapping::Cell c, std::int64_t step);
  // Lidar sub-cells updated since the last call (the step report's count).
  std::size_t take_lidar_updates();
  // What the last scan, taken in cell c, says of c's side h: the cell model's reading of a
  // lidar scan (sensing::read_cell_side), or of range readings (sensing::read_range_side);
  // unknown before the first scan and for bumpers.
  mapping::SideState reads_side(mapping::Cell c, mapping::Heading h) const;
  // What the last lidar scan, when it was taken in cell `from`, sees of side h of cell c
  // further along h (sensing::read_side_ahead: a side past the lidar's reach is unknown);
  // unknown without such a scan, and for set-ups without a lidar.
  mapping::SideState sees_side_ahead(mapping::Cell from, mapping::Cell c, mapping::Heading h) const;

  // Bumpers: the readings now, marked (not applied); true when one is pressed.
  bool gather_bumps(mapping::Cell c);
  // Applies the bump marks gathered so far.
  void apply_bumps();

 private:
  mapping::Point position(mapping::Cell c) const;
  // A point offset_m from the robot's centre along angle_rad relative to its heading.
  mapping::Point mounted(mapping::Point centre, double angle_rad, double offset_m) const;
  void scan_lidar(sensing::LidarMark mark, mapping::Cell c, std::int64_t step);
  void scan_ranges(sensing::RangeMark mark, mapping::Cell c);

  const ControllerOptions &options_;
  const sensing::SetUp &setup_;
  const Drive &drive_;
  mapping::OccupancyGrid &grid_;
  const mapping::SensorModel &model_;

  SensorDevices devices_;
  int revolution_steps_ = 0;

  mapping::ScanUpdate update_;
  sensing::ScanFilter filter_;
  std::optional<sensing::LeveledUpdate> leveled_;  // range and bump models
  std::vector<sensing::BumpReading> bump_readings_;
  std::vector<sensing::RangeReading> range_readings_;
  std::size_t lidar_updates_ = 0;
  // The lidar's last raw scan (for the filter's repeated-view rule), its ranges owned here.
  sensing::LidarScan previous_scan_;
  std::vector<float> previous_ranges_;
  std::int64_t previous_scan_step_ = 0;
  mapping::Cell previous_scan_cell_{};
};

}  // namespace robot
