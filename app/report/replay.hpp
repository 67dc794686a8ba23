#pragma once
// replay.html (run, room and every --out, unless --no-replay): one self-contained page that
// plays a run in a browser - no network, its script, style and the run's data inline. The
// same page for a maze run (a lattice of cells, each K x K sub-cells) and a room run (a
// metric grid: cells of cell_m, K = 1): a step slider (<input type="range" id="step">),
// first / back / play / on / last, speed, zoom and fit; it opens at the start (frame 0). It
// draws the learned map at each frame from the log-odds in map.png's tones
// (app/picture/map_picture.hpp), the path so far, the start, the robot and its heading, the
// goals and landmarks; beside it the frame's numbers (a maze run: move, step, cells visited,
// coverage; a room run: step, simulated time, pose in metres), the K x K log-odds of the cell
// under the pointer (the robot's cell when the pointer is elsewhere) and the summary block.
// The page is app/report/replay_page.html, built in.
//
// The data (a <script type="application/json" id="replay-data"> block, every "</" written
// "<\/"): "units" ("cells" or "metres": how the page names places), the grid's geometry and
// tones, the path (each pose's step and x, y in mm from the grid's south-west corner, yaw in
// mrad counter-clockwise from east), the goals (x, y in mm, a frame "goal_mm" wide), the
// landmarks (x, y, radius in mm, red, green, blue 0 to 255, or -1, -1, -1 when the world
// does not give its colour and the page draws it neutral grey: six numbers each), the solid
// boundary ("boundary_mm": x_min, y_min, x_max, y_max in mm, or [] for none: outside it the
// page draws wall, a band a map cell wide round it and any grid cells past it, in the room
// pictures' wall colour; the view holds the band and every landmark whole), and the
// marks' size rule ("mark_rule": kMarkOfFont, kLeastFontPx, kFontShareOfHeight of
// app/picture/size_rules.hpp: the start, the robot, the goals and the landmarks at least
// mark_rule[0] x max(mark_rule[1], the view's height / mark_rule[2]) screen pixels at any
// zoom), and the frames: each the last pose it shows, its step, its simulated time in ms (-1 when not
// known), its belief when the run localized ("belief": a list a frame of each cell's belief
// in thousandths, north-west first, row by row; null without --localize) and the sub-cells that changed since the previous frame, as pairs (gap, value) in
// ascending flat-index order (OccupancyGrid::index; the first gap is the index itself), the
// value 2 * round(100 * log-odds) + (1 if occupied by the map's rule, else 0), so the page
// shows log-odds to 0.01 and tells walls exactly as map.png does.
//
// Size: about 6 bytes a changed sub-cell a frame. A page over `max_bytes` is made again with
// two, four, ... recorded frames merged into one (the path keeps every pose); when even one
// frame for the whole run (the final map) is over, there is no page.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/picture/map_picture.hpp"
#include "app/picture/plain_grid_picture.hpp"
#include "app/report/grid_history.hpp"
#include "app/run/report.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "maze/world/geometry.hpp"

namespace app {

// replay.html's size limit: 16 MiB.
inline constexpr std::size_t kReplayMaxBytes = std::size_t{16} << 20;
// The largest grid a replay is recorded for, in sub-cells: past it the history costs more
// than the run (app/report/grid_history.hpp), and the final map alone is megabytes.
inline constexpr std::size_t kReplayMaxSubcells = std::size_t{1} << 20;

// How the page names places and what a frame is: a maze run's cells and moves, or a room
// run's metres and control steps.
enum class ReplayUnits { cells, metres };

// Where the robot was at `step`, in the world frame.
struct ReplayPose {
  std::int64_t step = 0;
  mapping::Point at;
  double yaw_rad = 0.0;  // counter-clockwise from east
  bool placed = false;   // set down by a supervisor (a teleport, a reset): no path drawn to it
};

// A sub-cell (flat grid index) that took `log_odds`.
struct ReplayChange {
  std::uint32_t index = 0;
  float log_odds = 0.0f;
};

// What the page shows at one position of its slider: the path up to pose `last_pose`, the
// map after `step`. Its changes are ReplayInput::changes [first, end): `end` is this frame's,
// `first` the previous frame's end.
struct ReplayFrame {
  std::size_t last_pose = 0;
  std::int64_t step = 0;
  double time_s = -1.0;  // simulated time; negative when not known
  std::size_t changes_end = 0;
};

struct ReplayInput {
  ReplayUnits units = ReplayUnits::cells;
  mapping::GridGeometry grid;       // a room's map: K = 1
  float initial_log_odds = 0.0f;    // every sub-cell before the first frame
  MapTones tones;
  std::vector<ReplayPose> path;     // the start first
  std::size_t start_pose = 0;       // the path's pose the start mark stands on
  std::vector<ReplayChange> changes;  // in order of frame
  std::vector<ReplayFrame> frames;    // at least one; the first shows the start
  int steps_per_frame = 0;            // control steps a recorded frame (a room run's); 0: a move a frame
  std::vector<mapping::Point> goals;  // centres
  double goal_side_m = 0.0;           // each goal's frame, a side
  double body_radius_m = 0.0;         // the robot's disc; 0: a fixed part of a cell
  std::vector<LandmarkMark> landmarks;
  // The world's floor when it is walled all round (a room's), in the world frame: drawn as
  // wall outside. None: the grid alone (a maze's outer walls lie on its cells).
  std::optional<PlainGridBounds> solid_boundary;
  // The world's solids, each as boxes of a raster of it, drawn as wall: the world of a run that
  // keeps no map (its page has no map to show them). Empty: none drawn.
  std::vector<PlainGridBounds> world_solids;
  // run --localize: the filter's belief after each recorded frame's arrival, each cell's in
  // thousandths, cell 1 (north-west) first, row by row. Empty: no belief drawn.
  std::vector<std::vector<int>> belief_permille;
  std::string title;                  // the world
  std::string caption;                // "model cell, K 3"
  std::int64_t steps = 0;             // the run's last step
  std::size_t reachable_cells = 0;    // cells reachable from the start: coverage at each move (0: none)
  // The summary block's lines, key and value (coverage, 100.00%).
  std::vector<std::pair<std::string, std::string>> summary;
  std::size_t max_bytes = kReplayMaxBytes;
};

struct Replay {
  std::string html;
  int frames_merged = 1;  // recorded frames a frame of the page
};

// A maze run's path and frames from its history: a frame an arrival, holding what the grid
// learned from that arrival up to the next (the last: up to `steps`, the run's last step);
// the poses at the cells' centres facing their headings. Sets grid, initial_log_odds, path,
// changes and frames of `input`.
void add_history(ReplayInput &input, const GridHistory &history, std::int64_t steps);
// A maze's goal cells as the page's goals: their centres on input.grid (add_history's), each
// framed three quarters of a cell wide.
void add_goal_cells(ReplayInput &input, const std::vector<mapping::Cell> &cells);

// A sub-cell's value in the data: 2 * round(100 * log_odds) + (1 if occupied by the tones' rule).
long replay_value(float log_odds, const MapTones &tones);

// Whether a cell of a metric map (K = 1) recorded at log-odds `was` is worth a change at `now`:
// the page shows it differently (its tone changed: first seen, turned occupied or free,
// another shade), or its log-odds moved by at least one update of the set-up (the smaller of
// the tones' occupied and free increments) and a quarter of `was`. Past the tones' saturation
// a cell seen every step is so recorded a few dozen times in a run, not every step.
bool replay_shows_change(float was, float now, const MapTones &tones);

// The world's solids as ReplayInput::world_solids: the boxes of each row's runs of solid
// cells of its truth raster, kWorldSolidCells cells on its longer side.
inline constexpr int kWorldSolidCells = 400;
std::vector<PlainGridBounds> world_solid_boxes(const maze::Arena &arena);

// The summary block's lines as the page's table shows them: wall_time_ms left out, so that a
// page made again of the same run is the same page.
std::vector<std::pair<std::string, std::string>> replay_summary(const Report &report);

// The page, or nothing when even the final map alone is over input.max_bytes.
std::optional<Replay> replay_html(const ReplayInput &input);

// Every "</" in `json` as "<\/", so that nothing in the data closes its <script> block.
std::string escaped_for_script(std::string json);

// The data block's JSON with `merged` recorded frames a frame (>= 1), "</" not yet escaped.
std::string replay_data_json(const ReplayInput &input, int merged);

}  // namespace app
