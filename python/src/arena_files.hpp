#pragma once
// The files of a Python controller's run on an arena (python3 -m maze_mapper.run --out), beside
// truth.png: map.png of the metric map the controller kept (maze_mapper.keep_map), drawn as
// `maze_mapper room --out` draws its map.png (app/picture/metric_map_pictures.hpp), and replay.html,
// the one replay page (app/report/replay.hpp) in metres:
//
//   path    every pose of trace.csv (its step, x, y, yaw), the first the start
//   frames  with a kept map, one at the first control step, one every
//           ceil(map cells / 2000) control steps (the room replay's rule) and one at the end,
//           each holding the map's cells the page shows differently since the frame before
//           (replay_shows_change), read from the controller's map then; a map kept again
//           on another grid starts the history again on it. Without a map, a frame every
//           control step (at most kPathOnlyFrames: a frame every N steps past that) over a grid
//           of the arena's extent never observed
//   marks   the arena's boundary as wall, its landmarks in their colour, its goals, the
//           robot's body

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/report/replay.hpp"
#include "app/run/report.hpp"
#include "kept_map.hpp"
#include "maze/world/world.hpp"
#include "pose_trace.hpp"

namespace maze_mapper_python {

inline constexpr std::size_t kPathOnlyFrames = 5000;

// The replay's frames as the run goes, and the history of the kept map between them.
class ArenaReplayRecorder {
 public:
  // After each trace row (the last of `visits`): a frame when one is due, the map read from
  // `kept` (null: none kept).
  void on_step(const std::vector<PoseTrace::Visit> &visits, const KeptMap *kept);
  // The controller keeps `kept` from now on.
  void keep(const KeptMap &kept);
  // After the run: the last frame, with the map as the controller left it.
  void finish(const std::vector<PoseTrace::Visit> &visits, const KeptMap *kept);

  const std::vector<app::ReplayChange> &changes() const { return changes_; }
  const std::vector<app::ReplayFrame> &frames() const { return frames_; }
  std::int64_t steps_per_frame() const { return steps_per_frame_; }

 private:
  // The cells of `kept` that show a change since last recorded, into changes_.
  void take_changes(const KeptMap *kept);

  sensing::MetricGridSpec spec_;  // the grid recorded on (cells_x 0: no map yet)
  app::MapTones tones_;
  std::int64_t steps_per_frame_ = 1;
  std::int64_t rows_since_frame_ = 0;
  std::vector<float> last_;   // each cell's log-odds as last recorded
  std::vector<float> now_;    // the map read (reused)
  std::vector<app::ReplayChange> changes_;
  std::vector<app::ReplayFrame> frames_;
};

// What an arena run's map.png and replay.html show besides the map and the path.
struct ArenaRunMarks {
  const maze::World *world = nullptr;
  double body_radius_m = 0.0;
  std::vector<std::pair<std::string, std::string>> summary;  // the printed summary's lines
};

// map.png of the kept map, with the path from `visits`.
std::string arena_map_png(const KeptMap &kept, const std::vector<PoseTrace::Visit> &visits,
                          const ArenaRunMarks &marks);

// replay.html's input: the recorder's frames (or, without a kept map, a frame a pose), the
// path, the arena's marks.
app::ReplayInput arena_replay_input(const ArenaReplayRecorder &recorder, const KeptMap *kept,
                                    const std::vector<PoseTrace::Visit> &visits, const ArenaRunMarks &marks);

}  // namespace maze_mapper_python
