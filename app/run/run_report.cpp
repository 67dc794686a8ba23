#include "app/run/run_report.hpp"
#include "app/run/report_keys.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "app/run/step_limit.hpp"

namespace app {
namespace {

using Json = nlohmann::ordered_json;

std::string percent(double value) { return fmt::format("{:.2f}%", value); }
double two_decimals(double percent) { return std::round(percent * 100.0) / 100.0; }

template <typename T>
Json or_null(const std::optional<T> &value) {
  return value ? Json(*value) : Json(nullptr);
}

Json cell_json(mapping::Cell c) { return Json::array({c.x, c.y}); }

void add_goal_entries(Report &e, const RunOptions &o, const RunSummary &s) {
  const bool goal = reports_goal(o);
  if (goal) e.both("goal", goal_text(s.reached_goal));
  else e.json_only("goal", nullptr);
  if (goal && s.shortest) {
    e.both("shortest_path", describe_shortest(*s.shortest),
           Json{{"known_cells", or_null(s.shortest->known_moves)},
                {"optimistic_cells", or_null(s.shortest->optimistic_moves)},
                {"proven", s.shortest->proven()}});
  } else {
    e.json_only("shortest_path", nullptr);
  }
}

void add_plan_entries(Report &e, const RunSummary &s) {
  if (!s.plan) {
    e.json_only("plan", nullptr);
    e.json_only("plan_length", nullptr);
    return;
  }
  const PlanSummary &p = *s.plan;
  e.both("plan", fmt::format("({},{}) -> ({},{}) dilate {}", p.from.x, p.from.y, p.to.x, p.to.y, p.dilate),
         Json{{"from", cell_json(p.from)}, {"to", cell_json(p.to)}, {"dilate", p.dilate}});
  if (p.found) {
    e.both("plan_length", fmt::format("{} sub-cells, {} cells", p.length_subcells, p.length_cells),
           Json{{"subcells", p.length_subcells}, {"cells", p.length_cells}});
  } else {
    e.both("plan_length", "no path");
  }
}

// --localize: the verdict printed, the filter's last state and its model in summary.json.
void add_localization_entries(Report &e, const RunSummary &s) {
  if (!s.localization || s.localization->updates.empty()) {
    e.json_only("localization", nullptr);
    return;
  }
  const LocalizationSummary &l = *s.localization;
  const LocalizationUpdate &last = l.updates.back();
  Json first = nullptr;
  if (l.localized_at) first = Json{{"move", l.updates[*l.localized_at].move}, {"step", l.updates[*l.localized_at].step}};
  e.both("localization", localization_verdict(l),
         Json{{"localized", last.share >= l.localized_share},
              {"cell", last.likeliest + 1},
              {"share", last.share},
              {"robot_cell", last.robot_cell + 1},
              {"first_localized", first},
              {"updates", l.updates.size()},
              {"sensor", {l.sensor.wall_given_wall, l.sensor.open_given_wall, l.sensor.wall_given_open, l.sensor.open_given_open}},
              {"motion", l.p_move},
              {"localized_share", l.localized_share}});
}

void add_speed_run_entries(Report &e, const RunOptions &o, const RunSummary &s) {
  if (!o.plan.speed_run) {
    e.json_only("search", nullptr);
    e.json_only("speed_run", nullptr);
    e.json_only("speed_run_turns", nullptr);
    return;
  }
  e.both("search", fmt::format("{} moves, {} cells visited, {:.3f} s", s.moves, s.visited, s.explore_time_s),
         Json{{"moves", s.moves}, {"visited", s.visited}, {"time_s", s.explore_time_s}});
  const robot::SpeedRun &run = s.speed_run;
  if (!run.time_s) {
    e.both("speed_run", "none (the search did not finish, or no known path to the goal)", Json("none"));
    e.json_only("speed_run_turns", nullptr);
    return;
  }
  e.both("speed_run", fmt::format("{} cells start to goal in {:.3f} s", run.cells, *run.time_s),
         Json{{"cells", run.cells}, {"time_s", *run.time_s}, {"return_cells", run.return_cells}});
  e.both("speed_run_turns", std::to_string(run.turns), Json(run.turns));
}

}  // namespace

bool reports_goal(const RunOptions &options) {
  return options.strategy == explore::StrategyKind::floodfill || options.plan.speed_run;
}

std::string goal_text(bool reached) { return reached ? "reached" : "not reached"; }

std::string describe_shortest(const explore::ShortestPathProof &proof) {
  const std::string may = proof.optimistic_moves
                              ? fmt::format("the unknown sides may allow {}", *proof.optimistic_moves)
                              : std::string("no path even through the unknown sides");
  if (!proof.known_moves) return fmt::format("none known ({})", may);
  if (proof.proven()) return fmt::format("{} cells start to goal, proven", *proof.known_moves);
  return fmt::format("{} cells start to goal, not proven ({})", *proof.known_moves, may);
}

Report run_report(const RunOptions &o, const RunSummary &s) {
  Report e;
  e.both("world", o.world);
  e.both("size", fmt::format("{}x{}", s.width, s.height));
  e.json_only("width", s.width);
  e.json_only("height", s.height);
  e.both("subcells", std::to_string(o.subcells), Json(o.subcells));
  e.both("model", std::string(sensing::to_string(o.model.kind)));
  if (o.threshold) e.both("threshold", fmt::format("{:.3f}", *o.threshold), Json(*o.threshold));
  else e.json_only("threshold", nullptr);
  e.both("strategy", std::string(explore::to_string(o.strategy)));
  e.both("robot", o.robot);
  e.both("seed", std::to_string(o.simulation.seed), Json(o.simulation.seed));
  const std::string reason = end_reason_name(s);
  e.both("end", end_text(reason, s.message), Json(reason));
  e.json_only("end_message", s.message);
  e.both("steps", std::to_string(s.steps), Json(s.steps));
  e.both("moves", std::to_string(s.moves), Json(s.moves));
  e.both("visited", std::to_string(s.visited), Json(s.visited));
  add_goal_entries(e, o, s);
  e.both("reachable", std::to_string(s.score.reachable_cells), Json(s.score.reachable_cells));
  e.both(std::string(report_key::coverage), percent(s.score.coverage_percent()), Json(two_decimals(s.score.coverage_percent())));
  e.both(std::string(report_key::wall_accuracy), percent(s.score.wall_accuracy_percent()),
         Json(two_decimals(s.score.wall_accuracy_percent())));
  add_plan_entries(e, s);
  add_speed_run_entries(e, o, s);
  add_localization_entries(e, s);
  e.both("sim_time_s", fmt::format("{:.3f}", s.sim_time_s), Json(s.sim_time_s));
  e.both("wall_time_ms", fmt::format("{:.0f}", s.wall_time_ms), Json(s.wall_time_ms));
  return e;
}

std::string format_summary(const RunOptions &options, const RunSummary &summary) {
  return format_summary(run_report(options, summary));
}

}  // namespace app
