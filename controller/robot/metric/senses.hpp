#pragma once
// What a robot in a room senses with, read into the room map (sensing/metric/map.hpp): its
// lidar, its IR or sonar ring, its bumpers or its depth rays, as its set-up's row says
// (sensing/setups.hpp: cell and ray read the lidar with the room's ray marks; pie and cone
// mark with the row's metres_range_mark; bump and depth with the pose log's marks).
// One scan reads every device at the pose the robot's own devices give, marks and applies.
// It also keeps what the last scan says of the way ahead (the nearest return within
// kAheadHalfAngle of the heading, from the robot's centre) and whether a bumper is pressed.

#include <cstddef>
#include <limits>
#include <vector>

#include "mapping/grid_types.hpp"
#include "robot/options.hpp"
#include "robot/sensor_devices.hpp"
#include "sensing/bump_depth_marks.hpp"
#include "sensing/metric/map.hpp"
#include "sensing/scan_filter.hpp"
#include "sensing/setups.hpp"

namespace robot {

// A return within this angle of the heading counts as ahead.
inline constexpr double kAheadHalfAngle_rad = 0.35;

class MetricSenses {
 public:
  // Finds the devices (common::InputError naming one the robot lacks; bump needs three
  // bumpers at 0 and +-45 deg, depth nine range sensors, as the homework's log has).
  MetricSenses(webots::Robot &robot, const ControllerOptions &options, sensing::MetricMap &map);
  void enable(int time_step_ms);

  // Reads every device at the robot's pose, marks and applies; returns the cells updated.
  std::size_t scan(mapping::Point centre, double yaw_rad, double time_s);

  // The last scan's nearest return ahead from the robot's centre, m (infinity: none).
  double clearance_ahead_m() const { return clearance_ahead_m_; }
  bool bumped() const { return bumped_; }
  // The last scan's pose and readings, as map-log reads them (bump and depth set-ups).
  const sensing::PoseStep &pose_step() const { return pose_step_; }
  // Whether a reading of nothing seen marks nothing (the cone set-up with a sonar, whose echo
  // may be lost at a slant): then the ground the body covers is what observes open floor.
  bool nothing_seen_marks_nothing() const;

 private:
  void read_ranges(mapping::Point centre, double yaw_rad);
  void find_bumpers(const std::vector<BumperMount> &mounts);
  void read_depth_mounts(const std::vector<RangeSensorMount> &mounts);
  void read_depth_rays(mapping::Point centre, double yaw_rad);

  const ControllerOptions &options_;
  sensing::MetricMap &map_;
  const sensing::SetUp &setup_;  // its row says how a scan marks the map
  sensing::BumpDepthOptions bump_depth_options_;
  SensorDevices devices_;
  int bumper_of_side_[3] = {-1, -1, -1};  // right, left, front: index into devices_.bumpers
  sensing::ScanFilter filter_;
  sensing::MetricMarks marks_;
  std::vector<sensing::RangeReading> readings_;
  sensing::PoseStep pose_step_;
  double clearance_ahead_m_ = std::numeric_limits<double>::infinity();
  bool bumped_ = false;
};

}  // namespace robot
