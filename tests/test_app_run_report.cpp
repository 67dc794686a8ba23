// The run report (app/run/run_report.hpp): one list of entries that the summary block, summary.json,
// the replay's and compare's tables and batch's columns render. Built here from hand-made
// results, so each rule is checked without a run.

#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

#include "app/batch/batch.hpp"
#include "app/run/run_report.hpp"

namespace {

app::RunSummary finished_run() {
  app::RunSummary s;
  s.width = 4;
  s.height = 4;
  s.steps = 2696;
  s.moves = 29;
  s.visited = 16;
  s.reached_goal = true;
  s.score.reachable_cells = 16;
  s.sim_time_s = 86.272;
  s.wall_time_ms = 1.4;
  return s;
}

app::RunOptions options_for(explore::StrategyKind strategy) {
  app::RunOptions o;
  o.world = "worlds/lab4x4.txt";
  o.strategy = strategy;
  return o;
}

}  // namespace

TEST_CASE("run report: the summary block is the entries with a printed value, in order") {
  const app::Report report = app::run_report(options_for(explore::StrategyKind::dfs), finished_run());
  const std::string block = app::format_summary(report);
  CHECK(block.starts_with("world: worlds/lab4x4.txt\nsize: 4x4\nsubcells: 3\nmodel: cell\nstrategy: dfs\n"));
  CHECK(block.ends_with("sim_time_s: 86.272\nwall_time_ms: 1\n"));
  CHECK(block.find("width") == std::string::npos);      // summary.json only
  CHECK(block.find("threshold") == std::string::npos);  // printed only when given
  CHECK(report.text("end") == "done");
}

TEST_CASE("run report: summary.json holds every entry, null where the run has none") {
  const app::Report report = app::run_report(options_for(explore::StrategyKind::dfs), finished_run());
  const nlohmann::ordered_json j = app::report_json(report);
  for (const auto &line : app::summary_pairs(report)) {
    CAPTURE(line.first);
    CHECK(j.contains(line.first));
  }
  CHECK(j["width"] == 4);
  CHECK(j["threshold"].is_null());
  CHECK(j["goal"].is_null());
  CHECK(j["speed_run"].is_null());
  CHECK(j.size() == report.entries().size());
}

TEST_CASE("run report: \"goal\" is reported when the run was asked to reach one, in every output") {
  app::BatchItem dfs;
  dfs.ran = true;
  dfs.summary = finished_run();
  dfs.report = app::run_report(options_for(explore::StrategyKind::dfs), dfs.summary);
  CHECK_FALSE(app::reports_goal(options_for(explore::StrategyKind::dfs)));
  CHECK(dfs.report->text("goal").empty());
  CHECK(app::row_of(dfs).goal.empty());  // reached_goal alone does not make a goal column

  app::BatchItem floodfill = dfs;
  floodfill.report = app::run_report(options_for(explore::StrategyKind::floodfill), floodfill.summary);
  CHECK(app::reports_goal(options_for(explore::StrategyKind::floodfill)));
  CHECK(floodfill.report->text("goal") == "reached");
  CHECK(app::report_json(*floodfill.report)["goal"] == "reached");
  CHECK(app::row_of(floodfill).goal == "reached");
}

TEST_CASE("run report: a speed run is one entry for the block, the JSON and batch's column") {
  app::RunOptions o = options_for(explore::StrategyKind::floodfill);
  o.plan.speed_run = true;
  app::BatchItem item;
  item.ran = true;
  item.summary = finished_run();
  item.summary.speed_run.time_s = 12.5;
  item.summary.speed_run.cells = 14;
  item.summary.speed_run.turns = 5;
  item.report = app::run_report(o, item.summary);
  CHECK(item.report->text("speed_run") == "14 cells start to goal in 12.500 s");
  CHECK(item.report->text("speed_run_turns") == "5");
  CHECK(app::report_json(*item.report)["speed_run"]["cells"] == 14);
  CHECK(app::row_of(item).speed_run == "14");
}
