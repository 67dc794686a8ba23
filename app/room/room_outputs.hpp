#pragma once
// What the room run (app/room/room_run.hpp) prints and writes: the maps as text and --out
// DIR's files (the summary: app/room/room_report.hpp).

#include <cstdint>
#include <string>
#include <vector>

#include "app/room/room_run.hpp"
#include "app/report/output_dir.hpp"
#include "robot/metric_controller.hpp"
#include "sensing/metric_map.hpp"
#include "sensing/setups.hpp"

namespace app {

// The ASCII map, north row first: W at or above the threshold, . below, blank never observed,
// * the last planned path, the robot's arrow.
std::string room_ascii_map(const robot::MetricController &c, double threshold);
// 1 at or above the threshold, else 0, north row first.
std::string room_binary_map(const sensing::MetricMap &map, double threshold);
// The wave's numbers, north row first, right-aligned; "" for an empty wave.
std::string room_wave_numbers(const sensing::MetricMap &map, const std::vector<std::int32_t> &wave);
// The files a room run adds to the run's: logodds.csv, thresholded.txt, wave.png (and the
// snapshots' NAME_wave.png).
const std::vector<std::string> &room_own_names();

// logodds.csv: every cell's log-odds to 6 decimals, comma-separated, north row first.
std::string room_logodds_csv(const sensing::MetricMap &map);
// map.pgm of the map: one pixel a cell, north up (pgm_pixel's tones).
std::string room_pgm(const sensing::MetricMap &map);

}  // namespace app
