#pragma once
// `maze_mapper demo pie`: the Waterloo assignment's Figure 1 update with the course's rule
// alone (sensing/pie_slice.hpp for the rule, docs/lab-pie.md for the exercise), from its
// options as typed to the text it prints: the set-up, each sensor's slices, and the updated
// cells' log-odds; on request their CSV and a picture of them with the slices' edges.

#include <string>

#include "sensing/pie_slice.hpp"

namespace app::course {

// The assignment's Figure 1, demo pie's set-up when no option changes it: the robot at
// (1.5, 2.5) m facing south; six IR sensors from its left to its right, 30 deg apart over its
// front (the figure's ring as this program mounts it), with the figure's readings; beta
// 10 deg, alpha 0.1 m, cells of 0.1 m, IR max range 1.5 m.
sensing::PieSliceOptions figure_1_options();

// demo pie's options as typed: the numbers in `options` (Figure 1's until an option changes
// one), the lists and the pose as text (empty: Figure 1's), the files to write (empty: none).
struct DemoPieInput {
  sensing::PieSliceOptions options = figure_1_options();
  std::string readings;  // "1,1.5,...", m, left to right
  std::string mounts;    // "75,45,...", deg from the heading, left positive
  std::string pose;      // Xm,Ym,YAW (app/run/option_values.hpp's parse_pose)
  std::string csv_path;  // x_m,y_m,logodds of every updated cell
  std::string svg_path;  // the picture as SVG
  std::string png_path;  // the picture; SVG or PDF when the name ends in .svg or .pdf
};

// Checks the input (common::InputError naming the option; sensing::validate's checks), prints
// a pose's warning on standard error, writes the files asked for and returns the text.
std::string run_demo_pie(const DemoPieInput &input);

}  // namespace app::course
