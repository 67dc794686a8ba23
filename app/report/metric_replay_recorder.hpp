#pragma once
// replay.html for a room run (room --out): the run recorded for the one replay page
// (app/report/replay.hpp), in metres. A frame at the start (step 0, nothing learned yet), one
// every `steps_per_frame` control steps and one at the run's end: the robot's pose and time,
// and the map cells the page shows differently since the frame before: a cell whose tone
// changed (first seen, turned occupied or free, another shade), or whose log-odds moved from
// the value last recorded by at least one update of the set-up and a quarter of that value
// (replay_shows_change): the log-odds the page shows under the pointer are the last
// recorded, within one update or a quarter of the map's.
//
// A frame costs O(cells) to record: steps_per_frame is cells / 2000 rounded up (every step
// for the IR room's 1500 cells, every 15 for the thick arena's 28900, every 80 for 400 x 400).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/picture/map_picture.hpp"
#include "app/report/replay.hpp"
#include "mapping/grid_types.hpp"
#include "robot/metric_controller.hpp"
#include "sensing/metric_map.hpp"

namespace app {

// What the page shows besides the frames.
struct MetricReplayText {
  std::string title;    // the world
  std::string caption;  // strategy and set-up
  std::optional<mapping::Point> goal;
  double body_radius_m = 0.0;
  std::vector<LandmarkMark> landmarks;
  std::optional<PlainGridBounds> boundary;  // the world's floor, walled all round
  std::vector<std::pair<std::string, std::string>> summary;  // the printed summary's lines
};

class MetricReplayRecorder {
 public:
  // The map must outlive the replay; `start` is the robot's pose before the first step.
  MetricReplayRecorder(const sensing::MetricMap &map, const MapTones &tones, const ReplayPose &start);

  // After each control step: a frame when its step is due.
  void on_step(const robot::MetricController &c);
  // After the run: the last frame, unless the last step made one.
  void finish(const robot::MetricController &c);

  // The page's input: the frames recorded, and `text`.
  ReplayInput input(const MetricReplayText &text) const;
  std::int64_t steps_per_frame() const { return steps_per_frame_; }

 private:
  void record(const robot::MetricController &c);

  const sensing::MetricMap &map_;
  MapTones tones_;
  std::int64_t steps_per_frame_ = 1;
  std::vector<float> last_;  // each cell's log-odds as last recorded
  std::vector<ReplayPose> path_;
  std::vector<ReplayChange> changes_;
  std::vector<ReplayFrame> frames_;
};

}  // namespace app
