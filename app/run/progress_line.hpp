#pragma once
// The one-line progress a long run and a batch draw on a terminal (standard error), redrawn
// in place and cleared when done. Only where nothing else draws on that terminal: never in
// pipes, files or goldens (the callers decide: progress_fd, is_terminal).
//
//   run:    moves 41  visited 30/36 reachable cells (83%)  sim 96.4 s  elapsed 1.2 s
//   room:   steps 1200  observed 830/8906 reachable free cells (9%)  sim 38.4 s  elapsed 1.2 s
//   batch:  [#########                     ]  30%  6/20 worlds  0:42 left
//
// A run's end is the reachable cells (in metres: the reachable free cells observed) (a search that proves its path sooner stops short of
// 100%); its time left is not known, so it shows none. A batch's end is its worlds: the time
// left is the worlds to go at the rate so far (elapsed time / worlds done).

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace app {

// Whole seconds as "0:07", "12:40" (m:ss) or "1:02:05" (h:mm:ss); a negative or non-finite
// time is "0:00".
std::string format_clock(double seconds);

// The percentage of `done` out of `total`, rounded down, so that 100 means all of it (0 of 0
// is 100).
int percent_done(std::size_t done, std::size_t total);

// "moves M  visited V/R reachable cells (P%)  sim S s  elapsed E s".
std::string format_run_progress(int moves, int visited, int reachable_cells, double sim_time_s, double elapsed_s);

// "steps N  observed O/R reachable free cells (P%)  sim S s  elapsed E s": a run in metres.
std::string format_metres_progress(std::int64_t steps, std::size_t observed, std::size_t reachable_free,
                                   double sim_time_s, double elapsed_s);

// "[####      ]  P%  D/T worlds  m:ss left": a 30-column bar; the time left from the rate so
// far, left out while no world is done (no rate yet) and once all are.
std::string format_batch_progress(std::size_t done, std::size_t total, double elapsed_s);

// A long run's progress line on fd, at most ten times a second.
class ProgressLine {
 public:
  ProgressLine(int fd, int reachable_cells);
  ~ProgressLine();
  ProgressLine(const ProgressLine &) = delete;
  ProgressLine &operator=(const ProgressLine &) = delete;

  void update(int moves, int visited, double sim_time_s);
  // A run in metres (reachable_cells: its reachable free cells): `observed` is counted only
  // when the line is drawn.
  void update_metres(std::int64_t steps, const std::function<std::size_t()> &observed, double sim_time_s);

 private:
  int fd_;
  int reachable_cells_;
  std::chrono::steady_clock::time_point started_;
  std::chrono::steady_clock::time_point next_draw_;
  bool drawn_ = false;

  bool due();  // at most ten times a second
  void draw(const std::string &text);
};

// A batch's progress line on fd, the time counted from its construction; update() is called
// once a world is done (batch's progress callback, already serialised by the pool).
class BatchProgressLine {
 public:
  explicit BatchProgressLine(int fd);
  ~BatchProgressLine();
  BatchProgressLine(const BatchProgressLine &) = delete;
  BatchProgressLine &operator=(const BatchProgressLine &) = delete;

  void update(std::size_t done, std::size_t total);

 private:
  int fd_;
  std::chrono::steady_clock::time_point started_;
  bool drawn_ = false;
};

}  // namespace app
