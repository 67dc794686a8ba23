#pragma once
// The files of `run --out DIR` (DESIGN §7). They live in app/ because summary.json holds the
// scores against the truth; the grid exports (PGM, PNG) read only the grid.
//
//   map.pgm + map.yaml  ROS map_server format: one pixel a sub-cell, north up, binary P5.
//                       Pixels: 0 occupied, 254 free, 205 unknown. A sub-cell is occupied
//                       when observed with p > 0.5 (log-odds > 0), free when observed with
//                       p <= 0.5, unknown when never observed - the rule of the ASCII map and
//                       of the explorer's walls. (ROS's own 0.65 / 0.196 thresholds would call
//                       a sub-cell seen once by the classroom model, p 0.6 or 0.3, unknown.)
//                       map.yaml keeps ROS's thresholds, which read 0/254/205 back exactly.
//   map.png             the probability grid in grey (255 * (1 - p): white free, black
//                       occupied; never observed is mid-grey 128), each sub-cell a square of
//                       png_scale() pixels, the robot's path (cell centres in order of
//                       arrival) drawn over it in red, the start marked in green. libpng.
//   summary.json        every key of the summary block (format_summary), with typed values
//                       (null where the block leaves the key out: "goal" without floodfill,
//                       "plan" without planning, ...), plus "options": every option in
//                       effect, one object a concern of RunOptions ("max_steps" is the limit
//                       in effect; a null "noise" is the robot's own).
//   trace.csv           one row a control step (see trace_header()).
// Every file is written to a temporary name in DIR, then renamed.

#include <string>
#include <vector>

#include "app/run.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "robot/cell_controller.hpp"

namespace app {

// Makes sure DIR can take the outputs before anything runs: creates it (and its parents)
// when missing, and checks that it is a directory a file can be created in (by creating and
// removing a probe file). Throws common::InputError "--out DIR: REASON" otherwise; then no
// directory it created is left behind.
void prepare_output_dir(const std::string &dir);

// The pixel of one sub-cell in map.pgm: 0, 254 or 205 (see above).
unsigned char pgm_pixel(float log_odds, float initial_log_odds);
std::string pgm_file(const mapping::OccupancyGrid &grid, float initial_log_odds);
std::string map_yaml(const mapping::GridGeometry &geometry, const std::string &image_file);

// Pixels per sub-cell in map.png: ceil(100 / K), so a cell is at least 100 px (a 4x4 maze
// at least 400 px wide), lowered for big mazes so the image stays within 4096 px a side
// where it can (never below 1).
int png_scale(const mapping::GridGeometry &geometry);
std::string png_file(const mapping::OccupancyGrid &grid, const mapping::SensorModel &model,
                      const std::vector<mapping::Cell> &path);

std::string summary_json(const RunOptions &options, const RunSummary &summary);

// "time_s,x_m,y_m,yaw_rad,cell_x,cell_y,action,subcells_updated\n"; the pose is the true
// pose from the simulator, the cell the controller's (see robot::StepReport).
std::string trace_header();
void append_trace_row(std::string &csv, const robot::StepReport &step, double x_m, double y_m,
                      double yaw_rad);

struct RunFiles {
  const mapping::OccupancyGrid *grid = nullptr;
  const mapping::SensorModel *model = nullptr;
  const std::vector<mapping::Cell> *path = nullptr;
  const std::string *trace_csv = nullptr;
};

// Writes the five files into dir (prepared by prepare_output_dir).
void write_outputs(const std::string &dir, const RunOptions &options, const RunSummary &summary,
                   const RunFiles &files);

}  // namespace app
