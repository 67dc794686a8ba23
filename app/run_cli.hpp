#pragma once
// The options of a maze run as the command line spells them, shared by `run` and `batch`
// so both read the same words (cmd_run.cpp).

#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/run.hpp"
#include "maze/world.hpp"
#include "model_options.hpp"

namespace app {

// What a command may supply or override in the world it loads, as typed: --cell-size M
// (text and num worlds), --start X,Y[,HEADING], --goal X,Y[;X,Y...].
struct WorldInput {
  std::optional<double> cell_size;
  std::string start;
  std::string goal;
};

// --cell-size alone (scan, convert), or with --start and --goal (run, compare, plan, batch).
void add_cell_size_option(CLI::App &command, WorldInput &input);
void add_world_options(CLI::App &command, WorldInput &input);

// Checks and converts; throws common::InputError naming the bad option. Cells are checked
// against the maze when it is loaded (maze::load_world).
maze::WorldOverrides to_world_overrides(const WorldInput &input);

// The run options as typed; to_run_options() checks and converts them once.
struct RunInput {
  std::string world;
  int subcells = 3;
  std::string model = "cell";
  std::string strategy = "dfs";
  int hit_depth = 0;
  bool ignore_no_return = false;
  std::optional<double> threshold;
  double pie_beta_deg = 10.0;
  double pie_alpha_m = sensing::RangeModelOptions{}.pie_contact_m;
  std::string robot;  // empty: the model's default robot (default_robot)
  std::uint64_t seed = common::kDefaultSeed;
  std::optional<double> noise;
  ModelOptionsInput sensor;
  bool ascii = false;
  std::string unknown;
  bool quiet = false;
  std::optional<std::int64_t> max_steps;
  std::string plan_from;  // X,Y (plan --from)
  std::string plan_to;    // X,Y (plan --to, run --plan-to)
  int dilate = 0;
  bool speed_run = false;
  double dropout = 0.0;
  double spikes = 0.0;
  std::string stuck_bumper;
  double wheel_slip = 0.0;
  WorldInput world_input;
};

// The mapping options run, batch, compare and plan take: --subcells --model --threshold
// --pie-beta --pie-alpha --hit-depth --ignore-no-return --strategy --robot --seed --noise
// --p-free --p-occ --prior --log-base --clamp --max-steps --dilate, and the faults
// --dropout --spikes --stuck-bumper --wheel-slip, and the world options --cell-size --start
// --goal.
void add_mapping_run_options(CLI::App &command, RunInput &input);

// Checks and converts; throws common::InputError naming the bad option. world is left
// empty when the input has none (run fills in the default world).
RunOptions to_run_options(const RunInput &input);

}  // namespace app
