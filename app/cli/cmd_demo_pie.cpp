// maze_mapper demo pie: the Waterloo assignment's Figure 1 update, the course's rule alone
// (sensing/pie_demo.hpp for the rule, docs/lab-pie.md for the exercise).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/parse_number.hpp"
#include "app/cli/cli_options.hpp"
#include "app/picture/plain_grid_picture.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "app/cli/demo_commands.hpp"
#include "mapping/log_odds.hpp"
#include "sensing/pie_demo.hpp"

namespace app {
namespace {

struct DemoPieInput {
  sensing::PieDemoOptions options;
  std::string readings;
  std::string mounts;
  std::string pose;
  std::string csv_path;
  std::string svg_path;
  std::string png_path;
};

std::string number(double v) { return fmt::format("{:.2f}", v); }

std::string sensor_table(const sensing::PieDemoOptions &o) {
  std::string out = "sensor  x_m   y_m   heading_deg  reading_m  clear_m  contact_m  kind\n";
  const auto slices = sensing::pie_demo_slices(o);
  for (std::size_t n = 0; n < slices.size(); ++n) {
    const auto &s = slices[n];
    out += fmt::format("{:>6}  {:<4}  {:<4}  {:>11}  {:>9}  {:>7}  {:>9}  {}\n", n + 1, number(s.x_m),
                       number(s.y_m), fmt::format("{:.1f}", s.heading_deg), number(s.reading_m),
                       number(s.clear_m), s.contact ? number(s.contact_m) : "-",
                       s.contact ? "contact" : "clear");
  }
  return out;
}

// The updated region, north row first: a cell's log-odds, `.` where no sensor updated it.
std::string region_matrix(const sensing::PieDemoOptions &o, const std::vector<sensing::PieDemoCell> &cells) {
  if (cells.empty()) return "no cell updated\n";
  int i0 = cells.front().i, i1 = i0, j0 = cells.front().j, j1 = j0;
  for (const auto &c : cells) {
    i0 = std::min(i0, c.i), i1 = std::max(i1, c.i), j0 = std::min(j0, c.j), j1 = std::max(j1, c.j);
  }
  const double r = o.resolution_m;
  std::string out = fmt::format("updated cells: x {} .. {} m, y {} .. {} m; rows by their centre's y_m, north first\n",
                                number(i0 * r), number((i1 + 1) * r), number(j0 * r), number((j1 + 1) * r));
  auto next = cells.begin();
  for (int j = j1; j >= j0; --j) {
    out += fmt::format("{:>5} |", number((j + 0.5) * r));
    for (int i = i0; i <= i1; ++i) {
      const bool here = next != cells.end() && next->i == i && next->j == j;
      out += here ? fmt::format(" {:+.2f}", (next++)->log_odds) : "     .";
    }
    out += "\n";
  }
  return out;
}

std::string csv_file(const sensing::PieDemoOptions &o, const std::vector<sensing::PieDemoCell> &cells) {
  std::string out = "x_m,y_m,logodds\n";
  for (const auto &c : cells) {
    out += fmt::format("{:.4f},{:.4f},{:.4f}\n", (c.i + 0.5) * o.resolution_m, (c.j + 0.5) * o.resolution_m,
                       c.log_odds);
  }
  return out;
}

// The grid around the updated cells and the robot, two cells of margin: every updated cell
// in map.png's tones, the cells no sensor updated in the never-observed tone.
PlainGrid pie_grid(const sensing::PieDemoOptions &o, const std::vector<sensing::PieDemoCell> &cells) {
  const double r = o.resolution_m;
  int i0 = static_cast<int>(std::floor(o.x_m / r)), i1 = i0, j0 = static_cast<int>(std::floor(o.y_m / r)), j1 = j0;
  for (const auto &c : cells) {
    i0 = std::min(i0, c.i), i1 = std::max(i1, c.i), j0 = std::min(j0, c.j), j1 = std::max(j1, c.j);
  }
  PlainGrid g = plain_grid_around(i0, i1, j0, j1, r, kUnknownTone);
  const double occupied = mapping::log_odds(sensing::kPieDemoOccupiedP);
  const double clear = mapping::log_odds(sensing::kPieDemoClearP);
  for (const auto &c : cells) {
    set_tone(g, (c.i + 0.5) * r, (c.j + 0.5) * r, log_odds_tone(c.log_odds, 0.0, occupied, clear));
  }
  return g;
}

// The updated cells, each slice's edges (at +-beta, to where it ends) in red, the robot a
// blue disc; the format by the file's extension (PNG unless .svg or .pdf).
std::string picture_file(const sensing::PieDemoOptions &o, const std::vector<sensing::PieDemoCell> &cells,
                         PictureFormat format) {
  const PlainGrid g = pie_grid(o, cells);
  const double occupied = mapping::log_odds(sensing::kPieDemoOccupiedP);
  const double clear = mapping::log_odds(sensing::kPieDemoClearP);
  Figure legend;
  legend.lines = {fmt::format("demo pie: beta {:g} deg, alpha {:g} m, cells {:g} m", o.half_angle_deg,
                              o.contact_m, o.resolution_m)};
  legend.items = {{Swatch::line, kPathColour, "slice edges"}, {Swatch::disc, kEndColour, "robot"}};
  legend.bar = map_tone_bar(log_odds_tones(0.0, occupied, clear), "not updated");
  legend.bar->right_word = "occupied";
  legend.bar->left_word = "clear";
  const PlainGridOverlay overlay = [&](Drawing &page, const PlainGridFrame &frame) {
    const double thickness = std::max(1.5, frame.cell_w_px / 8);
    for (const auto &s : sensing::pie_demo_slices(o)) {
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

sensing::PieDemoOptions to_options(const DemoPieInput &input) {
  sensing::PieDemoOptions o = input.options;
  if (!input.readings.empty()) o.readings_m = parse_number_list(input.readings, "--readings");
  if (!input.mounts.empty()) o.mounts_deg = parse_number_list(input.mounts, "--mounts");
  if (!input.pose.empty()) {
    std::vector<std::string> warnings;
    const PoseArgument pose = parse_pose(input.pose, "--pose", warnings);
    for (const std::string &warning : warnings) fmt::print(stderr, "{}\n", warning);
    o.x_m = pose.x_m, o.y_m = pose.y_m, o.heading_deg = pose.yaw_deg;
  }
  sensing::validate(o);
  return o;
}

void run_demo_pie(const DemoPieInput &input) {
  const sensing::PieDemoOptions o = to_options(input);
  const auto cells = sensing::pie_demo_update(o);
  if (!input.csv_path.empty()) common::write_file_atomically(input.csv_path, csv_file(o, cells));
  if (!input.svg_path.empty()) common::write_file_atomically(input.svg_path, picture_file(o, cells, PictureFormat::svg));
  if (!input.png_path.empty()) {
    const PictureFormat format = picture_format_of_file(input.png_path).value_or(PictureFormat::png);
    common::write_file_atomically(input.png_path, picture_file(o, cells, format));
  }
  std::string out = "IR pie-slice update (Waterloo assignment, Figure 1)\n";
  out += fmt::format("half-angle {:g} deg\nresolution {:g} m\n", o.half_angle_deg, o.resolution_m);
  out += fmt::format("robot at ({:g}, {:g}) m heading {:g} deg; IR max range {:g} m; contact depth alpha {:g} m\n",
                     o.x_m, o.y_m, o.heading_deg, o.max_range_m, o.contact_m);
  out += fmt::format("per sensor and cell (four corners and centre): occupied logit({:g}) = {:+.2f}, "
                     "clear logit({:g}) = {:+.2f}\n\n",
                     sensing::kPieDemoOccupiedP, mapping::log_odds(sensing::kPieDemoOccupiedP),
                     sensing::kPieDemoClearP, mapping::log_odds(sensing::kPieDemoClearP));
  out += sensor_table(o) + "\n" + region_matrix(o, cells);
  std::string wrote;
  for (const std::string *path : {&input.csv_path, &input.svg_path, &input.png_path}) {
    if (!path->empty()) wrote += "wrote " + *path + "\n";
  }
  if (!wrote.empty()) out += "\n" + wrote;
  std::cout << out;
}

}  // namespace

std::vector<double> parse_number_list(std::string_view text, const std::string &option, std::size_t count) {
  std::vector<double> values;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    std::string_view item = text.substr(start, comma == std::string_view::npos ? text.npos : comma - start);
    item = common::trim_blanks(item);
    const std::optional<double> value = common::parse_real(item);  // finite: checked by each option
    if (!value) {
      throw common::InputError(fmt::format("{} item {} is not a number (got '{}'{})", option, values.size() + 1, item,
                                           common::range_note<double>(item)));
    }
    values.push_back(*value);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (count > 0 && values.size() != count) {
    throw common::InputError(fmt::format("{} needs {} numbers (got {})", option, count, values.size()));
  }
  return values;
}

void add_demo_pie(CLI::App &demo, CommandContext &context) {
  CLI::App *pie = demo.add_subcommand("pie", "the IR pie-slice update of Figure 1 (the course's rule)");
  auto input = std::make_shared<DemoPieInput>();
  sensing::PieDemoOptions &o = input->options;
  pie->add_option("--readings", input->readings, "comma-separated IR readings in m, left to right (default 1,1.5,1.5,0.8,1.2,1.5)");
  pie->add_option("--mounts", input->mounts, "the sensors' directions from the heading, deg, left positive (default 75,45,15,-15,-45,-75)");
  pie->add_option("--pose", input->pose, "X,Y,YAW: the robot, m and degrees (1.5708rad: radians) (default 1.5,2.5,270)");
  pie->add_option("--beta", o.half_angle_deg, fmt::format("slice half-angle, deg (default {:g})", o.half_angle_deg));
  pie->add_option("--alpha", o.contact_m, fmt::format("contact depth, m (default {:g})", o.contact_m));
  pie->add_option("--resolution", o.resolution_m, fmt::format("cell side, m (default {:g})", o.resolution_m));
  pie->add_option("--max-range", o.max_range_m, fmt::format("IR max range, m (default {:g})", o.max_range_m));
  pie->add_option("--csv", input->csv_path, "FILE: x_m,y_m,logodds of every updated cell, by its centre");
  pie->add_option("--svg", input->svg_path, "FILE: --png's picture as SVG");
  pie->add_option("--png", input->png_path, "FILE: the updated cells in map.png's tones and each slice's edges as a PNG picture (SVG or PDF when FILE ends in .svg or .pdf)");
  pie->callback([&context, input] {
    run_demo_pie(*input);
    context.status = 0;
  });
}

}  // namespace app
