#pragma once
// One row of a batch, whatever the kind of run (a maze run, a room run, an mms program's run):
// the row of the table, of `batch --csv` and of `batch merge`. Its columns are declared once,
// in batch_row.cpp's table, each named by the summary.json key it carries (app/run/report.hpp):
//
//   world,kind,robot,model,strategy,seed,size,end,end_message,steps,moves,sim_time_s,
//   wall_time_ms,coverage,wall_accuracy,cell_accuracy,goal,speed_run,score,error
//
//   column          maze run                room run                 mms run
//   kind            maze                    room                     mms
//   strategy        dfs, frontier, ...      frontier, ...            the algorithm's command line
//   size            16x16                   (empty)                  16x16
//   end             done, incomplete, ...   done, time up, ...       exited, reached, wall limit, ...
//   moves           cell-to-cell moves      (empty)                  cell-to-cell moves
//   coverage        % of reachable cells    % of reachable free      % of reachable cells
//                   visited                 cells observed           visited
//   wall_accuracy   % of sides right        (empty)                  % of sides right
//   cell_accuracy   (empty)                 % of cells right         (empty)
//   goal            reached / not reached   (empty)                  reached / not reached
//                   (when asked)
//   speed_run       cells (when made)       (empty)                  (empty)
//   score           (empty)                 (empty)                  mms's score
//
// A column a kind has no value for is empty, as is every column but world, kind and error of a
// run that did not start (error says why). Numbers: percentages with two decimals,
// sim_time_s three, wall_time_ms none.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/run/report.hpp"
#include "common/csv.hpp"

namespace app {

enum class RunKind { maze, room, mms };
inline constexpr std::array<RunKind, 3> kRunKinds{RunKind::maze, RunKind::room, RunKind::mms};
std::string_view to_string(RunKind kind);  // "maze", "room", "mms"

struct BatchRow {
  std::string world;  // the job's name: "WORLD", or "WORLD pos:N" (--each-start)
  RunKind kind = RunKind::maze;
  bool ran = false;          // the run started and ended: it has an end
  bool ok = false;           // ran, and ended as its kind counts a success (batch_row_ok)
  bool interrupted = false;  // stopped by a signal, or never started because of one
  std::string robot;
  std::string model;
  std::string strategy;
  std::optional<std::uint64_t> seed;
  std::string size;  // "16x16"
  std::string end;
  std::string end_message;
  std::optional<std::int64_t> steps;
  std::optional<std::int64_t> moves;  // the search's cell-to-cell moves (not the speed run's)
  std::optional<double> sim_time_s;
  std::optional<double> wall_time_ms;
  std::optional<double> coverage_percent;
  std::optional<double> wall_accuracy_percent;
  std::optional<double> cell_accuracy_percent;
  std::string goal;       // "reached", "not reached", or empty (not asked)
  std::string speed_run;  // the speed run's cells, or empty: none made
  std::optional<double> score;
  std::string error;      // why the row failed: it did not run, or did not end as planned
};

// The row of a run's report: every column but kind, score and error takes the report's
// summary.json value of its own key (world, robot, model, strategy, seed, size, end,
// end_message, steps, moves, sim_time_s, wall_time_ms, coverage, wall_accuracy, cell_accuracy,
// goal, speed_run's cells), empty where the report has none; `ran` set. The caller sets the
// row's name, kind, ok and error.
BatchRow row_from_report(const Report &report);

// Whether a row read back from a CSV ran as its kind counts a success: no error, and an end
// that is one (maze: done or max steps; room: done, goal reached, arrived or time up; mms:
// exited or reached, with the goal reached), whatever part it was merged from.
bool batch_row_ok(const BatchRow &row);

// The header line (without "\n"): the columns' names in order.
const std::string &batch_csv_header();
// One row as a CSV line (with "\n"): common/csv.hpp's fields, empty where the row has no value.
std::string format_batch_csv_row(const BatchRow &row);

// Where a row of a CSV is: the file, the line its record starts on.
struct RowPlace {
  const std::string &file;
  int line = 0;
};
// Reads one row of a CSV whose header named its columns `names` (each one of the table's, or
// an older header's "ms" for wall_time_ms; a name the table does not have is skipped) as a
// run of `kind` unless a kind column says otherwise. Throws common::InputError
// "FILE:LINE:COL: error: NAME must be ... (got 'TEXT')" for a value out of its column's range:
// percentages 0 to 100, moves and steps whole numbers from 0, times from 0, a kind that is
// none.
BatchRow parse_batch_row(const std::vector<std::string> &names, const std::vector<common::CsvField> &fields,
                         RunKind kind, const RowPlace &at);
// Whether `name` is a column a CSV header may name (the table's, or "ms").
bool is_batch_column(std::string_view name);

// What the totals count, per kind.
struct KindTotals {
  int worlds = 0;
  int ok = 0;
  int interrupted = 0;
  int ran = 0;
  std::int64_t moves = 0;
  double run_ms = 0.0;
  int with_goal = 0;
  int goal_reached = 0;
  struct Mean {
    double sum = 0.0;
    int count = 0;
  };
  Mean coverage, wall_accuracy, cell_accuracy, score;
};
struct BatchTotals {
  std::array<KindTotals, kRunKinds.size()> kinds;
  const KindTotals &of(RunKind kind) const { return kinds[static_cast<std::size_t>(kind)]; }
};
void add_to_totals(BatchTotals &totals, const BatchRow &row);
// The totals, a line a kind that has rows (no "\n" after the last):
//   maze  "total: 3 worlds, 2 ok, 1 failed; moves 144; mean coverage 100.00%; mean wall_accuracy
//          100.00%[; goal reached 2 of 2]; run time 812 ms"
//   room  "...; mean coverage 99.10%; mean cell_accuracy 95.20%; run time ..."
//   mms   "...; moves 144; mean coverage ...; mean wall_accuracy ...; goal reached 2 of 3; mean score 1.2e+03; run time ..."
// With one kind the line starts "total:"; with several each starts "total maze:", "total room:",
// ..., and a last line "total: N worlds, N ok, N failed; run time T ms" adds them up.
std::string format_totals(const BatchTotals &totals);

}  // namespace app
