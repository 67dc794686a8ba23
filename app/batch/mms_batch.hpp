#pragma once
// `maze_mapper batch WORLD... [--jobs N] [--csv FILE] [mms options] -- COMMAND [ARGS...]`:
// the mms algorithm once on each maze (app/mms/mms_session.hpp), on a pool of threads, a row
// each in input order with mms's stats. A run the algorithm spoils (it hangs, crashes,
// exits early, floods or writes garbage) is a failed row with its reason; its process is
// killed and the other runs go on. Ctrl-C or SIGTERM stops the runs in flight (their
// children killed) and starts no other.

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "app/batch/batch_row.hpp"
#include "app/mms/mms_session.hpp"

namespace app {

struct MmsBatchItem {
  std::string world;
  bool ran = false;          // the run started and ended (run holds its result)
  bool ok = false;           // exit_status(run) == 0: ended as asked, the goal reached
  bool bad_input = false;    // the world (or robot) could not be used
  bool interrupted = false;  // stopped by Ctrl-C / SIGTERM, or never started because of it
  std::string error;         // why it failed
  MmsRun run;
  BatchRow row;              // its row of the CSV (batch_row.hpp): the robot's run, with mms's end and score
};

std::vector<MmsBatchItem> run_mms_batch(const RunOptions &options, const MmsOptions &mms,
                                        const std::vector<std::string> &worlds, int jobs,
                                        const std::function<void(std::size_t, std::size_t)> &progress,
                                        bool (*interrupted)());

// The table: world, size, end, lines, moves, goal, distance, turns, effective (totals),
// best_run (distance/turns/effective), score, ms, then the reason of a failed row; then
// "total: N worlds, N ok, N failed; goal reached N of N; mean score X" and the elapsed time.
std::string format_mms_batch_table(const std::vector<MmsBatchItem> &items, double elapsed_ms,
                                   const std::vector<std::string> &skipped);

// The rows as CSV in the one batch row's columns (batch_row.hpp: kind mms, strategy the
// algorithm's command line, end mms's ending, score mms's score), interrupted worlds left out.
std::string format_mms_batch_csv(const std::vector<MmsBatchItem> &items);

// 128 + the signal when interrupted (130 Ctrl-C, 143 SIGTERM, 129 SIGHUP), 0 when every run
// was ok, 2 when every world was bad input, else 1.
int mms_batch_exit_status(const std::vector<MmsBatchItem> &items);

}  // namespace app
