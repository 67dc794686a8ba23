#include "app/run/step_limit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace app {

std::int64_t steps_to_reach(double time_limit_s, int step_ms) {
  const double limit_ms = time_limit_s * 1000.0;
  constexpr auto kMost = std::numeric_limits<std::int64_t>::max();
  if (!(limit_ms < 9.0e18)) return kMost;  // inf, or past int64's range
  const std::int64_t ms = std::llround(limit_ms);  // whole ms, as the simulator counts its time
  return std::max<std::int64_t>(1, ms / step_ms + (ms % step_ms != 0 ? 1 : 0));
}

void name_step_limit(const RunOptions &options, RunSummary &summary) {
  if (summary.reason != robot::EndReason::max_steps) return;
  if (summary.time_limited) {
    summary.message = fmt::format("{:g} s of simulated time", *options.time_limit_s);
  } else if (!summary.max_steps_asked) {
    // The default limit is a safety net far above what any set-up needs; reaching it is a failure.
    summary.message = fmt::format("the default limit of {} steps ran out; --max-steps N allows more", summary.max_steps);
  }
}

std::string end_reason_name(const RunSummary &summary) {
  if (summary.time_limited && summary.reason == robot::EndReason::max_steps) return std::string(kTimeLimitEnd);
  return std::string(robot::to_string(summary.reason));
}

StepLimit step_limit(const RunOptions &options, const maze::Maze &maze) {
  StepLimit limit{options.max_steps.value_or(max_steps_for(maze)), options.max_steps.has_value(), false};
  if (options.time_limit_s) {
    const std::int64_t timed = steps_to_reach(*options.time_limit_s, options.simulation.basic_time_step_ms);
    if (timed < limit.steps) limit = {timed, true, true};
  }
  return limit;
}

}  // namespace app
