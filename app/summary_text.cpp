// The summary block a run ends with (DESIGN §9) and the exit status it ends with.

#include <string>
#include <string_view>

#include <fmt/format.h>

#include "app/run.hpp"
#include "common/interrupt.hpp"

namespace app {
namespace {

std::string percent(double value) { return fmt::format("{:.2f}%", value); }

}  // namespace

std::string describe_shortest(const explore::ShortestPathProof &proof) {
  const std::string may = proof.optimistic_moves
                              ? fmt::format("the unknown sides may allow {}", *proof.optimistic_moves)
                              : std::string("no path even through the unknown sides");
  if (!proof.known_moves) return fmt::format("none known ({})", may);
  if (proof.proven()) return fmt::format("{} cells start to goal, proven", *proof.known_moves);
  return fmt::format("{} cells start to goal, not proven ({})", *proof.known_moves, may);
}

std::string format_summary(const RunOptions &options, const RunSummary &s) {
  std::string text;
  auto line = [&text](std::string_view key, const std::string &value) {
    text += fmt::format("{}: {}\n", key, value);
  };
  line("world", options.world);
  line("size", fmt::format("{}x{}", s.width, s.height));
  line("subcells", std::to_string(options.subcells));
  line("model", std::string(sensing::to_string(options.model.kind)));
  if (options.threshold) line("threshold", fmt::format("{:.3f}", *options.threshold));
  line("strategy", std::string(explore::to_string(options.strategy)));
  line("robot", options.robot);
  line("seed", std::to_string(options.simulation.seed));
  line("end", s.message.empty() ? std::string(robot::to_string(s.reason))
                                : fmt::format("{} ({})", robot::to_string(s.reason), s.message));
  line("steps", std::to_string(s.steps));
  line("moves", std::to_string(s.moves));
  line("visited", std::to_string(s.visited));
  const bool micromouse = options.strategy == explore::StrategyKind::floodfill || options.plan.speed_run;
  if (micromouse) line("goal", s.reached_goal ? "reached" : "not reached");
  if (micromouse && s.shortest) line("shortest_path", describe_shortest(*s.shortest));
  line("reachable", std::to_string(s.score.reachable_cells));
  line("coverage", percent(s.score.coverage_percent()));
  line("wall_accuracy", percent(s.score.wall_accuracy_percent()));
  if (s.plan) {
    line("plan", fmt::format("({},{}) -> ({},{}) dilate {}", s.plan->from.x, s.plan->from.y, s.plan->to.x,
                             s.plan->to.y, s.plan->dilate));
    line("plan_length", s.plan->found ? fmt::format("{} sub-cells, {} cells", s.plan->length_subcells,
                                                    s.plan->length_cells)
                                      : std::string("no path"));
  }
  if (options.plan.speed_run) {
    line("search", fmt::format("{} moves, {} cells visited, {:.3f} s", s.moves, s.visited, s.explore_time_s));
    const robot::SpeedRun &run = s.speed_run;
    line("speed_run", run.time_s ? fmt::format("{} cells start to goal in {:.3f} s", run.cells, *run.time_s)
                                 : std::string("none (the search did not finish, or no known path to the goal)"));
    if (run.time_s) line("speed_run_turns", std::to_string(run.turns));
  }
  line("sim_time_s", fmt::format("{:.3f}", s.sim_time_s));
  line("wall_time_ms", fmt::format("{:.0f}", s.wall_time_ms));
  return text;
}

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
