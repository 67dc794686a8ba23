#pragma once
// `maze_mapper batch WORLD... [--jobs N] [--csv FILE] [run options]`: many independent runs
// on a pool of threads, reported in input order whatever the number of jobs.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "app/run.hpp"

namespace app {

// What the paths on a command line name.
struct WorldList {
  // Worlds to run: each file named as it is (a missing or unreadable one too: its run fails
  // with the reason, and the others still run); for a directory, every regular file in it
  // (not recursive) whose content is one of the maze formats (maze::detect_format: it may
  // still fail to load, and is then a failed row), in natural order ("s4" before "s10").
  std::vector<std::string> worlds;
  // Files in the directories that are no maze at all (a README, an image), in the same
  // order: not run, but named in the totals.
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
};

// Runs options (world replaced) on each world with `jobs` threads (>= 1). progress(done,
// total) is called from one thread at a time after each run. When interrupted (may be null)
// returns true, the runs in flight stop at their next step and no other starts; those
// worlds come back with `interrupted` set.
std::vector<BatchItem> run_batch(const RunOptions &options, const std::vector<std::string> &worlds,
                                 int jobs, const std::function<void(std::size_t, std::size_t)> &progress,
                                 bool (*interrupted)() = nullptr);

// The table: world, size, moves, coverage, wall_accuracy, ms, end (the ending and its
// reason); a world that did not run has its error instead; then the totals, which name the
// skipped files.
std::string format_batch_table(const std::vector<BatchItem> &items, double elapsed_ms,
                               const std::vector<std::string> &skipped = {});
// The same as CSV: world,size,moves,coverage,wall_accuracy,ms,end,error; interrupted worlds
// are left out (the file holds the finished runs).
std::string format_batch_csv(const std::vector<BatchItem> &items);

// 130 when interrupted, 0 when every run succeeded, 2 when every world was bad input, else 1.
int batch_exit_status(const std::vector<BatchItem> &items);

}  // namespace app
