#pragma once
// `maze_mapper map-log LOG.csv`: a pose + bump/depth log mapped onto a numCells grid, the
// Cornell-style homework (sensing/bump_depth_marks.hpp for the rule, docs/lab-map-log.md),
// from its options as typed to the text it prints: the set-up, the final log-odds (north row
// first) and the thresholded map; with --out the grids and pictures, the final ones and
// snapshots.
//
// The log is a CSV file: a header line naming t,x,y,theta and bump_right,bump_left,bump_front
// or depth_1 ... depth_9, in any order among other columns (run --out's trace.csv names do
// too: time_s, gps_x_m, gps_y_m, imu_yaw_rad, depth_N_m), then one line a time step.

#include <string>

#include "sensing/bump_depth_marks.hpp"

namespace app::course {

// The homework's set-up, map-log's when no option changes it: 25 x 25 cells, prior 0.5, base
// 10; bumpers 0.16 m from the centre; nine depth rays 57 deg across (a Kinect's field of
// view), 28.5 ... -28.5 deg, left positive, max 10 m.
sensing::BumpDepthOptions homework_options();

// map-log's options as typed: the numbers in `options` (the homework's until an option
// changes one), the lists as text.
struct MapLogInput {
  std::string log_path;
  std::string sensor;          // bump or depth; empty: from the log's columns
  std::string cells = "25,25";  // X,Y
  std::string boundary;        // XS,XE,YS,YE, m (required)
  std::string base = "10";     // e or 10
  std::string depth_angles;    // A1,...,A9, deg, left positive
  std::string depth_reading = "range";  // range or axial
  std::string depth_origin;    // X,Y in the robot's frame, m
  std::string snapshots;       // F1,F2,...: fractions of the log (needs out_dir)
  std::string out_dir;         // empty: no files
  double threshold = -0.5;     // log-odds at or above which a cell is drawn W
  sensing::BumpDepthOptions options = homework_options();
  bool bump_options_given = false;   // --bump-radius
  bool depth_options_given = false;  // --depth-angles, --depth-max, --depth-reading, --depth-origin
};

// Checks the options and the log (common::InputError naming the option, or the log's
// FILE:LINE:COL for a bad line), refuses an option of the other sensor, warns on standard
// error about poses outside the boundary, writes --out's files and returns the text.
std::string run_map_log(const MapLogInput &input);

}  // namespace app::course
