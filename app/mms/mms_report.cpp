#include "app/mms/mms_report.hpp"
#include "app/run/report_keys.hpp"

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/mms/mms_protocol.hpp"
#include "app/run/run_report.hpp"

namespace app {
namespace {

using Json = nlohmann::ordered_json;

// The ending as printed: "interrupted by SIGTERM", "failed (the algorithm ended ...)", "exited".
std::string mms_end_text(const MmsReport &r) {
  if (r.end == MmsEnd::interrupted) return r.message;
  return end_text(to_string(r.end), r.message);
}

// A stat as mms prints it (6 significant digits), printed and as a JSON number: 47.4, not the
// float's 47.400001525878906; a best-run stat before a run has finished is "-" and null.
void add_stat(Report &e, std::string key, std::optional<float> value) {
  if (!value) {
    e.both(std::move(key), "-", Json(nullptr));
    return;
  }
  const std::string text = mms_number(static_cast<double>(*value));
  e.both(std::move(key), text, Json(std::stod(text)));
}

// A count of mms's (cells, turns): printed whole, an integer in summary.json; "-" and null
// for a best-run count before a run has finished.
template <typename Count>
void add_count(Report &e, std::string key, std::optional<Count> value) {
  if (!value) e.both(std::move(key), "-", Json(nullptr));
  else e.both(std::move(key), std::to_string(*value), Json(*value));
}

}  // namespace

Report mms_report(const RunOptions &options, const MmsOptions &mms, const MmsRun &run) {
  const Report robot = run_report(options, run.summary);
  Report e;
  const auto robot_entries = [&](std::initializer_list<std::string_view> keys) {
    for (const std::string_view key : keys) {
      if (const ReportEntry *entry = robot.find(key)) e.add(*entry);
    }
  };
  const MmsReport &r = run.mms;
  const MmsStats &s = r.stats;
  robot_entries({"world", "size", "width", "height", "subcells", "model", "threshold", "robot", "seed"});
  e.both("algorithm", command_line(mms.command));
  e.both("walls", mms.walls == MmsWalls::truth ? "truth" : "sensed");
  e.both("end", mms_end_text(r), Json(std::string(to_string(r.end))));
  e.json_only("end_message", r.message);
  e.both("lines", std::to_string(r.lines), Json(r.lines));
  robot_entries({"steps", "moves"});
  e.both("crashes", std::to_string(r.crashes), Json(r.crashes));
  robot_entries({"visited"});
  e.both("goal", goal_text(run.summary.reached_goal));
  robot_entries({report_key::reachable, report_key::coverage, report_key::wall_accuracy});
  add_count(e, "total_distance", std::optional<long long>(s.total_distance()));
  add_count(e, "total_turns", std::optional<int>(s.total_turns()));
  add_stat(e, "total_effective_distance", s.total_effective_distance());
  add_count(e, "best_run_distance", s.best_run_distance());
  add_count(e, "best_run_turns", s.best_run_turns());
  add_stat(e, "best_run_effective_distance", s.best_run_effective_distance());
  add_stat(e, "score", s.score());
  robot_entries({"sim_time_s", "wall_time_ms"});
  return e;
}

}  // namespace app
