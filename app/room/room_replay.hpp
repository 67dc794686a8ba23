#pragma once
// replay.html for a room run (room --out): one self-contained page that plays the run in a
// browser, no network: a frame slider and play/pause; the map at each frame in map.png's
// tones; the trajectory in metres from the start, the robot (its body and heading), the goal;
// the summary. The page is app/room/room_replay_page.html, built in.
//
// The data (<script type="application/json" id="replay-data">, every "</" written "<\/"):
// the grid (cells_x, cells_y, cell_m, origin), the tone of a cell never observed ("initial",
// 0xRRGGBB), and a frame every `steps_per_frame` control steps and at the run's end: its step,
// its time in ms, the pose (x and y in mm, yaw in mrad) and the cells whose tone changed since
// the frame before, as pairs (gap, 0xRRGGBB) in ascending flat index (j * cells_x + i; the
// first gap is the index itself).
//
// A frame costs O(cells) to record: steps_per_frame is cells / 2000 rounded up (every step
// for the IR room's 1500 cells, every 15 for the thick arena's 28900, every 80 for 400 x 400).
// A page over the limit is made again with frames merged two, four, ... to one; nothing when
// even one frame (the final map) is over.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/picture/map_picture.hpp"
#include "app/report/replay.hpp"
#include "mapping/grid_types.hpp"
#include "robot/room_controller.hpp"
#include "sensing/room_map.hpp"

namespace app {

// What the page shows besides the frames.
struct RoomReplayText {
  std::string title;    // the world
  std::string caption;  // strategy and set-up
  mapping::Point start;
  std::optional<mapping::Point> goal;
  double body_radius_m = 0.0;
  std::vector<std::pair<std::string, std::string>> summary;  // the printed summary's lines
};

class RoomReplay {
 public:
  // The map must outlive the replay.
  RoomReplay(const sensing::RoomMap &map, const MapTones &tones);

  // After each control step: a frame when its step is due.
  void on_step(const robot::RoomController &c);
  // After the run: the last frame, unless the last step made one.
  void finish(const robot::RoomController &c);

  // The page, or nothing when even one frame is over max_bytes.
  std::optional<std::string> html(const RoomReplayText &text, std::size_t max_bytes = kReplayMaxBytes) const;
  // The data block's JSON with `per` recorded frames merged into one (>= 1), "</" not escaped.
  std::string data_json(const RoomReplayText &text, std::size_t per) const;
  std::int64_t steps_per_frame() const { return steps_per_frame_; }

 private:
  struct Frame {
    std::int64_t step = 0;
    long t_ms = 0;
    long x_mm = 0;
    long y_mm = 0;
    long yaw_mrad = 0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> changes;  // (flat index, 0xRRGGBB), ascending
  };
  void record(const robot::RoomController &c);
  std::uint32_t rgb_at(std::size_t n) const;
  // The frames merged `per` into one: each the last one's pose, the group's changes (later wins).
  std::vector<Frame> merged(std::size_t per) const;

  const sensing::RoomMap &map_;
  MapTones tones_;
  std::uint32_t initial_ = 0;
  std::int64_t steps_per_frame_ = 1;
  std::vector<std::uint32_t> last_;  // each cell's tone at the last frame
  std::vector<Frame> frames_;
};

}  // namespace app
