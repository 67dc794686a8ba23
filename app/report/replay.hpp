#pragma once
// replay.html (run --out, unless --no-replay): one self-contained page that plays the run in
// a browser - no network, its script, style and the run's data inline. A step slider
// (<input type="range" id="step">) and play/pause; the learned map at each move drawn from
// the log-odds in map.png's tones (app/picture/map_picture.hpp); the robot and its heading; the path
// so far; the goals and landmarks; the K x K log-odds of the cell under the pointer (the robot's cell when
// the pointer is elsewhere); the summary block. The page is app/report/replay_page.html, built in.
//
// The data (a <script type="application/json" id="replay-data"> block, every "</" written
// "<\/"): the grid's geometry and tones, the landmarks (x and y in cells from the grid's
// south-west corner, radius in cells, red, green, blue 0 to 255: six numbers each), every arrival (step, cell, heading) and one frame a
// move: the sub-cells that changed since the previous frame, as pairs (gap, value) in
// ascending flat-index order (OccupancyGrid::index; the first gap is the index itself), the
// value 2 * round(100 * log-odds) + (1 if occupied by the map's rule, else 0), so the page
// shows log-odds to 0.01 and tells walls exactly as map.png does. Frame f holds what the
// grid learned from arrival f up to the next arrival (the last frame: up to the run's end).
//
// Size: about 6 bytes a changed sub-cell a frame. A page over `max_bytes` is made again with
// two, four, ... moves a frame (the path keeps every move); when even one frame for the
// whole run (the final map) is over, there is no page.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/report/grid_history.hpp"
#include "app/picture/map_picture.hpp"
#include "mapping/grid_types.hpp"

namespace app {

// replay.html's size limit: 16 MiB.
inline constexpr std::size_t kReplayMaxBytes = std::size_t{16} << 20;
// The largest grid a replay is recorded for, in sub-cells: past it the history costs more
// than the run (app/report/grid_history.hpp), and the final map alone is megabytes.
inline constexpr std::size_t kReplayMaxSubcells = std::size_t{1} << 20;

struct ReplayInput {
  const GridHistory *history = nullptr;  // the whole run, with an arrival at the start
  MapTones tones;
  std::vector<mapping::Cell> goals;
  std::vector<LandmarkMark> landmarks;   // drawn as map.png draws them
  std::string title;                     // the world
  std::string caption;                   // "model cell, K 3"
  std::int64_t steps = 0;                // the run's last step
  std::size_t reachable_cells = 0;       // cells reachable from the start: coverage at each move
  // The summary block's lines, key and value ("coverage", "100.00%").
  std::vector<std::pair<std::string, std::string>> summary;
  std::size_t max_bytes = kReplayMaxBytes;
};

struct Replay {
  std::string html;
  int moves_per_frame = 1;
};

// The page, or nothing when even the final map alone is over input.max_bytes.
std::optional<Replay> replay_html(const ReplayInput &input);

// Every "</" in `json` as "<\/", so that nothing in the data closes its <script> block.
std::string escaped_for_script(std::string json);
// `page` with its mark <!--REPLAY_DATA--> replaced by `data` (the room run's page uses it too).
std::string page_with_data(std::string_view page, const std::string &data);

// The data block's JSON with `moves_per_frame` moves a frame (>= 1), "</" not yet escaped.
std::string replay_data_json(const ReplayInput &input, int moves_per_frame);

}  // namespace app
