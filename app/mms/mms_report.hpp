#pragma once
// The report of an mms program's run (app/run/report.hpp): the robot's run as a maze run
// reports it (run_report: world, size, model, robot, seed, steps, moves, visited, reachable,
// coverage, wall_accuracy, times), with the program's ending, its goal and mms's stats in
// their place. The summary block, summary.json (with "options") and replay.html's table show it.
//
//   entry                summary block                                 summary.json
//   algorithm            algorithm: python3 algo.py                    "algorithm": "python3 algo.py"
//   walls                walls: sensed                                 "walls": "sensed"
//   end                  end: exited (the algorithm ended (exit ...    "end": "exited"
//   lines                lines: 212                                    "lines": 212
//   crashes              crashes: 0                                    "crashes": 0
//   goal                 goal: reached                                 "goal": "reached"
//   total_distance ...   total_distance: 47                            "total_distance": 47
//   best_run_distance    best_run_distance: -                          "best_run_distance": null
//   score                score: 2000                                   "score": 2000

#include "app/mms/mms_session.hpp"
#include "app/run/report.hpp"
#include "app/run/run_options.hpp"

namespace app {

Report mms_report(const RunOptions &options, const MmsOptions &mms, const MmsRun &run);

}  // namespace app
