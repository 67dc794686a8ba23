#pragma once
// The report of a run, whatever its kind (a maze run, a room run, an mms program's run): every
// fact the run's outputs show, built once from the run's options and its result. The summary
// block, summary.json, replay.html's table, compare's table and batch's columns are renderers
// of it: a key, its printed form and its typed form are stated where the report is built and
// nowhere else, and nothing parses printed text back.
//
//   entry            summary block            summary.json
//   world            world: worlds/x.txt      "world": "worlds/x.txt"
//   width            (not printed)            "width": 4
//   end              end: done                "end": "done"
//   end_message      (part of "end:")         "end_message": "..."
//
// Every kind of run reports the core keys, in this order among its own: world, model,
// strategy, robot, seed, end, end_message, steps, sim_time_s, wall_time_ms. Every entry is a key
// of summary.json (null where the run has no value); an entry with a printed form is a line of
// the summary block, in the report's order.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace app {

struct ReportEntry {
  std::string key;
  std::optional<std::string> text;  // the summary block's value; nullopt: no line in the block
  nlohmann::ordered_json json;      // summary.json's value; null: the run has none
};

class Report {
 public:
  const std::vector<ReportEntry> &entries() const { return entries_; }
  // The entry of `key`; nullptr when the report has none (a key is never repeated).
  const ReportEntry *find(std::string_view key) const;
  // The printed value of `key`; "" when the block has no such line.
  std::string text(std::string_view key) const;

  // Appends an entry printed as `text`, in summary.json as `json`.
  void both(std::string key, std::string text, nlohmann::ordered_json json);
  // Appends an entry printed and in summary.json as the same string.
  void both(std::string key, const std::string &text);
  // Appends an entry of summary.json only.
  void json_only(std::string key, nlohmann::ordered_json json);
  // Appends `entry` as it is (an entry of another report: a kind's report built on another's).
  void add(ReportEntry entry);

 private:
  std::vector<ReportEntry> entries_;
};

// The summary block: `key: value` a line for every entry with a printed value, in order.
std::string format_summary(const Report &report);
// The same lines as (key, value) pairs, in order: replay.html's and compare's tables.
std::vector<std::pair<std::string, std::string>> summary_pairs(const Report &report);
// summary.json's run keys: every entry in order, null where the run has no value.
nlohmann::ordered_json report_json(const Report &report);
// The "end" entry's printed form: the ending, then its message in parentheses when it has one.
std::string end_text(std::string_view ending, std::string_view message);

}  // namespace app
