// maze_mapper demo pie's command line; the demo is app/course/demo_pie.hpp.

#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "app/cli/floor_options.hpp"
#include "app/cli/demo_commands.hpp"
#include "app/course/demo_pie.hpp"

namespace app {

void add_demo_pie(CLI::App &demo, CommandContext &context) {
  CLI::App *pie = demo.add_subcommand("pie", "the IR pie-slice update of Figure 1 (the course's rule)");
  auto input = std::make_shared<course::DemoPieInput>();
  sensing::PieSliceOptions &o = input->options;
  pie->add_option("--readings", input->readings, "comma-separated IR readings in m, left to right (default 1,1.5,1.5,0.8,1.2,1.5)");
  pie->add_option("--mounts", input->mounts, "the sensors' directions from the heading, deg, left positive (default 75,45,15,-15,-45,-75)");
  pie->add_option("--pose", input->pose, "X,Y,YAW: the robot, X and Y with their unit m, YAW in degrees (1.5708rad: radians) (default 1.5m,2.5m,270)");
  pie->add_option("--beta", o.half_angle_deg, fmt::format("slice half-angle, deg (default {:g})", o.half_angle_deg));
  pie->add_option("--alpha", o.contact_m, fmt::format("contact depth, m (default {:g})", o.contact_m));
  add_resolution_option(*pie, [&o](const Length &side) { o.resolution_m = metres(side); }, fmt::format("{:g}", o.resolution_m));
  pie->add_option("--max-range", o.max_range_m, fmt::format("IR max range, m (default {:g})", o.max_range_m));
  pie->add_option("--csv", input->csv_path, "FILE: x_m,y_m,logodds of every updated cell, by its centre");
  pie->add_option("--svg", input->svg_path, "FILE: --png's picture as SVG");
  pie->add_option("--png", input->png_path, "FILE: the updated cells in map.png's tones and each slice's edges as a PNG picture (SVG or PDF when FILE ends in .svg or .pdf)");
  pie->callback([&context, input] {
    std::cout << course::run_demo_pie(*input);
    context.status = 0;
  });
}

}  // namespace app
