#pragma once
// The options of a maze run as the command line spells them, shared by `run` and `batch`
// so both read the same words (cmd_run.cpp).

#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/run.hpp"
#include "model_options.hpp"

namespace app {

// The run options as typed; to_run_options() checks and converts them once.
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
};

// The mapping options both commands take: --subcells --model --hit-depth --ignore-no-return
// --strategy --robot --seed --noise --p-free --p-occ --prior --log-base --clamp --max-steps.
void add_mapping_run_options(CLI::App &command, RunInput &input);

// Checks and converts; throws common::InputError naming the bad option. world is left
// empty when the input has none (run fills in the default world).
RunOptions to_run_options(const RunInput &input);

}  // namespace app
