#include "app/course/demo_pie.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "app/picture/plain_grid_picture.hpp"
#include "app/run/option_values.hpp"
#include "common/atomic_file.hpp"
#include "common/standard_streams.hpp"
#include "mapping/log_odds.hpp"

namespace app::course {
namespace {

std::string two_decimals(double v) { return fmt::format("{:.2f}", v); }

std::string pie_sensor_table(const sensing::PieSliceOptions &o) {
  std::string out = "sensor  x_m   y_m   heading_deg  reading_m  clear_m  contact_m  kind\n";
  const auto slices = sensing::pie_slices(o);
  for (std::size_t n = 0; n < slices.size(); ++n) {
    const auto &s = slices[n];
    out += fmt::format("{:>6}  {:<4}  {:<4}  {:>11}  {:>9}  {:>7}  {:>9}  {}\n", n + 1, two_decimals(s.x_m),
                       two_decimals(s.y_m), fmt::format("{:.1f}", s.heading_deg), two_decimals(s.reading_m),
                       two_decimals(s.clear_m), s.contact ? two_decimals(s.contact_m) : "-",
                       s.contact ? "contact" : "clear");
  }
  return out;
}

// The updated region, north row first: a cell's log-odds, `.` where no sensor updated it.
std::string region_matrix(const sensing::PieSliceOptions &o, const std::vector<sensing::PieSliceCell> &cells) {
  if (cells.empty()) return "no cell updated\n";
  int i0 = cells.front().i, i1 = i0, j0 = cells.front().j, j1 = j0;
  for (const auto &c : cells) {
    i0 = std::min(i0, c.i), i1 = std::max(i1, c.i), j0 = std::min(j0, c.j), j1 = std::max(j1, c.j);
  }
  const double r = o.resolution_m;
  std::string out = fmt::format("updated cells: x {} .. {} m, y {} .. {} m; rows by their centre's y_m, north first\n",
                                two_decimals(i0 * r), two_decimals((i1 + 1) * r), two_decimals(j0 * r), two_decimals((j1 + 1) * r));
  auto next = cells.begin();
  for (int j = j1; j >= j0; --j) {
    out += fmt::format("{:>5} |", two_decimals((j + 0.5) * r));
    for (int i = i0; i <= i1; ++i) {
      const bool here = next != cells.end() && next->i == i && next->j == j;
      out += here ? fmt::format(" {:+.2f}", (next++)->log_odds) : "     .";
    }
    out += "\n";
  }
  return out;
}

std::string pie_csv(const sensing::PieSliceOptions &o, const std::vector<sensing::PieSliceCell> &cells) {
  std::string out = "x_m,y_m,logodds\n";
  for (const auto &c : cells) {
    out += fmt::format("{:.4f},{:.4f},{:.4f}\n", (c.i + 0.5) * o.resolution_m, (c.j + 0.5) * o.resolution_m,
                       c.log_odds);
  }
  return out;
}

// The grid around the updated cells and the robot, two cells of margin: every updated cell
// in map.png's tones, the cells no sensor updated in the never-observed tone.
PlainGrid pie_grid(const sensing::PieSliceOptions &o, const std::vector<sensing::PieSliceCell> &cells) {
  const double r = o.resolution_m;
  int i0 = static_cast<int>(std::floor(o.x_m / r)), i1 = i0, j0 = static_cast<int>(std::floor(o.y_m / r)), j1 = j0;
  for (const auto &c : cells) {
    i0 = std::min(i0, c.i), i1 = std::max(i1, c.i), j0 = std::min(j0, c.j), j1 = std::max(j1, c.j);
  }
  PlainGrid g = plain_grid_around(i0, i1, j0, j1, r, kUnknownTone);
  const double occupied = mapping::log_odds(sensing::kPieSliceOccupiedP);
  const double clear = mapping::log_odds(sensing::kPieSliceClearP);
  for (const auto &c : cells) {
    set_tone(g, (c.i + 0.5) * r, (c.j + 0.5) * r, log_odds_tone(c.log_odds, 0.0, occupied, clear));
  }
  return g;
}

// The updated cells, each slice's edges (at +-beta, to where it ends) in red, the robot a
// blue disc; the format by the file's extension (PNG unless .svg or .pdf).
std::string pie_picture(const sensing::PieSliceOptions &o, const std::vector<sensing::PieSliceCell> &cells,
                         PictureFormat format) {
  const PlainGrid g = pie_grid(o, cells);
  const double occupied = mapping::log_odds(sensing::kPieSliceOccupiedP);
  const double clear = mapping::log_odds(sensing::kPieSliceClearP);
  Figure legend;
  legend.lines = {fmt::format("demo pie: beta {:g} deg, alpha {:g} m, cells {:g} m", o.half_angle_deg,
                              o.contact_m, o.resolution_m)};
  legend.items = {{Swatch::line, kPathColour, "slice edges"}, {Swatch::disc, kEndColour, "robot"}};
  legend.bar = map_tone_bar(log_odds_tones(0.0, occupied, clear), "not updated");
  legend.bar->right_word = "occupied";
  legend.bar->left_word = "clear";
  const PlainGridOverlay overlay = [&](Drawing &page, const PlainGridFrame &frame) {
    const double thickness = std::max(1.5, frame.cell_w_px / 8);
    for (const auto &s : sensing::pie_slices(o)) {
      const double end_m = s.contact ? s.contact_m : s.clear_m;
      for (const double side : {-1.0, 1.0}) {
        const double a = (s.heading_deg + side * o.half_angle_deg) * std::numbers::pi / 180.0;
        page.polyline({frame.at(s.x_m, s.y_m), frame.at(s.x_m + end_m * std::cos(a), s.y_m + end_m * std::sin(a))},
                      thickness, kPathColour);
      }
    }
    page.ringed_disc(frame.at(o.x_m, o.y_m), std::max(3.0, frame.cell_w_px), kEndColour, 1.5, kWhite);
  };
  return plain_grid_picture(g, legend, overlay, format).encode();
}

sensing::PieSliceOptions pie_options(const DemoPieInput &input) {
  sensing::PieSliceOptions o = input.options;
  if (!input.readings.empty()) o.readings_m = parse_number_list(input.readings, "--readings");
  if (!input.mounts.empty()) o.mounts_deg = parse_number_list(input.mounts, "--mounts");
  if (!input.pose.empty()) {
    std::vector<std::string> warnings;
    const PoseArgument pose = parse_pose(input.pose, "--pose", warnings);
    for (const std::string &warning : warnings) common::print_stderr("{}\n", warning);
    o.x_m = pose.x_m, o.y_m = pose.y_m, o.heading_deg = pose.yaw_deg;
  }
  sensing::validate(o);
  return o;
}

}  // namespace

sensing::PieSliceOptions figure_1_options() {
  sensing::PieSliceOptions o;
  o.x_m = 1.5;
  o.y_m = 2.5;
  o.heading_deg = 270.0;  // facing south
  o.mounts_deg = {75.0, 45.0, 15.0, -15.0, -45.0, -75.0};
  o.readings_m = {1.0, 1.5, 1.5, 0.8, 1.2, 1.5};
  o.half_angle_deg = 10.0;
  o.contact_m = 0.1;
  o.resolution_m = 0.1;
  o.max_range_m = 1.5;
  return o;
}

std::string run_demo_pie(const DemoPieInput &input) {
  const sensing::PieSliceOptions o = pie_options(input);
  const auto cells = sensing::pie_slice_update(o);
  if (!input.csv_path.empty()) common::write_file_atomically(input.csv_path, pie_csv(o, cells));
  if (!input.svg_path.empty()) common::write_file_atomically(input.svg_path, pie_picture(o, cells, PictureFormat::svg));
  if (!input.png_path.empty()) {
    const PictureFormat format = picture_format_of_file(input.png_path).value_or(PictureFormat::png);
    common::write_file_atomically(input.png_path, pie_picture(o, cells, format));
  }
  std::string out = "IR pie-slice update (Waterloo assignment, Figure 1)\n";
  out += fmt::format("half-angle {:g} deg\nresolution {:g} m\n", o.half_angle_deg, o.resolution_m);
  out += fmt::format("robot at ({:g}, {:g}) m heading {:g} deg; IR max range {:g} m; contact depth alpha {:g} m\n",
                     o.x_m, o.y_m, o.heading_deg, o.max_range_m, o.contact_m);
  out += fmt::format("per sensor and cell (four corners and centre): occupied logit({:g}) = {:+.2f}, "
                     "clear logit({:g}) = {:+.2f}\n\n",
                     sensing::kPieSliceOccupiedP, mapping::log_odds(sensing::kPieSliceOccupiedP),
                     sensing::kPieSliceClearP, mapping::log_odds(sensing::kPieSliceClearP));
  out += pie_sensor_table(o) + "\n" + region_matrix(o, cells);
  std::string wrote;
  for (const std::string *path : {&input.csv_path, &input.svg_path, &input.png_path}) {
    if (!path->empty()) wrote += "wrote " + *path + "\n";
  }
  if (!wrote.empty()) out += "\n" + wrote;
  return out;
}

}  // namespace app::course
