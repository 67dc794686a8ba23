// maze_mapper demo trilaterate's and demo localize's command lines; the demos are
// app/course/demo_trilaterate.hpp and app/course/demo_localize.hpp.

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "app/cli/cli_options.hpp"
#include "app/cli/demo_commands.hpp"
#include "app/course/demo_localize.hpp"
#include "app/course/demo_trilaterate.hpp"
#include "common/error.hpp"
#include "common/parse_number.hpp"

namespace app {

void add_demo_trilaterate(CLI::App &demo, CommandContext &context) {
  CLI::App *tri = demo.add_subcommand("trilaterate", "the localization lab's Task 1: a pose from distances to the corner landmarks");
  auto input = std::make_shared<course::DemoTrilaterateInput>();
  auto seed = std::make_shared<std::uint64_t>(1);
  tri->add_option("--distances", input->distances,
                  fmt::format("Y,R,G[,B]: distances in m to yellow (NW), red (NE), green (SW)[, blue (SE)]; "
                              "in a list of four one may be - (not measured) (default {})", course::kDefaultDistances));
  tri->add_option("--pose", input->pose, "X,Y: the robot in m; the four distances computed from it");
  tri->add_option("--noise", input->noise_m, "SIGMA: with --pose, Gaussian noise in m on each distance");
  CLI::Option *seed_option = add_seed_option(*tri, *seed, "--noise's draws");
  tri->add_option("--sigma", input->sigma_m, fmt::format("the probabilistic variant's sigma, m (default {:g})", input->sigma_m));
  tri->callback([&context, input, seed, seed_option] {
    if (seed_option->count() > 0) input->seed = *seed;
    std::cout << course::run_demo_trilaterate(*input);
    context.status = 0;
  });
}

void add_demo_localize(CLI::App &demo, CommandContext &context) {
  CLI::App *cmd = demo.add_subcommand("localize", "the localization lab's Task 2: a grid Bayes filter over a known maze's cells");
  auto input = std::make_shared<course::DemoLocalizeInput>();
  auto seed = std::make_shared<std::uint64_t>(1);
  course::DemoLocalizeInput &o = *input;
  accept_shipped_world_names(cmd->add_option("WORLD", o.world, fmt::format("the maze (default {}, shipped)", course::kLocalizeWorld)));
  cmd->add_option("--start", o.start, "CELL: the robot's start cell, numbered row by row from the north-west (default the world's start)");
  cmd->add_option("--moves", o.moves, "N,E,S,...: the robot's moves (default the right-hand rule)");
  cmd->add_option("--max-steps", o.max_steps, fmt::format("at most this many moves (default {})", o.max_steps));
  cmd->add_option("--motion", o.motion, fmt::format("P: a move succeeds with P, else the robot stays (default {:g})", o.motion));
  cmd->add_option("--sensor", o.sensor, "P1,P2,P3,P4: P(z=wall|wall), P(z=no wall|wall), P(z=wall|no wall), P(z=no wall|no wall) (default 0.8,0.2,0.4,0.6)");
  cmd->add_option("--localized", o.localized, fmt::format("F: done when one cell holds F of the belief or particles (default {:g})", o.localized));
  CLI::Option *seed_option = add_seed_option(*cmd, *seed, "noisy moves and readings, and the particles' draws");
  auto particles = std::make_shared<std::string>();
  CLI::Option *particles_option =
      cmd->add_option("--particles", *particles, "[N]: a particle filter of N particles (N left out: 250)")->expected(0, 1);
  cmd->add_flag("--explain", o.explain, "work step 0's correction by hand, cell by cell");
  cmd->callback([&context, input, seed, seed_option, particles, particles_option] {
    if (seed_option->count() > 0) input->seed = *seed;
    if (particles_option->count() > 0) {
      const std::optional<int> n = particles->empty() ? 250 : common::parse_number<int>(*particles);
      if (!n) throw common::InputError(fmt::format("--particles must be a whole number (got '{}')", *particles));
      input->particles = n;
    }
    std::cout << course::run_demo_localize(*input).text;
    context.status = 0;
  });
}

}  // namespace app
