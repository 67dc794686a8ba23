#pragma once
// The run report: every fact a run's outputs show, built once from the run's options and its
// result. The summary block, summary.json, replay.html's table, compare's table and CSV and
// batch's columns are renderers of it: a key, its printed form and its typed form are stated
// here and nowhere else, and nothing parses printed text back.
//
//   entry            summary block            summary.json
//   world            world: worlds/x.txt      "world": "worlds/x.txt"
//   width            (not printed)            "width": 4
//   goal             goal: reached            "goal": "reached"   (null unless reports_goal)
//   end_message      (part of "end:")         "end_message": "..."
//
// Every entry is a key of summary.json (null where the run has no value); an entry with a
// printed form is a line of the summary block, in the report's order.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/run/run.hpp"

namespace app {

struct ReportEntry {
  std::string key;
  std::optional<std::string> text;  // the summary block's value; nullopt: no line in the block
  nlohmann::ordered_json json;      // summary.json's value; null: the run has none
};

class RunReport {
 public:
  RunReport(const RunOptions &options, const RunSummary &summary);

  const std::vector<ReportEntry> &entries() const { return entries_; }
  // The entry of `key`; nullptr when the report has none (a key is never repeated).
  const ReportEntry *find(std::string_view key) const;
  // The printed value of `key`; "" when the block has no such line.
  std::string text(std::string_view key) const;

 private:
  std::vector<ReportEntry> entries_;
};

// The rule for the "goal" and "shortest_path" entries: a run reports reaching its goal when
// it was asked to reach one (the floodfill search, or a --speed-run).
bool reports_goal(const RunOptions &options);

// The summary block: `key: value` a line for every entry with a printed value, in order.
std::string format_summary(const RunReport &report);
// The same lines as (key, value) pairs, in order: replay.html's and compare's tables.
std::vector<std::pair<std::string, std::string>> summary_pairs(const RunReport &report);
// summary.json's run keys: every entry in order, null where the run has no value.
nlohmann::ordered_json report_json(const RunReport &report);

}  // namespace app
