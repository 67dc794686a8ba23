#pragma once
// The report of a maze run (app/run/report.hpp): its entries, built once from the run's
// options and its result.
//
//   entry            summary block            summary.json
//   size             size: 4x4                "size": "4x4"
//   width            (not printed)            "width": 4
//   goal             goal: reached            "goal": "reached"   (null unless reports_goal)

#include "app/run/report.hpp"
#include "app/run/run.hpp"

namespace app {

Report run_report(const RunOptions &options, const RunSummary &summary);

// The rule for the "goal" and "shortest_path" entries: a run reports reaching its goal when
// it was asked to reach one (the floodfill search, or a --speed-run).
bool reports_goal(const RunOptions &options);
// The "goal" entry's printed value: "reached" or "not reached".
std::string goal_text(bool reached);

}  // namespace app
