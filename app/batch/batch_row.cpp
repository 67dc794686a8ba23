// A batch row, its columns and its totals (app/batch/batch_row.hpp).

#include "app/batch/batch_row.hpp"
#include "app/run/report_keys.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "app/run/step_limit.hpp"
#include "app/mms/mms_session.hpp"
#include "common/error.hpp"
#include "common/parse_number.hpp"
#include "robot/cell/controller.hpp"
#include "robot/metric/controller.hpp"

namespace app {
namespace {

using Json = nlohmann::ordered_json;

// A cell being read: its text, where it is, and the name its header gave its column.
struct CellIn {
  const common::CsvField &field;
  const RowPlace &at;
  std::string_view name;
};

common::InputError cell_error(const CellIn &in, std::string_view what) {
  return common::InputError(common::SourceLocation{in.at.file, in.at.line, in.field.column},
                            fmt::format("{} {} (got '{}')", in.name, what, in.field.text));
}

// An empty cell: no value; else a number within [least, most].
template <typename Number>
std::optional<Number> number_in(const CellIn &in, Number least, Number most, std::string_view what) {
  if (in.field.text.empty()) return std::nullopt;
  const std::optional<Number> v = common::parse_number<Number>(in.field.text);
  if (!v || !(*v >= least && *v <= most)) throw cell_error(in, what);
  return v;
}

std::optional<double> percent_in(const CellIn &in) {
  return number_in(in, 0.0, 100.0, "must be a percentage from 0 to 100");
}
std::optional<std::int64_t> count_in(const CellIn &in) {
  return number_in<std::int64_t>(in, 0, std::numeric_limits<std::int64_t>::max(), "must be a whole number from 0");
}

template <typename Whole>
std::string whole_text(const std::optional<Whole> &value) {
  return value ? std::to_string(*value) : std::string();
}
std::string fixed_text(const std::optional<double> &value, int decimals) {
  return value ? fmt::format("{:.{}f}", *value, decimals) : std::string();
}
std::string percent_text(const std::optional<double> &value) { return fixed_text(value, 2); }

RunKind kind_in(const CellIn &in) {
  for (const RunKind kind : kRunKinds) {
    if (in.field.text == to_string(kind)) return kind;
  }
  throw cell_error(in, "must be maze, room or mms");
}

// A column: its name (summary.json's key), how a row writes it, reads it back, and takes it
// from a run report's value of that key (null where the report has none; nullptr: not a key
// of the report).
struct Column {
  std::string_view name;
  std::string (*write)(const BatchRow &);
  void (*read)(BatchRow &, const CellIn &);
  void (*take)(BatchRow &, const Json &) = nullptr;
};

std::string json_text(const Json &j) { return j.is_string() ? j.get<std::string>() : std::string(); }
template <typename Number>
std::optional<Number> json_number(const Json &j) {
  return j.is_number() ? std::optional<Number>(j.get<Number>()) : std::nullopt;
}

// A column of text as it stands, the report's JSON string.
template <std::string BatchRow::*Field>
Column text_column(std::string_view name) {
  return {name, [](const BatchRow &r) { return r.*Field; }, [](BatchRow &r, const CellIn &in) { r.*Field = in.field.text; },
          [](BatchRow &r, const Json &j) { r.*Field = json_text(j); }};
}

// A column of a percentage, "" for none.
template <std::optional<double> BatchRow::*Field>
Column percent_column(std::string_view name) {
  return {name, [](const BatchRow &r) { return percent_text(r.*Field); },
          [](BatchRow &r, const CellIn &in) { r.*Field = percent_in(in); },
          [](BatchRow &r, const Json &j) { r.*Field = json_number<double>(j); }};
}

constexpr double kMostMs = 1e12;   // 30 years of one run
constexpr double kMostSimS = 1e12;

const std::array kColumns{
    text_column<&BatchRow::world>("world"),
    Column{"kind", [](const BatchRow &r) { return std::string(to_string(r.kind)); },
           [](BatchRow &r, const CellIn &in) { r.kind = kind_in(in); }},
    text_column<&BatchRow::robot>("robot"),
    text_column<&BatchRow::model>("model"),
    text_column<&BatchRow::strategy>("strategy"),
    Column{"seed", [](const BatchRow &r) { return whole_text(r.seed); },
           [](BatchRow &r, const CellIn &in) {
             r.seed = number_in<std::uint64_t>(in, 0, std::numeric_limits<std::uint64_t>::max(),
                                               "must be a whole number from 0");
           },
           [](BatchRow &r, const Json &j) { r.seed = json_number<std::uint64_t>(j); }},
    text_column<&BatchRow::size>("size"),
    text_column<&BatchRow::end>("end"),
    text_column<&BatchRow::end_message>("end_message"),
    Column{"steps", [](const BatchRow &r) { return whole_text(r.steps); },
           [](BatchRow &r, const CellIn &in) { r.steps = count_in(in); },
           [](BatchRow &r, const Json &j) { r.steps = json_number<std::int64_t>(j); }},
    Column{"moves", [](const BatchRow &r) { return whole_text(r.moves); },
           [](BatchRow &r, const CellIn &in) { r.moves = count_in(in); },
           [](BatchRow &r, const Json &j) { r.moves = json_number<std::int64_t>(j); }},
    Column{"sim_time_s", [](const BatchRow &r) { return fixed_text(r.sim_time_s, 3); },
           [](BatchRow &r, const CellIn &in) {
             r.sim_time_s = number_in(in, 0.0, kMostSimS, "must be a number of seconds from 0");
           },
           [](BatchRow &r, const Json &j) { r.sim_time_s = json_number<double>(j); }},
    Column{"wall_time_ms", [](const BatchRow &r) { return fixed_text(r.wall_time_ms, 0); },
           [](BatchRow &r, const CellIn &in) {
             r.wall_time_ms = number_in(in, 0.0, kMostMs, "must be a number of milliseconds from 0");
           },
           [](BatchRow &r, const Json &j) { r.wall_time_ms = json_number<double>(j); }},
    percent_column<&BatchRow::coverage_percent>(report_key::coverage),
    percent_column<&BatchRow::wall_accuracy_percent>(report_key::wall_accuracy),
    percent_column<&BatchRow::cell_accuracy_percent>(report_key::cell_accuracy),
    text_column<&BatchRow::goal>("goal"),
    Column{"speed_run", [](const BatchRow &r) { return r.speed_run; },
           [](BatchRow &r, const CellIn &in) { r.speed_run = in.field.text; },
           [](BatchRow &r, const Json &j) { r.speed_run = j.is_object() ? j["cells"].dump() : std::string(); }},
    Column{"score", [](const BatchRow &r) { return r.score ? mms_number(*r.score) : std::string(); },
           [](BatchRow &r, const CellIn &in) {
             r.score = number_in(in, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                                 "must be a number");
           }},
    Column{"error", [](const BatchRow &r) { return r.error; }, [](BatchRow &r, const CellIn &in) { r.error = in.field.text; }},
};

// An older header's name for a column: the maze batch's and the mms batch's "ms".
std::string_view column_name(std::string_view name) { return name == "ms" ? "wall_time_ms" : name; }

const Column *column_named(std::string_view name) {
  const std::string_view wanted = column_name(name);
  const auto it = std::find_if(kColumns.begin(), kColumns.end(), [&](const Column &c) { return c.name == wanted; });
  return it == kColumns.end() ? nullptr : &*it;
}

// The report's JSON value of `key`, or null when it has none.
const Json &json_of(const Report &report, std::string_view key) {
  static const Json kNull;
  const ReportEntry *entry = report.find(key);
  return entry != nullptr ? entry->json : kNull;
}

bool one_of(std::string_view end, std::initializer_list<std::string_view> ends) {
  return std::find(ends.begin(), ends.end(), end) != ends.end();
}

std::string percent(double v) { return fmt::format("{:.2f}%", v); }

std::string mean_text(const KindTotals::Mean &mean, std::string_view name) {
  return fmt::format("mean {} {}", name, percent(mean.count > 0 ? mean.sum / mean.count : 0.0));
}

void add_mean(KindTotals::Mean &mean, const std::optional<double> &value) {
  if (!value) return;
  mean.sum += *value;
  ++mean.count;
}

// "3 worlds, 2 ok, 1 failed[, 1 interrupted]"
std::string counts_text(int worlds, int ok, int interrupted) {
  std::string out = fmt::format("{} worlds, {} ok, {} failed", worlds, ok, worlds - ok - interrupted);
  if (interrupted > 0) out += fmt::format(", {} interrupted", interrupted);
  return out;
}

// The kind's scores: "moves 144; mean coverage ...; ..." as its header says.
std::string scores_text(RunKind kind, const KindTotals &t) {
  std::string out;
  if (kind != RunKind::room) out += fmt::format("; moves {}", t.moves);
  out += "; " + mean_text(t.coverage, report_key::coverage);
  out += "; " + (kind == RunKind::room ? mean_text(t.cell_accuracy, report_key::cell_accuracy)
                                       : mean_text(t.wall_accuracy, report_key::wall_accuracy));
  if (t.with_goal > 0 || kind == RunKind::mms) out += fmt::format("; goal reached {} of {}", t.goal_reached, t.with_goal);
  if (kind == RunKind::mms) {
    out += fmt::format("; mean score {}", t.score.count > 0 ? mms_number(t.score.sum / t.score.count) : "-");
  }
  return out;
}

}  // namespace

std::string_view to_string(RunKind kind) {
  switch (kind) {
    case RunKind::maze: return "maze";
    case RunKind::room: return "room";
    case RunKind::mms: return "mms";
  }
  return "maze";
}

BatchRow row_from_report(const Report &report) {
  BatchRow row;
  row.ran = true;
  for (const Column &c : kColumns) {
    if (c.take != nullptr) c.take(row, json_of(report, c.name));
  }
  return row;
}

bool batch_row_ok(const BatchRow &row) {
  if (!row.ran || !row.error.empty()) return false;
  switch (row.kind) {
    case RunKind::maze:
      // As exit_status: a run that ended other than done (or at a step or time limit, which
      // the CSV does not say was the user's) did not map its maze.
      return one_of(row.end, {robot::to_string(robot::EndReason::done), robot::to_string(robot::EndReason::max_steps),
                              kTimeLimitEnd});
    case RunKind::room:
      return one_of(row.end, {robot::to_string(robot::MetricEnding::done), robot::to_string(robot::MetricEnding::goal_reached),
                              robot::to_string(robot::MetricEnding::arrived), robot::to_string(robot::MetricEnding::time_up)});
    case RunKind::mms:
      return one_of(row.end, {to_string(MmsEnd::exited), to_string(MmsEnd::reached)}) && row.goal == "reached";
  }
  return false;
}

const std::string &batch_csv_header() {
  static const std::string header = [] {
    std::string h;
    for (const Column &c : kColumns) h += (h.empty() ? "" : ",") + std::string(c.name);
    return h;
  }();
  return header;
}

std::string format_batch_csv_row(const BatchRow &row) {
  std::string line;
  for (const Column &c : kColumns) {
    if (!line.empty()) line += ',';
    line += common::csv_field(c.write(row));
  }
  return line + '\n';
}

bool is_batch_column(std::string_view name) { return column_named(name) != nullptr; }

BatchRow parse_batch_row(const std::vector<std::string> &names, const std::vector<common::CsvField> &fields,
                         RunKind kind, const RowPlace &at) {
  BatchRow row;
  row.kind = kind;
  for (std::size_t i = 0; i < names.size() && i < fields.size(); ++i) {
    if (const Column *column = column_named(names[i])) column->read(row, CellIn{fields[i], at, names[i]});
  }
  row.ran = !row.end.empty();
  row.ok = batch_row_ok(row);
  return row;
}

void add_to_totals(BatchTotals &totals, const BatchRow &row) {
  KindTotals &t = totals.kinds[static_cast<std::size_t>(row.kind)];
  ++t.worlds;
  if (row.interrupted) ++t.interrupted;
  if (row.ok) ++t.ok;
  if (!row.ran) return;
  ++t.ran;
  t.moves += row.moves.value_or(0);
  add_mean(t.coverage, row.coverage_percent);
  add_mean(t.wall_accuracy, row.wall_accuracy_percent);
  add_mean(t.cell_accuracy, row.cell_accuracy_percent);
  add_mean(t.score, row.score);
  t.run_ms += row.wall_time_ms.value_or(0.0);
  if (!row.goal.empty()) ++t.with_goal;
  if (row.goal == "reached") ++t.goal_reached;
}

std::string format_totals(const BatchTotals &totals) {
  std::vector<RunKind> present;
  for (const RunKind kind : kRunKinds) {
    if (totals.of(kind).worlds > 0) present.push_back(kind);
  }
  if (present.empty()) present.push_back(RunKind::maze);
  std::string out;
  KindTotals all;
  for (const RunKind kind : present) {
    const KindTotals &t = totals.of(kind);
    const std::string name = present.size() == 1 ? "total" : fmt::format("total {}", to_string(kind));
    out += fmt::format("{}: {}{}; run time {:.0f} ms", name, counts_text(t.worlds, t.ok, t.interrupted),
                       scores_text(kind, t), t.run_ms);
    if (present.size() > 1) out += '\n';
    all.worlds += t.worlds;
    all.ok += t.ok;
    all.interrupted += t.interrupted;
    all.run_ms += t.run_ms;
  }
  if (present.size() > 1) {
    out += fmt::format("total: {}; run time {:.0f} ms", counts_text(all.worlds, all.ok, all.interrupted), all.run_ms);
  }
  return out;
}

}  // namespace app
