#pragma once
// `maze_mapper batch WORLD... [--jobs N] [--csv FILE] [run options]`: many independent runs
// on a pool of threads, reported in input order whatever the number of jobs.

#include <cstddef>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "app/run/run.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "app/run/run_report.hpp"

namespace app {

// What the paths on a command line name.
struct WorldList {
  // Worlds to run: each file named as it is (a missing or unreadable one too: its run fails
  // with the reason, and the others still run); for a directory, every regular file in it
  // (not recursive) whose content is one of the maze formats (maze::detect_format: it may
  // still fail to load, and is then a failed row), in natural order ("s4" before "s10").
  std::vector<std::string> worlds;
  // Files in the directories that are no maze at all (a README, an image), in the same
  // order, then their entries that are no regular file, each with what it is ("sub (a folder:
  // folders are not searched)", "x.txt (a dangling link)", a FIFO, a device): not run, but
  // named in the totals.
  std::vector<std::string> skipped;
};
WorldList expand_worlds(const std::vector<std::string> &paths);

// Natural order: runs of digits compare as numbers, everything else byte by byte.
bool natural_less(const std::string &a, const std::string &b);

struct BatchItem {
  std::string world;
  bool ran = false;           // the run started and ended (summary is its result)
  bool ok = false;            // ran, and ended as planned (exit_status 0)
  bool bad_input = false;     // failed on its input (common::InputError)
  bool interrupted = false;   // stopped by Ctrl-C, or never started because of it
  std::string error;          // the error line, when it did not run or did not end as planned
  RunSummary summary;         // when it ran
  std::optional<Report> report;  // when it ran: the goal and speed_run columns come from it
};

// One run of a batch: a world, and the start position to start from (--each-start: pos:N,
// 1-based), else the one the options say.
struct BatchJob {
  std::string world;
  std::optional<int> start_position;
};
// The row's name of a job: "WORLD", or "WORLD pos:N".
std::string job_name(const BatchJob &job);
// --each-start: a job per start position of each world (maze::Maze::start_positions); a
// world that does not load is one job (its run fails with the reason).
std::vector<BatchJob> each_start_jobs(const std::vector<std::string> &worlds, const maze::WorldOverrides &overrides);
std::vector<BatchJob> plain_jobs(const std::vector<std::string> &worlds);

// The pool both batches run on: run(i) for every i in [0, count), on `jobs` threads (>= 1),
// each index once, in any order. Once interrupted (may be null) returns true, skip(i) is
// called instead for the indices not started yet. progress(done, count) (may be empty) is
// called from one thread at a time after each run.
void for_each_in_pool(std::size_t count, int jobs, const std::function<void(std::size_t)> &run,
                      const std::function<void(std::size_t)> &skip,
                      const std::function<void(std::size_t, std::size_t)> &progress, bool (*interrupted)());

// Runs options (world and start replaced) on each job with `jobs` threads (>= 1). progress(done,
// total) is called from one thread at a time after each run. When interrupted (may be null)
// returns true, the runs in flight stop at their next step and no other starts; those
// worlds come back with `interrupted` set.
std::vector<BatchItem> run_batch(const RunOptions &options, const std::vector<BatchJob> &batch_jobs,
                                 int jobs, const std::function<void(std::size_t, std::size_t)> &progress,
                                 bool (*interrupted)() = nullptr);
std::vector<BatchItem> run_batch(const RunOptions &options, const std::vector<std::string> &worlds,
                                 int jobs, const std::function<void(std::size_t, std::size_t)> &progress,
                                 bool (*interrupted)() = nullptr);

// One row of the table and the CSV, as a run made it or a CSV line reads back.
struct BatchRow {
  std::string world;
  bool ran = false;
  bool ok = false;
  bool interrupted = false;
  std::string size;                 // "16x16"
  long moves = 0;                   // the search's cell-to-cell moves (not the speed run's)
  double coverage_percent = 0.0;
  double wall_accuracy_percent = 0.0;
  std::string goal;                 // the report's "goal": "reached", "not reached", or empty (not asked)
  std::string speed_run;            // the speed run's cells, or empty: none made
  double ms = 0.0;                  // wall-clock time of the run
  std::string end;                  // robot::to_string(EndReason)
  std::string error;
};
BatchRow row_of(const BatchItem &item);

// What the totals line counts.
struct BatchTotals {
  int worlds = 0;
  int ok = 0;
  int interrupted = 0;
  int ran = 0;
  long moves = 0;
  double coverage_sum = 0.0;
  double accuracy_sum = 0.0;
  double run_ms = 0.0;
  int with_goal = 0;
  int goal_reached = 0;
};
void add_to_totals(BatchTotals &totals, const BatchRow &row);
// "total: 3 worlds, 2 ok, 1 failed; moves 144; mean coverage 100.00%; mean wall_accuracy
// 100.00%[; goal reached 2 of 2]; run time 812 ms"
std::string format_totals(const BatchTotals &totals);

// The table: world, size, moves, coverage, wall_accuracy, goal, speed_run (cells), ms, end
// (the ending and its reason), "-" where a column does not apply; a world that did not run
// has its error instead; then the totals, the elapsed time, and the skipped files.
std::string format_batch_table(const std::vector<BatchItem> &items, double elapsed_ms,
                               const std::vector<std::string> &skipped = {});

inline constexpr std::string_view kBatchCsvHeader =
    "world,size,moves,coverage,wall_accuracy,goal,speed_run,ms,end,error";
// The same as CSV (common/csv.hpp), kBatchCsvHeader then a line a row, empty where a column
// does not apply; interrupted worlds are left out (the file holds the finished runs).
std::string format_batch_csv(const std::vector<BatchItem> &items);
std::string format_batch_csv_row(const BatchRow &row);

// --shard K/N: the K-th (1-based) of N contiguous, near-equal parts of the world list, the
// same on every machine for the same list; parts 1 ... N together are the list, in order.
// Throws common::InputError unless the text is K/N with 1 <= K <= N.
struct Shard {
  int index = 1;  // K
  int count = 1;  // N
};
Shard parse_shard(const std::string &text);
std::vector<std::string> shard_of(const std::vector<std::string> &worlds, Shard shard);

// `batch merge`: the rows of batch CSVs, in the order of the files and of their lines. A
// UTF-8 byte order mark and CRLF line ends are read (a spreadsheet's export). Throws
// common::InputError for a file that cannot be read ("FILE: error: ..."), a header that is
// not kBatchCsvHeader, a line that does not parse ("FILE:LINE: error: ..."), a number out
// of its column's range (moves a whole number from 0, coverage and wall_accuracy 0 to 100,
// ms from 0: "FILE:LINE:COL: error: ..."), and a part given twice: the same file again
// (its real path), or one holding the same rows as an earlier one.
std::vector<BatchRow> read_batch_csvs(const std::vector<std::string> &files);

// 130 when interrupted, 0 when every run succeeded, 2 when every world was bad input, else 1.
int batch_exit_status(const std::vector<BatchItem> &items);

// Runs one world's run() for a batch row: a bad input (common::InputError) marks the row
// bad_input with its diagnostic, a wait a stop signal ended (common::Interrupted: a FIFO
// world without a writer) marks it interrupted, any other failure is the row's error; the
// batch goes on.
template <typename Row, typename Run>
void run_row(Row &row, Run &&run) {
  try {
    run();
  } catch (const common::Interrupted &e) {
    row.interrupted = true;
    row.error = e.what();
  } catch (const common::InputError &e) {
    row.bad_input = true;
    row.error = e.diagnostic();
  } catch (const std::exception &e) {
    row.error = fmt::format("error: {}", e.what());
  }
}

}  // namespace app
