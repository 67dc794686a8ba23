// The truth's verdict on a run's ending (app/run.cpp, judge_ending): a run that got the maze
// wrong never ends `done` (exit status 0). Regression (the trust sweep): `run worlds/lab4x4.txt
// --robot sonar-ring --model pie --seed 1` ended "done" at 67.50 % wall accuracy, and
// `--robot bumper-depth --model cone --seed 1` at 82.50 %.

#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "app/evaluation.hpp"
#include "app/run.hpp"

namespace {

app::RunSummary run_lab4x4(const std::string &robot, sensing::ModelKind model, explore::StrategyKind strategy) {
  app::RunOptions options;
  options.world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  options.robot = robot;
  options.model.kind = model;
  options.strategy = strategy;
  options.simulation.seed = 1;
  options.output.quiet = true;
  std::ostringstream sink;
  return app::run_world(options, sink);
}

}  // namespace

TEST_CASE("judge_ending: every cell visited but sides wrong is incomplete, exit status 1") {
  for (const auto &[robot, model] : {std::pair{"sonar-ring", sensing::ModelKind::pie},
                                     std::pair{"bumper-depth", sensing::ModelKind::cone}}) {
    const app::RunSummary s = run_lab4x4(robot, model, explore::StrategyKind::dfs);
    CAPTURE(robot);
    CAPTURE(s.message);
    REQUIRE(s.score.coverage_percent() == 100.0);
    REQUIRE(s.score.wall_accuracy_percent() < 100.0);
    CHECK(s.reason == robot::EndReason::incomplete);
    CHECK(s.message.find("of 40 sides mapped wrong") != std::string::npos);
    CHECK(app::exit_status(s) == 1);
  }
}

TEST_CASE("judge_ending: done means every reachable cell visited and every side right") {
  const app::RunSummary s = run_lab4x4("hambot", sensing::ModelKind::cell, explore::StrategyKind::dfs);
  CHECK(s.reason == robot::EndReason::done);
  CHECK(s.score.wall_accuracy_percent() == 100.0);
  CHECK(app::exit_status(s) == 0);
}

TEST_CASE("judge_ending: floodfill leaves sides unknown by design and stays done; none is contradicted") {
  const app::RunSummary s = run_lab4x4("hambot", sensing::ModelKind::cell, explore::StrategyKind::floodfill);
  CHECK(s.reason == robot::EndReason::done);
  CHECK(s.score.wall_accuracy_percent() < 100.0);
  CHECK(s.score.sides_contradicted == 0);
}

TEST_CASE("score_map: a side learned wrong is contradicted, an unknown one is not") {
  maze::Maze m(2, 1);
  m.set_start({0, 0}, maze::Side::north);
  // Sides N0 S0 W0 N1 S1 E1 (walls) and the shared 0|1 (open): a phantom wall on the shared
  // side, the north of (1,0) never observed, the rest right.
  const auto learned = [&m](maze::Cell c, maze::Side s) {
    if (c == maze::Cell{0, 0} && s == maze::Side::east) return app::LearnedSide::wall;
    if (c == maze::Cell{1, 0} && s == maze::Side::north) return app::LearnedSide::unknown;
    return m.has_wall(c, s) ? app::LearnedSide::wall : app::LearnedSide::open;
  };
  const app::MapScore score = app::score_map(m, {true, true}, learned);
  CHECK(score.sides == 7);
  CHECK(score.sides_correct == 5);
  CHECK(score.sides_contradicted == 1);
}

// Regression (the trust sweep): `run --wheel-slip 0.98` ran out of the default step limit
// (100,000 steps; no --max-steps given) at 93.75 % coverage and exited 0.
TEST_CASE("the default step limit running out is a failure; a --max-steps the user gave is not") {
  app::RunOptions options;
  options.world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  options.output.quiet = true;
  options.simulation.wheel_slip = 0.98;
  std::ostringstream sink;
  const app::RunSummary limited = app::run_world(options, sink);
  CHECK(limited.reason == robot::EndReason::max_steps);
  CHECK(limited.message.find("the default limit of 100000 steps ran out") != std::string::npos);
  CHECK(app::exit_status(limited) == 1);
  options.max_steps = 100000;
  const app::RunSummary asked = app::run_world(options, sink);
  CHECK(asked.reason == robot::EndReason::max_steps);
  CHECK(asked.message.empty());
  CHECK(app::exit_status(asked) == 0);
}
