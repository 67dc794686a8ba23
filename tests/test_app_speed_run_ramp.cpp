// The micromouse robot's speed run with its speed profile (a ramped leg a straight): clearly
// faster than its own search on the classic 16 x 16 maze at 0.18 m, on the same path.

#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "app/run/run.hpp"

TEST_CASE("speed run: the micromouse's ramped straights beat its search on classic16x16 at 0.18 m") {
  app::RunOptions options;
  options.world = std::string(WORLDS_DIR) + "/classic16x16.txt";
  options.world_overrides.cell_size_m = 0.18;
  options.robot = "micromouse";
  options.strategy = explore::StrategyKind::floodfill;
  options.plan.speed_run = true;
  options.output.quiet = true;
  std::ostringstream out;
  const app::RunSummary s = app::run_world(options, out);
  CHECK(s.reason == robot::EndReason::done);
  REQUIRE(s.shortest);
  REQUIRE(s.speed_run.time_s);
  CHECK(s.speed_run.cells == s.shortest->known_moves);
  CHECK(s.reached_goal);
  // The search drove the same 97 cells (cell by cell, stopping in each) in about 214 s.
  CHECK(*s.speed_run.time_s < 0.75 * s.explore_time_s);
}
