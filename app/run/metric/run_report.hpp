#pragma once
// The report of a room run (app/run/report.hpp): its entries, built once from the run's options
// and its result, in the same `key: value` block and summary.json as every kind of run.
//
//   entry          summary block                                              summary.json
//   grid           grid: 50 x 30 cells of 0.1 m over 0,5,0,3                  (its parts: cells_x ... boundary_m)
//   model          model: pie                                                 "model": "pie"
//   robot          robot: ir-fan                                              "robot": "ir-fan"
//   end            end: done (no frontier left)                               "end": "done"
//   cell_accuracy  cell_accuracy: 89.13% (1337 of 1500 cells; observed ...)   89.13 (report_keys.hpp's key)
//   coverage       coverage: 98.56% (1229 of 1247 reachable free cells)       98.56 (report_keys.hpp's key)
//   sim_time_s     sim_time_s: 35.072                                         "sim_time_s": 35.072

#include <string>

#include "app/run/metric/run.hpp"
#include "app/run/report.hpp"
#include "sensing/metric/map.hpp"
#include "sensing/setups.hpp"

namespace app {

Report metric_run_report(const RunOptions &options, const std::string &robot_name, const sensing::SetUp &setup,
                   const sensing::MetricGridSpec &spec, const MetricRunSummary &summary);

}  // namespace app
