#pragma once
// A run's step limit: --max-steps (or max_steps_for's safety net) and --time-limit, simulated
// seconds, turned into control steps, and the words a run stopped by it ends with.

#include <cstdint>
#include <string>
#include <string_view>

#include "app/run/run.hpp"

namespace app {

// The control steps of `step_ms` it takes simulated time to reach `time_limit_s` (in whole ms):
// the run ends with the first step at or past the limit, as the simulator's own time limit
// (SimulationOptions::time_limit_s), a room run's and the Python runner's end it. At least 1,
// saturating at the largest step count (a limit of 1e300 s or inf is no limit).
std::int64_t steps_to_reach(double time_limit_s, int step_ms);
// The step limit in effect for options on maze: --max-steps (or max_steps_for's), lowered to
// what --time-limit allows.
struct StepLimit {
  std::int64_t steps = 0;
  bool asked = false;         // --max-steps or --time-limit set it, not max_steps_for
  bool time_limited = false;  // --time-limit's is the lower
};
StepLimit step_limit(const RunOptions &options, const maze::Maze &maze);
// A run stopped by its step limit says which: `S s of simulated time` (--time-limit's), or the
// default limit (a failure); a --max-steps the user gave needs no words.
void name_step_limit(const RunOptions &options, RunSummary &summary);
// The `end` of a run --time-limit stopped.
inline constexpr std::string_view kTimeLimitEnd = "time limit";
// The summary's `end`: kTimeLimitEnd for a run --time-limit stopped, else the controller's
// reason (`done`, `max steps`, ...).
std::string end_reason_name(const RunSummary &summary);

}  // namespace app
