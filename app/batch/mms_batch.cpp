#include "common/csv.hpp"
#include "app/batch/mms_batch.hpp"

#include <algorithm>
#include <ostream>
#include <sstream>

#include <fmt/format.h>

#include "app/batch/batch.hpp"
#include "app/run/run_report.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"

namespace app {
namespace {

// The row of a run that ended: the robot's run as a maze run's report has it, with the
// algorithm as its strategy, mms's ending and its score.
BatchRow mms_row(const RunOptions &options, const MmsOptions &mms, const MmsRun &run) {
  BatchRow row = row_from_report(run_report(options, run.summary));
  row.strategy = command_line(mms.command);
  row.end = std::string(to_string(run.mms.end));
  row.end_message = run.mms.end == MmsEnd::interrupted ? std::string() : run.mms.message;
  row.goal = run.summary.reached_goal ? "reached" : "not reached";
  row.score = run.mms.stats.score();
  return row;
}

MmsBatchItem run_one(RunOptions options, const MmsOptions &mms, const std::string &world, bool (*interrupted)()) {
  MmsBatchItem item;
  item.world = world;
  options.world = world;
  options.output.quiet = true;
  RunControls controls;
  controls.interrupted = interrupted;
  std::ostringstream sink;
  run_row(item, [&] {
    item.run = run_mms_world(options, mms, sink, controls);
    item.row = mms_row(options, mms, item.run);
    item.ran = true;
    item.interrupted = item.run.mms.end == MmsEnd::interrupted;
    item.ok = exit_status(item.run) == 0;
    if (!item.ok) {
      const MmsReport &r = item.run.mms;
      const bool as_asked = r.end == MmsEnd::exited || r.end == MmsEnd::reached;
      if (item.interrupted) {
        item.error = r.message;  // "interrupted by SIGTERM"
      } else {
        item.error = as_asked ? fmt::format("{}, but the goal was not reached", r.message)
                              : fmt::format("{}: {}", to_string(r.end), r.message);
      }
    }
  });
  item.row.world = item.world;
  item.row.kind = RunKind::mms;
  item.row.ran = item.ran;
  item.row.ok = item.ok;
  item.row.interrupted = item.interrupted;
  item.row.error = item.error;
  return item;
}

std::string optional_number(const auto &value) { return value ? mms_number(static_cast<double>(*value)) : std::string(); }

// The cells of one row, the table's and the CSV's alike (empty where a run did not happen).
std::vector<std::string> cells_of(const MmsBatchItem &item) {
  if (!item.ran) return {item.world, "", item.interrupted ? "interrupted" : "failed", "", "", "", "", "", "", "", "", "", "", "", item.error};
  const RunSummary &s = item.run.summary;
  const MmsReport &r = item.run.mms;
  const MmsStats &st = r.stats;
  return {item.world,
          fmt::format("{}x{}", s.width, s.height),
          std::string(to_string(r.end)),
          std::to_string(r.lines),
          std::to_string(s.moves),
          s.reached_goal ? "reached" : "not reached",
          std::to_string(st.total_distance()),
          std::to_string(st.total_turns()),
          mms_number(st.total_effective_distance()),
          optional_number(st.best_run_distance()),
          optional_number(st.best_run_turns()),
          optional_number(st.best_run_effective_distance()),
          mms_number(st.score()),
          fmt::format("{:.0f}", s.wall_time_ms),
          item.error};
}

}  // namespace

std::vector<MmsBatchItem> run_mms_batch(const RunOptions &options, const MmsOptions &mms,
                                        const std::vector<std::string> &worlds, int jobs,
                                        const std::function<void(std::size_t, std::size_t)> &progress,
                                        bool (*interrupted)()) {
  std::vector<MmsBatchItem> items(worlds.size());
  for_each_in_pool(
      worlds.size(), jobs, [&](std::size_t i) { items[i] = run_one(options, mms, worlds[i], interrupted); },
      [&](std::size_t i) {
        items[i].world = worlds[i];
        items[i].interrupted = true;
        items[i].error = "not run (interrupted by " + common::interrupt_name() + ")";
      },
      progress, interrupted);
  return items;
}

std::string format_mms_batch_table(const std::vector<MmsBatchItem> &items, double elapsed_ms,
                                   const std::vector<std::string> &skipped) {
  const std::vector<std::string> header{"world", "size", "end", "lines", "moves", "goal", "distance", "turns",
                                        "effective", "best_run", "score", "ms"};
  std::vector<std::vector<std::string>> rows;
  int ok = 0;
  int interrupted = 0;
  int reached = 0;
  int ran = 0;
  double score_sum = 0.0;
  for (const MmsBatchItem &item : items) {
    std::vector<std::string> c = cells_of(item);
    const std::string best = item.ran && item.run.mms.stats.solved()
                                 ? fmt::format("{}/{}/{}", c[9], c[10], c[11])
                                 : (item.ran ? "-" : "");
    rows.push_back({c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], best, c[12], c[13], c[14]});
    ok += item.ok ? 1 : 0;
    interrupted += item.interrupted ? 1 : 0;
    if (item.ran && !item.interrupted) {  // an interrupted run is shown, not counted
      ++ran;
      reached += item.run.summary.reached_goal ? 1 : 0;
      score_sum += item.run.mms.stats.score();
    }
  }
  std::vector<std::size_t> widths(header.size());
  for (std::size_t i = 0; i < header.size(); ++i) widths[i] = header[i].size();
  for (const auto &row : rows) {
    for (std::size_t i = 0; i < header.size(); ++i) widths[i] = std::max(widths[i], row[i].size());
  }
  std::string out;
  const auto add_row = [&](const std::vector<std::string> &row) {
    std::string line;
    for (std::size_t i = 0; i < header.size(); ++i) line += fmt::format("{:<{}}  ", row[i], widths[i]);
    if (row.size() > header.size() && !row.back().empty()) line += row.back();
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + '\n';
  };
  add_row(header);
  for (const auto &row : rows) add_row(row);
  const int failed = static_cast<int>(items.size()) - ok - interrupted;
  out += fmt::format("total: {} worlds, {} ok, {} failed", items.size(), ok, failed);
  if (interrupted > 0) out += fmt::format(", {} interrupted", interrupted);
  out += fmt::format("; goal reached {} of {}; mean score {}\n", reached, ran, ran ? mms_number(score_sum / ran) : "-");
  out += fmt::format("elapsed: {:.0f} ms\n", elapsed_ms);
  if (!skipped.empty()) out += fmt::format("skipped, not mazes: {} file{}\n", skipped.size(), skipped.size() == 1 ? "" : "s");
  return out;
}

std::string format_mms_batch_csv(const std::vector<MmsBatchItem> &items) {
  std::string out = batch_csv_header() + '\n';
  for (const MmsBatchItem &item : items) {
    if (!item.interrupted) out += format_batch_csv_row(item.row);
  }
  return out;
}

int mms_batch_exit_status(const std::vector<MmsBatchItem> &items) {
  if (std::any_of(items.begin(), items.end(), [](const MmsBatchItem &i) { return i.interrupted; })) {
    return common::interrupted_exit_status();
  }
  if (std::all_of(items.begin(), items.end(), [](const MmsBatchItem &i) { return i.ok; })) return 0;
  if (std::all_of(items.begin(), items.end(), [](const MmsBatchItem &i) { return i.bad_input; })) return 2;
  return 1;
}

}  // namespace app
