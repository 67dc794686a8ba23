// The exit status a run ends with (the summary block itself: app/run/run_report.hpp).

#include <string>
#include <string_view>

#include <fmt/format.h>

#include "app/run/run.hpp"
#include "common/interrupt.hpp"

namespace app {
namespace {

int ending_status(const RunSummary &summary) {
  switch (summary.reason) {
    case robot::EndReason::done: return 0;
    case robot::EndReason::max_steps: return summary.max_steps_asked ? 0 : 1;
    case robot::EndReason::no_progress:
    case robot::EndReason::incomplete:
    case robot::EndReason::wrong_map:
    case robot::EndReason::simulation_ended: return 1;
    case robot::EndReason::stopped: return summary.interrupted ? common::interrupted_exit_status() : 0;
  }
  return 1;
}

}  // namespace

int exit_status(const RunSummary &summary) {
  const int status = ending_status(summary);
  // A path was asked for (plan, run --plan-to, --speed-run) and none found or driven: not the
  // run that was asked, whichever command asked (run --plan-to exited 0 where plan exits 1).
  const bool no_path = (summary.plan && !summary.plan->found) || (summary.speed_run_asked && !summary.speed_run.time_s);
  return status == 0 && no_path ? 1 : status;
}

}  // namespace app
