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
#include "app/batch/batch_row.hpp"
#include "app/run/metric/run.hpp"
#include "app/run/run_report.hpp"

namespace app {

// What a batch runs its worlds as (--kind).
//   auto  each as what it is: a maze (a text map, a num file, a wall-segment XML on a lattice)
//         as a maze run, an arena (a .room file, the course's XML of obstacles) as a room run
//   maze  mazes only: a folder's arenas are skipped, "not mazes"
//   room  every world as a room run (a maze as the arena of its walls)
enum class KindChoice { automatic, maze, room };
// "auto", "maze" or "room"; common::InputError naming --kind otherwise.
KindChoice parse_kind_choice(const std::string &text);

// What the paths on a command line name.
struct WorldList {
  // Worlds to run: each file named as it is (a missing or unreadable one too: its run fails
  // with the reason, and the others still run); for a directory, every regular file in it
  // (not recursive) whose content is a world the choice runs (maze::detect_format: it may
  // still fail to load, and is then a failed row), in natural order ("s4" before "s10").
  std::vector<std::string> worlds;
  // Files in the directories that are none (a README, an image; an arena for --kind maze),
  // in the same order, then their entries that are no regular file, each with what it is
  // ("sub (a folder: folders are not searched)", "x.txt (a dangling link)", a FIFO, a
  // device): not run, but named in the totals.
  std::vector<std::string> skipped;
  std::string_view skipped_as = "not mazes";  // what the totals call them: "not mazes", "not worlds"
};
// The library's default is mazes only (the command line's is KindChoice::automatic).
WorldList expand_worlds(const std::vector<std::string> &paths, KindChoice choice = KindChoice::maze);

// Natural order: runs of digits compare as numbers, everything else byte by byte.
bool natural_less(const std::string &a, const std::string &b);

struct BatchItem {
  std::string world;
  RunKind kind = RunKind::maze;
  bool ran = false;           // the run started and ended (report is its result)
  bool ok = false;            // ran, and ended as planned (exit status 0)
  bool bad_input = false;     // failed on its input (common::InputError)
  bool interrupted = false;   // stopped by Ctrl-C, or never started because of it
  std::string error;          // the error line, when it did not run or did not end as planned
  RunSummary summary;         // a maze run's result, when it ran
  std::optional<Report> report;  // when it ran, whatever its kind: the row's columns come from it
};

// One run of a batch: a world, what it runs as, and the start position to start from
// (--each-start: pos:N, 1-based), else the one the options say.
struct BatchJob {
  std::string world;
  std::optional<int> start_position;
  RunKind kind = RunKind::maze;
};
// The row's name of a job: "WORLD", or "WORLD pos:N".
std::string job_name(const BatchJob &job);
// What `choice` runs the world at `path` as: a room run for --kind room, or for auto when
// its content is an arena; else a maze run (a file that is no world, too: its run says why).
RunKind run_kind_of(const std::string &path, KindChoice choice);
// --each-start: a job per start position of each maze (maze::Maze::start_positions); an
// arena, or a world that does not load, is one job (its run fails with the reason).
std::vector<BatchJob> each_start_jobs(const std::vector<std::string> &worlds, const maze::WorldOverrides &overrides,
                                      KindChoice choice = KindChoice::maze);
std::vector<BatchJob> plain_jobs(const std::vector<std::string> &worlds, KindChoice choice = KindChoice::maze);

// What a batch gives each run: a maze run's options, and a room run's (room_options_for).
struct BatchOptions {
  // Not explicit: a maze run's options are a batch's, its room runs those of no option given.
  BatchOptions(RunOptions run_options);
  BatchOptions(RunOptions run_options, RunOptions room_options);
  RunOptions run;
  RunOptions room;
};

// The room run a batch makes, quiet: the batch's options (its --seed and simulated faults,
// --max-steps, --time-limit, --threshold, the sensor model's numbers: log base 10 for bump
// and depth unless --log-base is given, as the room command) with `room_only`'s strategy and
// options in metres as the batch read them (--strategy, --waypoints, --laps, --cells,
// --resolution and the depth rays), and the robot and model when given(NAME) says the user
// typed them (a room has no cell model: ray unless another is given; the robot: the set-up's
// unless given).
RunOptions room_options_for(const RunOptions &options, const RunOptions &room_only,
                            const std::function<bool(std::string_view)> &given);

// The pool both batches run on: run(i) for every i in [0, count), on `jobs` threads (>= 1),
// each index once, in any order. Once interrupted (may be null) returns true, skip(i) is
// called instead for the indices not started yet. progress(done, count) (may be empty) is
// called from one thread at a time after each run.
void for_each_in_pool(std::size_t count, int jobs, const std::function<void(std::size_t)> &run,
                      const std::function<void(std::size_t)> &skip,
                      const std::function<void(std::size_t, std::size_t)> &progress, bool (*interrupted)());

// Runs each job as its kind (the options' world and start replaced) with `jobs` threads (>= 1).
// progress(done, total) is called from one thread at a time after each run. When interrupted
// (may be null) returns true, the runs in flight stop at their next step and no other starts;
// those worlds come back with `interrupted` set.
std::vector<BatchItem> run_batch(const BatchOptions &options, const std::vector<BatchJob> &batch_jobs,
                                 int jobs, const std::function<void(std::size_t, std::size_t)> &progress,
                                 bool (*interrupted)() = nullptr);
// Maze runs of the worlds (plain_jobs).
std::vector<BatchItem> run_batch(const BatchOptions &options, const std::vector<std::string> &worlds,
                                 int jobs, const std::function<void(std::size_t, std::size_t)> &progress,
                                 bool (*interrupted)() = nullptr);

BatchRow row_of(const BatchItem &item);

// The table: world, size, moves, coverage, wall_accuracy, cell_accuracy (when a room ran),
// goal, speed_run (cells), ms, end (the ending and its reason), "-" where a column does not
// apply; a world that did not run has its error instead; then the totals (format_totals), the
// elapsed time, and the skipped files ("N skipped, <skipped_as>: a, b, c and N more").
std::string format_batch_table(const std::vector<BatchItem> &items, double elapsed_ms,
                               const std::vector<std::string> &skipped = {}, std::string_view skipped_as = "not mazes");

// The same as CSV (batch_row.hpp), batch_csv_header() then a line a row; interrupted worlds
// are left out (the file holds the finished runs).
std::string format_batch_csv(const std::vector<BatchItem> &items);

// --shard K/N: the K-th (1-based) of N contiguous, near-equal parts of the world list, the
// same on every machine for the same list; parts 1 ... N together are the list, in order.
// Throws common::InputError unless the text is K/N with 1 <= K <= N.
struct Shard {
  int index = 1;  // K
  int count = 1;  // N
};
Shard parse_shard(const std::string &text);
std::vector<std::string> shard_of(const std::vector<std::string> &worlds, Shard shard);

// `batch merge`: the rows of batch CSVs, in the order of the files and of their lines, of
// any kind and mixed. A part's header is batch_csv_header(), or the one of an older maze
// batch ("world,size,moves,...,ms,end,error": maze rows) or mms batch ("world,size,end,lines,
// ...": mms rows, its columns the row has no place for dropped). A UTF-8 byte order mark and
// CRLF line ends are read (a spreadsheet's export). Throws common::InputError for a file that
// cannot be read ("FILE: error: ..."), a header that is none of those ("FILE:1: error: not a
// batch CSV (the first line must be '<batch_csv_header()>')"), a line that does not parse
// ("FILE:LINE: error: ..."), a value out of its column's range (parse_batch_row:
// "FILE:LINE:COL: error: ..."), and a part given twice: the same file again (its real path),
// or one holding the same rows as an earlier one.
std::vector<BatchRow> read_batch_csvs(const std::vector<std::string> &files);
// One part's rows from its text, as read_batch_csvs reads a file's (its errors but those of
// reading a file or of a part given twice). A quote never closed is refused where it opened
// ("FILE:LINE:COL: error: not a batch CSV row: the quoted field that opens here is never
// closed"), in time proportional to the text.
std::vector<BatchRow> read_batch_csv_text(const std::string &file, std::string_view text);

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
