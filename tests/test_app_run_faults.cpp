// Acceptance under simulated faults: with 5 % of the lidar beams dropped (+inf) and
// 1 % spiked (a random range), the mapper still maps every generated 16 x 16 maze to the end,
// every cell visited, with wall_accuracy >= 99 %, with the cell model and with the ray model.
// The scan filter (sensing/scan_filter.hpp) and the rescans of an unknown side make it so.
// The `acceptance` suite: CTest runs it in optimised builds only (tests/CMakeLists.txt).

#include <doctest/doctest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "app/run/run.hpp"
#include "trust.hpp"
#include "maze/generate/generator.hpp"

namespace {

constexpr int kSeeds = 50;

void check_faulty_mapping(sensing::ModelKind model) {
  app::RunOptions options;
  options.model.kind = model;
  options.output.quiet = true;
  options.simulation.dropout = 0.05;
  options.simulation.spikes = 0.01;
  std::size_t sides = 0, correct = 0;
  double worst = 100.0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    maze::GeneratorOptions g;
    g.width = g.height = 16;
    g.seed = static_cast<std::uint64_t>(seed);
    const maze::Maze m = maze::generate_maze(g);
    options.world = fmt::format("generated 16x16 seed {}", seed);
    options.simulation.seed = static_cast<std::uint64_t>(seed);
    std::ostringstream sink;
    const app::RunSummary s = app::run_maze(options, m, sink);
    CAPTURE(seed);
    CAPTURE(s.message);
    REQUIRE(s.reason == robot::EndReason::done);
    CHECK(ends_as_mapped(s));
    CHECK(s.score.coverage_percent() == 100.0);
    CHECK(s.score.wall_accuracy_percent() >= 99.0);
    worst = std::min(worst, s.score.wall_accuracy_percent());
    sides += s.score.sides;
    correct += s.score.sides_correct;
  }
  MESSAGE(fmt::format("{}: {} of {} sides right over {} mazes, worst maze {:.2f} %",
                      sensing::to_string(model), correct, sides, kSeeds, worst));
}

}  // namespace

TEST_SUITE("acceptance") {
  TEST_CASE("faults with the cell model: 5 % dropout and 1 % spikes keep wall_accuracy at least 99 % on 16x16 mazes") {
    check_faulty_mapping(sensing::ModelKind::cell);
  }
  TEST_CASE("faults with the ray model: 5 % dropout and 1 % spikes keep wall_accuracy at least 99 % on 16x16 mazes") {
    check_faulty_mapping(sensing::ModelKind::ray);
  }
}
