#pragma once
// What the room run (app/room/room_run.hpp) prints and writes: the maps as text and --out
// DIR's files (the summary: app/room/room_report.hpp).

#include <cstdint>
#include <string>
#include <vector>

#include "app/room/room_run.hpp"
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
// A file the run made, by its name in the output folder (e.g. "snapshots/t15s.png").
struct RoomFile {
  std::string name;
  std::string bytes;
};

// The names a room run may write in its --out dir: every run's (run_output_names: the core
// files, summary.json, trace.csv, map.png, truth.png, replay.html, snapshots/...) and the
// room's own, logodds.csv, thresholded.txt and wave.png; "snapshots/" stands for that
// folder's files.
std::vector<std::string> room_output_names();

// Writes trace.csv, logodds.csv, thresholded.txt, map.pgm + map.yaml, summary.json and the
// pictures (map.png, wave.png, snapshots/...) into dir, each atomically.
void write_room_outputs(const std::string &dir, const sensing::MetricMap &map, const std::string &trace,
                        const std::string &summary_json, double threshold, const std::vector<RoomFile> &pictures);

}  // namespace app
