// maze_mapper run [WORLD] [options]: explore and map one world (see app/run.hpp).

#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/run.hpp"
#include "app/run_cli.hpp"
#include "app/terminal.hpp"
#include "commands.hpp"
#include "common/error.hpp"
#include "model_options.hpp"

namespace app {
namespace {

// What only `run` takes, besides the mapping options.
struct RunOnlyInput {
  std::string out;
  bool no_color = false;
  bool animate = false;
  double fps = RunOptions{}.fps;
  double speed = RunOptions{}.speed;
  bool step = false;
};

void check_positive(const char *option, double value) {
  if (!(value > 0.0 && value <= 1e6)) {
    throw common::InputError(fmt::format("{} must be a number above 0 (got {})", option, value));
  }
}

}  // namespace

void add_mapping_run_options(CLI::App &run, RunInput &input) {
  run.add_option("--subcells", input.subcells, "K: sub-cells per cell side, odd, 3 to 9 (default 3)");
  run.add_option("--model", input.model, "mapping model: cell (default) or ray");
  run.add_option("--hit-depth", input.hit_depth, "ray model: sub-cells behind a hit also occupied (default 0)");
  run.add_flag("--ignore-no-return", input.ignore_no_return,
               "ray model: a beam with no return frees nothing (default: free up to max range)");
  run.add_option("--strategy", input.strategy,
                 "dfs (default), frontier, left-wall, right-wall or floodfill");
  run.add_option("--robot", input.robot, "robot profile (default hambot)");
  run.add_option("--seed", input.seed, "seed of the sensor noise (default 42)");
  run.add_option("--noise", input.noise,
                 "lidar noise, standard deviation as a fraction of max range (0: off; default: the robot's)");
  add_model_options(run, input.sensor);
  add_clamp_option(run, input.sensor);
  run.add_option("--max-steps", input.max_steps, "stop after this many control steps (default 2000000)");
}

RunOptions to_run_options(const RunInput &input) {
  RunOptions o;
  o.world = input.world;
  o.subcells = input.subcells;
  o.model = mapping::parse_model(input.model);
  o.hit_depth = input.hit_depth;
  o.ignore_no_return = input.ignore_no_return;
  o.strategy = explore::parse_strategy(input.strategy);
  o.robot = input.robot;
  o.seed = input.seed;
  if (input.noise && !(*input.noise >= 0.0 && *input.noise <= 1.0)) {
    throw common::InputError(
        fmt::format("--noise must be a fraction of the max range from 0 to 1 (got {})", *input.noise));
  }
  o.noise = input.noise;
  o.sensor = to_sensor_model_options(input.sensor);
  mapping::validate(o.sensor);
  o.ascii = input.ascii;
  if (!input.unknown.empty()) {
    if (input.unknown.size() != 1 || static_cast<unsigned char>(input.unknown[0]) < 0x20 ||
        static_cast<unsigned char>(input.unknown[0]) > 0x7e || input.unknown == "W") {
      throw common::InputError(fmt::format(
          "--unknown must be one printable ASCII character other than W (got '{}')", input.unknown));
    }
    o.unknown = input.unknown[0];
  }
  o.quiet = input.quiet;
  if (input.max_steps < 1) {
    throw common::InputError(fmt::format("--max-steps must be at least 1 (got {})", input.max_steps));
  }
  o.max_steps = input.max_steps;
  return o;
}

std::string default_world() {
  const std::string relative = "worlds/lab4x4.txt";
  if (std::filesystem::exists(relative)) return relative;
  return std::string(MAZE_MAPPER_WORLDS_DIR) + "/lab4x4.txt";
}

void add_run_command(CLI::App &cli, CommandContext &context) {
  auto input = std::make_shared<RunInput>();
  auto only = std::make_shared<RunOnlyInput>();
  CLI::App *run = cli.add_subcommand(
      "run", "explore a world cell by cell and map it; print the map as it goes and a summary");
  run->add_option("WORLD", input->world, "maze file (default worlds/lab4x4.txt)");
  add_mapping_run_options(*run, *input);
  run->add_flag("--ascii", input->ascii, "heading arrows as ^ > v < instead of ↑ → ↓ ←");
  run->add_option("--unknown", input->unknown, "CHAR drawn for never-observed sub-cells (default blank)");
  run->add_flag("--quiet", input->quiet, "print only the final map and the summary");
  run->add_option("--out", only->out,
                  "DIR: write map.pgm + map.yaml (ROS map_server), map.png, summary.json, trace.csv");
  run->add_flag("--no-color", only->no_color, "no ANSI colours (default: colours when stdout is a terminal)");
  run->add_flag("--animate", only->animate, "redraw the map in place as the robot moves");
  run->add_option("--fps", only->fps, "--animate: frames per second, at most (default 30)");
  run->add_option("--speed", only->speed,
                  "--animate: simulated seconds per wall-clock second (default 10)");
  run->add_flag("--step", only->step, "stop after each cell: Enter goes on, q quits");
  run->callback([input, only, &context] {
    RunOptions options = to_run_options(*input);
    if (options.world.empty()) options.world = default_world();
    check_positive("--fps", only->fps);
    check_positive("--speed", only->speed);
    options.out_dir = only->out;
    options.color = !only->no_color && is_terminal(STDOUT_FILENO);
    options.animate = only->animate;
    options.fps = only->fps;
    options.speed = only->speed;
    options.step = only->step;
    RunControls controls;
    controls.in = &std::cin;
    if (options.step && is_terminal(STDIN_FILENO)) controls.prompt = &std::cerr;
    controls.interrupted = &SigintGuard::interrupted;
    controls.terminal_fd = STDOUT_FILENO;
    const SigintGuard sigint;
    const RunSummary summary = run_world(options, std::cout, controls);
    context.status = exit_status(summary);
  });
}

}  // namespace app
