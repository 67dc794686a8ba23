#pragma once
// The plan after a run (run --plan-to, plan): a wavefront path on the learned grid.

#include <iosfwd>

#include "app/run/run.hpp"
#include "mapping/sensor_model.hpp"
#include "render/ascii_map.hpp"
#include "robot/cell/controller.hpp"

namespace app {

// Plans from options.plan.from (default where the robot ended) to options.plan.to on the
// learned grid and prints the map with the path drawn as '*' on `out`, or a line saying there
// is no path.
PlanSummary plan_path(const RunOptions &options, const robot::RunResult &result,
                      const mapping::SensorModel &model, render::MapStyle style, std::ostream &out);

}  // namespace app
