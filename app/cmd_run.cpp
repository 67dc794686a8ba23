// maze_mapper run [WORLD] [options]: explore and map one world (see app/run.hpp).

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/run.hpp"
#include "commands.hpp"
#include "common/error.hpp"
#include "model_options.hpp"

namespace app {
namespace {

// run's options as typed; to_run_options() checks and converts them once.
struct RunInput {
  std::string world;
  int subcells = 3;
  std::string model = "cell";
  std::string strategy = "dfs";
  int hit_depth = 0;
  bool ignore_no_return = false;
  std::string robot = "hambot";
  std::uint64_t seed = common::kDefaultSeed;
  std::optional<double> noise;
  ModelOptionsInput sensor;
  bool ascii = false;
  std::string unknown;
  bool quiet = false;
  std::int64_t max_steps = RunOptions{}.max_steps;
  double dropout = 0.0;
  double spikes = 0.0;
  std::string stuck_bumper;
  double wheel_slip = 0.0;
};

RunOptions to_run_options(const RunInput &input) {
  RunOptions o;
  o.world = input.world.empty() ? default_world() : input.world;
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
  o.dropout = input.dropout;
  o.spikes = input.spikes;
  o.stuck_bumper = input.stuck_bumper;
  o.wheel_slip = input.wheel_slip;
  return o;
}

}  // namespace

std::string default_world() {
  const std::string relative = "worlds/lab4x4.txt";
  if (std::filesystem::exists(relative)) return relative;
  return std::string(MAZE_MAPPER_WORLDS_DIR) + "/lab4x4.txt";
}

void add_run_command(CLI::App &cli, CommandContext &context) {
  auto input = std::make_shared<RunInput>();
  CLI::App *run = cli.add_subcommand(
      "run", "explore a world cell by cell and map it; print the map as it goes and a summary");
  run->add_option("WORLD", input->world, "maze file (default worlds/lab4x4.txt)");
  run->add_option("--subcells", input->subcells, "K: sub-cells per cell side, odd, 3 to 9 (default 3)");
  run->add_option("--model", input->model, "mapping model: cell (default) or ray");
  run->add_option("--hit-depth", input->hit_depth, "ray model: sub-cells behind a hit also occupied (default 0)");
  run->add_flag("--ignore-no-return", input->ignore_no_return,
                "ray model: a beam with no return frees nothing (default: free up to max range)");
  run->add_option("--strategy", input->strategy,
                  "dfs (default), frontier, left-wall, right-wall or floodfill");
  run->add_option("--robot", input->robot, "robot profile (default hambot)");
  run->add_option("--seed", input->seed, "seed of the sensor noise (default 42)")
      ->check(CLI::Validator(
          [](std::string &text) {
            // CLI11 would read "-1" as 2^64 - 1.
            return text.find('-') == std::string::npos
                       ? std::string()
                       : "must be a whole number from 0 (got '" + text + "')";
          },
          ""));
  run->add_option("--noise", input->noise,
                  "lidar noise, standard deviation as a fraction of max range (0: off; default: the robot's)");
  add_model_options(*run, input->sensor);
  add_clamp_option(*run, input->sensor);
  run->add_flag("--ascii", input->ascii, "heading arrows as ^ > v < instead of ↑ → ↓ ←");
  run->add_option("--unknown", input->unknown, "CHAR drawn for never-observed sub-cells (default blank)");
  run->add_flag("--quiet", input->quiet, "print only the final map and the summary");
  run->add_option("--max-steps", input->max_steps, "stop after this many control steps (default 2000000)");
  run->add_option("--dropout", input->dropout, "fault: fraction of lidar beams that read +infinity (default 0)");
  run->add_option("--spikes", input->spikes, "fault: fraction of lidar beams that read a random range (default 0)");
  run->add_option("--stuck-bumper", input->stuck_bumper, "fault: NAME, a bumper that always reads pressed");
  run->add_option("--wheel-slip", input->wheel_slip,
                  "fault: fraction of wheel turning that does not move the robot; encoders count it all (default 0)");
  run->callback([input, &context] {
    const RunOptions options = to_run_options(*input);
    if (context.run_parse_only != nullptr) {
      *context.run_parse_only = options;
      return;
    }
    const RunSummary summary = run_world(options, std::cout);
    context.status = exit_status(summary);
  });
}

}  // namespace app
