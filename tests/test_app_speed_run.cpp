// Acceptance of the micromouse search and speed run: whole runs with the default
// sensor noise, floodfill searching until its path is proven shortest, then the speed run
// from the start to the goal, against a breadth-first search of the true maze done here.

#include <doctest/doctest.h>

#include <cstdint>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "true_shortest.hpp"
#include "app/run/run.hpp"
#include "maze/generate/generator.hpp"
#include "maze/world/maze.hpp"

namespace {

// The true maze's shortest moves from the start to the nearest goal.
int bfs_shortest(const maze::Maze &m) {
  return test_maze::true_shortest_moves(m, m.start(), [&](maze::Cell c) { return m.is_goal(c); });
}

// A generated maze with the micromouse goal: the centre 2 x 2.
maze::Maze micromouse_maze(maze::Algorithm algorithm, int size, double loops, std::uint64_t seed) {
  maze::GeneratorOptions g;
  g.algorithm = algorithm;
  g.width = size;
  g.height = size;
  g.seed = seed;
  g.loops = loops;
  maze::Maze m = maze::generate_maze(g);
  m.clear_goals();
  for (const int y : {size / 2 - 1, size / 2}) {
    for (const int x : {size / 2 - 1, size / 2}) m.add_goal({x, y});
  }
  return m;
}

}  // namespace

TEST_SUITE("acceptance") {
  TEST_CASE("micromouse speed run: the true shortest path on every maze, every generator, with loops and without, K 3 and 5") {
    app::RunOptions options;
    options.strategy = explore::StrategyKind::floodfill;
    options.plan.speed_run = true;
    options.output.quiet = true;
    // dfs mazes are long rivers (floodfill rarely turns wrong in them); kruskal and prim
    // branch everywhere, so the search must back out of dead ends and keep searching.
    for (const maze::Algorithm algorithm : {maze::Algorithm::dfs, maze::Algorithm::kruskal, maze::Algorithm::prim}) {
      for (const int size : {16, 32}) {
        for (const double loops : {0.0, 0.2}) {
          for (const int k : {3, 5}) {
            for (std::uint64_t seed = 1; seed <= 10; ++seed) {
              const maze::Maze m = micromouse_maze(algorithm, size, loops, seed);
              options.subcells = k;
              options.simulation.seed = seed;
              options.world = fmt::format("generated {0}x{0} --algorithm {3} --loops {1} --seed {2}", size, loops, seed,
                                          static_cast<int>(algorithm));
              std::ostringstream sink;
              const app::RunSummary s = app::run_maze(options, m, sink);
              CAPTURE(options.world);
              CAPTURE(k);
              CAPTURE(s.message);
              REQUIRE(s.reason == robot::EndReason::done);
              REQUIRE(s.shortest);
              CHECK(s.shortest->proven());
              REQUIRE(s.speed_run.time_s);
              CHECK(s.speed_run.cells == bfs_shortest(m));
            }
          }
        }
      }
    }
  }
}
