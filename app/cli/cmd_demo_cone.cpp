// maze_mapper demo cone's command line; the demo is app/course/demo_cone.hpp.

#include <iostream>
#include <memory>

#include "app/cli/floor_options.hpp"
#include "app/cli/demo_commands.hpp"
#include "app/course/demo_cone.hpp"

namespace app {

void add_demo_cone(CLI::App &demo, CommandContext &context) {
  CLI::App *cone = demo.add_subcommand("cone", "the sensor-model lecture's cone sweep (Khepera III IR or sonar)");
  auto input = std::make_shared<course::DemoConeInput>();
  cone->add_option("--sensor", input->sensor, "ir or sonar (default ir)");
  CLI::Option *range = cone->add_option("--range", input->range_m, "the reading D, m (default 0.2 for ir, 1 for sonar)");
  cone->add_option("--pose", input->pose, "X,Y,YAW: the sensor, X and Y with their unit m, YAW in degrees (1.5708rad: radians) (default 0m,0m,90)");
  add_resolution_option(*cone, [input](const Length &side) { input->resolution_m = metres(side); }, "0.01 for ir, 0.05 for sonar");
  cone->add_option("--csv", input->csv_path, "FILE: i,j of the marked cells");
  cone->add_option("--png", input->png_path, "FILE: the marked cells and the beam's edges as a PNG picture (SVG or PDF when FILE ends in .svg or .pdf)");
  cone->callback([&context, input, range] {
    input->range_given = range->count() > 0;
    std::cout << course::run_demo_cone(*input);
    context.status = 0;
  });
}

}  // namespace app
