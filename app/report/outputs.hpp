#pragma once
// The files of `run --out DIR` (docs/output.md). They live in app/ because summary.json holds the
// scores against the truth; the grid exports (PGM, PNG) read only the grid.
//
//   map.pgm + map.yaml  ROS map_server format: one pixel a sub-cell, north up, binary P5.
//                       Pixels: 0 occupied, 254 free, 205 unknown. A sub-cell is occupied
//                       when observed with p > 0.5 (log-odds > 0), free when observed with
//                       p <= 0.5, unknown when never observed - the rule of the ASCII map and
//                       of the explorer's walls. (ROS's own 0.65 / 0.196 thresholds would call
//                       a sub-cell seen once by the classroom model, p 0.6 or 0.3, unknown.)
//                       map.yaml keeps ROS's thresholds, which read 0/254/205 back exactly.
//   map.png             the learned grid in tones a projector survives (dark occupied, light
//                       free, blue-grey never observed), the path, start, end and goals, and
//                       a legend strip with a scale bar: app/picture/map_picture.hpp.
//   truth.png           the true maze, each scored side marked right, missed, phantom or
//                       unseen, unvisited cells shaded, with the summary's wall_accuracy and
//                       coverage in the legend: app/report/truth_picture.hpp.
//   summary.json        every key of the summary block (format_summary), with typed values
//                       (null where the block leaves the key out: "goal" without floodfill,
//                       "plan" without planning, ...), plus "options": every option in
//                       effect, one object a concern of RunOptions ("max_steps" is the limit
//                       in effect; a null "noise" is the robot's own).
//   trace.csv           rows of control steps (trace_every_step(): every step, or the steps
//                       where something happens; see trace_header()), map-log can read it.
//   snapshots/NN.png    --snapshots N: map.png as it was after each of snapshot_steps(steps,
//                       N) (app/report/grid_history.hpp), 01.png first, the step in the caption.
//   replay.html         the run in a browser, unless --no-replay: app/report/replay.hpp. Not written
//                       (a warning on stderr) for a grid over kReplayMaxSubcells sub-cells or a
//                       page over kReplayMaxBytes even with the whole run in one frame.
//   map.svg, map.pdf, truth.svg, ... the same pictures with --picture-format svg or pdf.
//   plan.png, plan.csv  --plan-to (or `plan --out`) when a path was found: map.png's picture
//                       with the planned path in magenta instead of the exploration's; the
//                       path's sub-cells in order, `index,subcell_x,subcell_y,x_m,y_m`.
// Every file is written to a temporary name in DIR, then renamed (trace.csv too: its rows go
// to the temporary as the run goes, so its memory is a buffer, not the whole trace).

#include <functional>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/report/grid_history.hpp"
#include "app/picture/map_picture.hpp"
#include "app/report/output_dir.hpp"
#include "app/report/replay.hpp"
#include "app/run/report.hpp"
#include "app/run/run.hpp"
#include "common/atomic_file.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "robot/cell/controller.hpp"

namespace app {

// The pixel of one sub-cell in map.pgm: 0, 254 or 205 (see above).
unsigned char pgm_pixel(float log_odds, float initial_log_odds);
std::string pgm_file(const mapping::OccupancyGrid &grid, float initial_log_odds);
std::string map_yaml(const mapping::GridGeometry &geometry, const std::string &image_file);

// The tones of map.png for this run: its prior, --threshold and the set-up's own p_occ and
// p_free as increments of `model` (the course's numbers for pie, bump and depth).
MapTones map_tones(const RunOptions &options, const mapping::SensorModel &model);
// "maze8x8.txt, model cell, K 3": the legend's first line, the world's file name first.
std::string map_caption(const RunOptions &options);
// map.png's bytes (app/picture/map_picture.hpp), or map.svg's or map.pdf's; on `page` when given.
std::string png_file(const mapping::OccupancyGrid &grid, const MapTones &tones, const MapMarks &marks,
                     const std::string &caption, PictureFormat format = PictureFormat::png,
                     const std::optional<PageFrame> &page = std::nullopt);

// summary.json's text: the report's keys (report_json), then "options", every option the run
// used (the defaults filled in).
std::string summary_json(const RunOptions &options, const RunSummary &summary, const Report &report);
// The same of a maze run: its report is run_report(options, summary).
std::string summary_json(const RunOptions &options, const RunSummary &summary);

// "step,time_s,true_x_m,true_y_m,true_yaw_rad,cell_x,cell_y,action,subcells_updated\n":
// the control step (1-based, as the console's "step N"), simulated seconds, the true pose from
// the simulator, the controller's cell (the one arrived in at that step, as the console
// prints it; see robot::StepReport), what the robot did, and the sub-cells its scan updated;
// then `sensor_columns` (app/report/trace_sensors.hpp: the pose the robot reads, its bumps or depth).
std::string trace_header(const std::string &sensor_columns = "");
// Whether trace.csv has a row every control step: with --trace-steps, and for the set-ups
// whose readings map-log reads back (bump, depth, pie, cone: their bump or range columns).
// Else (cell, ray: a lidar robot's columns are its pose) a row when the action or the cell
// differs from the step before or a scan updated the grid, and the first and last steps: a
// 256 x 256 maze's trace is then megabytes, not a gigabyte.
bool trace_every_step(const RunOptions &options);
// The columns every trace.csv starts with, a maze run's and a Python controller's:
// "step,time_s,true_x_m,true_y_m,true_yaw_rad" (no line end).
std::string_view pose_trace_columns();
// Those columns' values of one row: the step, simulated seconds to 3 decimals, the true pose
// to 4 (no line end).
void append_pose_trace_values(std::string &csv, std::int64_t step, double time_s, double x_m, double y_m,
                              double yaw_rad);
// One row; `sensor_values` are the sensor columns' values (",..."), as the header has them.
void append_trace_row(std::string &csv, const robot::StepReport &step, double x_m, double y_m,
                      double yaw_rad, const std::string &sensor_values = "");

struct RunFiles {
  const mapping::OccupancyGrid *grid = nullptr;
  const mapping::SensorModel *model = nullptr;
  const std::vector<mapping::Cell> *path = nullptr;
  common::OutputFile *trace = nullptr;  // trace.csv as written during the run: committed here
  std::vector<mapping::Cell> goals;     // the maze's goal cells, marked on the pictures
  const maze::Maze *truth = nullptr;    // truth.png
  const explore::Visits *visits = nullptr;
  std::function<LearnedSide(maze::Cell, maze::Side)> learned;
  const GridHistory *history = nullptr;  // --snapshots, replay.html: the run as it went
  std::vector<LandmarkMark> landmarks;   // the world's landmarks, drawn on the pictures
  // The run's report when its kind builds its own (mms: the program's ending and stats);
  // else run_report(options, summary). summary.json and replay.html's table show it.
  std::optional<Report> report;
};

// Whether a run with --out records a GridHistory: for --snapshots, or for replay.html when
// the grid has at most kReplayMaxSubcells sub-cells (else a warning on stderr that the
// replay is not written).
bool keeps_history(const RunOptions &options, const mapping::GridGeometry &geometry);

// replay.html's bytes for this run, or nothing when it is too large (app/report/replay.hpp).
std::optional<Replay> replay_file(const RunOptions &options, const RunSummary &summary, const RunFiles &files);

// truth.png's bytes (app/report/truth_picture.hpp) for this run, or truth.svg's or truth.pdf's;
// on `page` when given.
std::string truth_png_file(const RunOptions &options, const RunFiles &files, PictureFormat format = PictureFormat::png,
                           const std::optional<PageFrame> &page = std::nullopt);
// The page every picture of this run is drawn on (map, truth, snapshots, plan): one size, one
// font, one scale, so that they can be flipped between. `steps` is the run's last step.
PageFrame run_page(const RunOptions &options, const RunFiles &files, std::int64_t steps);

// The files a run reads, for refuse_outputs_over_inputs: the world and --robot's file.
std::vector<NamedInput> run_inputs(const RunOptions &options);

// Writes the files into `out` (see above), in each of options.output.picture_formats for the
// pictures (map, truth, snapshots, plan). The caller adds its kind's own files, if any, and
// finishes `out` (which removes what an earlier run left and names the files on stderr).
void write_outputs(OutputDir &out, const RunOptions &options, const RunSummary &summary, const RunFiles &files);

}  // namespace app
