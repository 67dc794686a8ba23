#pragma once
// A 360-degree lidar scan of the given readings, the default lidar's limits (0.05 to 12 m),
// from (0.5, 0.5) facing north: what the scan filter and median tests feed in.

#include <numbers>
#include <vector>

#include "sensing/scan.hpp"

inline sensing::LidarScan full_circle(const std::vector<float> &ranges) {
  sensing::LidarScan s;
  s.origin = {0.5, 0.5};
  s.yaw_rad = std::numbers::pi / 2.0;
  s.fov_rad = 2.0 * std::numbers::pi;
  s.min_range_m = 0.05;
  s.max_range_m = 12.0;
  s.ranges = ranges;
  return s;
}
