#pragma once
// The maps of a run in metres (app/run/metric/run.hpp) as text, as the room command prints
// them (the summary: app/run/metric/run_report.hpp).

#include <cstdint>
#include <string>
#include <vector>

#include "robot/metric/controller.hpp"
#include "sensing/metric/map.hpp"

namespace app {

// The ASCII map, north row first: W at or above the threshold, . below, blank never observed,
// * the last planned path, the robot's arrow.
std::string metric_ascii_map(const robot::MetricController &c, double threshold);
// 1 at or above the threshold, else 0, north row first.
std::string metric_binary_map(const sensing::MetricMap &map, double threshold);
// The wave's numbers, north row first, right-aligned; "" for an empty wave.
std::string metric_wave_numbers(const sensing::MetricMap &map, const std::vector<std::int32_t> &wave);

}  // namespace app
