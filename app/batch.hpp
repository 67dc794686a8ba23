#pragma once
// `maze_mapper batch WORLD... [--jobs N] [--csv FILE] [run options]`: many independent runs
// on a pool of threads, reported in input order whatever the number of jobs.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "app/run.hpp"

namespace app {

// The worlds named: a file as it is; a directory, every regular file in it (sorted by name,
// not recursive) that loads as a world. Throws common::InputError for a path that does not
// exist; the error of a named file that does not load comes from its run.
std::vector<std::string> expand_worlds(const std::vector<std::string> &paths);

struct BatchItem {
  std::string world;
  bool ok = false;            // ran, and ended as planned (exit_status 0)
  bool bad_input = false;     // failed on its input (common::InputError)
  std::string error;          // the error line, when it did not run
  RunSummary summary;         // when it ran
};

// Runs options (world replaced) on each world with `jobs` threads (>= 1). progress(done,
// total) is called from one thread at a time after each run.
std::vector<BatchItem> run_batch(const RunOptions &options, const std::vector<std::string> &worlds,
                                 int jobs, const std::function<void(std::size_t, std::size_t)> &progress);

// The table: world, size, moves, coverage, wall_accuracy, ms; a failed world's row says its
// error; then the totals.
std::string format_batch_table(const std::vector<BatchItem> &items, double elapsed_ms);
// The same as CSV: world,size,moves,coverage,wall_accuracy,ms,end,error.
std::string format_batch_csv(const std::vector<BatchItem> &items);

// 0 when every run succeeded, 2 when every world was bad input, else 1.
int batch_exit_status(const std::vector<BatchItem> &items);

}  // namespace app
