// maze_mapper map-log's command line; the homework is app/course/map_log.hpp.

#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli/cli_options.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/help_format.hpp"
#include "app/course/map_log.hpp"

namespace app {

void add_map_log_command(CLI::App &cli, CommandContext &context) {
  CLI::App *cmd = cli.add_subcommand("map-log", "a pose + bump/depth log mapped onto a numCells grid (the bump/depth homework)");
  auto input = std::make_shared<course::MapLogInput>();
  sensing::BumpDepthOptions &o = input->options;
  cmd->add_option("LOG", input->log_path, "CSV: t,x,y,theta and bump_right,bump_left,bump_front or depth_1..depth_9, or run --out's trace.csv")->required();
  cmd->add_option("--sensor", input->sensor, "bump or depth (default the one the log's columns hold)");
  cmd->add_option("--cells", input->cells, "X,Y: numCells (default 25,25)");
  show_as_required(*cmd->add_option("--boundary", input->boundary, "XS,XE,YS,YE: the grid's extent, m (required)"));
  cmd->add_option("--prior", o.prior, "prior probability (default 0.5)");
  cmd->add_option("--log-base", input->base, "e or 10 (default 10, the homework's)");
  CLI::Option *radius = cmd->add_option("--bump-radius", o.bump_radius_m, fmt::format("centre to the bumpers' contact points, m (default {:g})", o.bump_radius_m));
  CLI::Option *angles = cmd->add_option("--depth-angles", input->depth_angles, "A1,...,A9: depth_1..depth_9's directions, deg, left positive (default 28.5 ... -28.5)");
  CLI::Option *depth_max = cmd->add_option("--depth-max", o.depth_max_m, "depth max range, m: readings >= it are ignored (default 10)");
  CLI::Option *reading = cmd->add_option("--depth-reading", input->depth_reading,
      "range or axial: a depth reading is the range along its ray (run's trace.csv), or the depth along the "
      "sensor's forward axis, a depth camera's and the Cornell homework simulator's: range = depth / cos A "
      "(default range)");
  CLI::Option *origin = cmd->add_option("--depth-origin", input->depth_origin,
      "X,Y: the depth sensor's origin in the robot's frame, m, x forward, y left (default 0,0: the centre)");
  cmd->add_option("--threshold", input->threshold, "log-odds at or above which a cell is drawn W (default -0.5)");
  cmd->add_option("--snapshots-at", input->snapshots, "F1,F2,...: fractions of the log to write grids at (default 0.333,0.667,1; needs --out)");
  // run's --snapshots is a count; this one's fractions were --snapshots before.
  add_old_spelling(*cmd, "--snapshots", "--snapshots-at", [input](const std::string &text) { input->snapshots = text; });
  cmd->add_option("-o,--out", input->out_dir, "DIR: logodds.csv (Y rows, north first) and logodds.png, logodds_stepN.csv and .png per snapshot, thresholded.txt and .png");
  cmd->callback([&context, input, radius, angles, depth_max, reading, origin] {
    input->bump_options_given = radius->count() > 0;
    input->depth_options_given = angles->count() + depth_max->count() + reading->count() + origin->count() > 0;
    std::cout << course::run_map_log(*input);
    context.status = 0;
  });
}

}  // namespace app
