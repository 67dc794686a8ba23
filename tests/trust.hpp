#pragma once
// The project's trust rule, as the tests check it: a dfs or frontier run ends `done` exactly
// when it visited every reachable cell and got every side right (app/run/run.cpp, judge_ending);
// a run that got the maze wrong ends `wrong map` or `incomplete` and says why.

#include "app/run/run.hpp"

inline bool ends_as_mapped(const app::RunSummary &s) {
  const bool right = s.score.coverage_percent() == 100.0 && s.score.wall_accuracy_percent() == 100.0;
  return (s.reason == robot::EndReason::done) == right;
}
