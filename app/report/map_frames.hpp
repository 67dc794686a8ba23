#pragma once
// replay.html's frames of a run drawn in metres (a room run, a Python controller's run): the
// path and, every few control steps, the cells of the kept map (a MapView) that the page
// shows differently since the frame before (replay_shows_change): the log-odds the page
// shows under the pointer are the last recorded, within one update or a quarter of the map's.
//
//   frames  the first at the first pose given, one every ceil(map cells / 2000) poses after
//           it (every pose for the IR room's 1500 cells, every 15 for the thick arena's
//           28900, every 80 for 400 x 400) and one at the run's end; a frame costs O(cells).
//           A map kept again on another grid starts the history again on it. Without a map,
//           a frame every pose, thinned to at most kPathOnlyFrames on the page.
//   path    every pose given (PathPoses::every_step) or the frames' (PathPoses::at_frames).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "app/report/replay.hpp"
#include "app/run/map_view.hpp"

namespace app {

inline constexpr std::size_t kPathOnlyFrames = 5000;

enum class PathPoses { every_step, at_frames };

class MapFrames {
 public:
  explicit MapFrames(PathPoses path) : path_poses_(path) {}

  // The map read from now on; on the same grid as the one kept before, its history goes on.
  void keep(MapView view);
  // After a control step (the first: the start): the pose, and a frame when one is due.
  void on_step(const ReplayPose &pose, double time_s);
  // After the run: the last frame, unless the last pose made one; else the changes the
  // controller made after its last step, into it.
  void finish(const ReplayPose &pose, double time_s);

  bool empty() const { return frames_.empty(); }
  const std::vector<ReplayPose> &path() const { return path_; }
  // The page's grid, tones, path, changes, frames and last step; `without_map`: the grid a
  // run that kept no map is drawn on (never observed).
  void fill(ReplayInput &input, const mapping::GridGeometry &without_map) const;

 private:
  void record_frame(const ReplayPose &pose, double time_s);
  void take_changes();

  PathPoses path_poses_;
  MapView view_;
  std::int64_t steps_per_frame_ = 1;
  std::int64_t poses_since_frame_ = 0;
  std::vector<float> last_;  // each cell's log-odds as last recorded
  std::vector<float> now_;   // the map read (reused)
  std::vector<ReplayPose> path_;
  std::vector<ReplayChange> changes_;
  std::vector<ReplayFrame> frames_;
};

// The grid of a metric map spec as the page's (K = 1).
mapping::GridGeometry replay_grid(const sensing::MetricGridSpec &spec);

}  // namespace app
