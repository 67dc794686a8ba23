#include "app/run/progress_line.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "app/run/terminal.hpp"
#include "common/stdout_buffer.hpp"

namespace app {
namespace {

constexpr const char *kClearLine = "\r\x1b[K";

// Writes all of text to fd; a terminal that refuses is left alone (progress is a courtesy),
// and one that holds the write (Ctrl-S) still lets a stop signal end the wait.
void write_progress(int fd, const std::string &text) {
  (void)common::write_all_interruptible(fd, text.data(), text.size(), true);
}

// The line cut to one column less than the terminal's width, so that it never wraps (a
// wrapped line is not cleared by kClearLine and scrolls what was printed before it away).
std::string fitted_to_terminal(int fd, std::string line) {
  const int columns = terminal_size(fd).columns;
  if (columns > 1 && line.size() >= static_cast<std::size_t>(columns)) line.resize(static_cast<std::size_t>(columns - 1));
  return line;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::string format_clock(double seconds) {
  const auto whole = std::isfinite(seconds) && seconds > 0.0 ? static_cast<std::int64_t>(std::llround(seconds)) : 0;
  const std::int64_t h = whole / 3600;
  const std::int64_t m = whole / 60 % 60;
  const std::int64_t s = whole % 60;
  if (h > 0) return fmt::format("{}:{:02}:{:02}", h, m, s);
  return fmt::format("{}:{:02}", m, s);
}

int percent_done(std::size_t done, std::size_t total) {
  if (total == 0 || done >= total) return 100;
  return static_cast<int>(done * 100 / total);
}

std::string format_run_progress(int moves, int visited, int reachable_cells, double sim_time_s, double elapsed_s) {
  const auto percent = percent_done(static_cast<std::size_t>(std::max(visited, 0)),
                                    static_cast<std::size_t>(std::max(reachable_cells, 0)));
  return fmt::format("moves {}  visited {}/{} reachable cells ({}%)  sim {:.1f} s  elapsed {:.1f} s", moves, visited,
                     reachable_cells, percent, sim_time_s, elapsed_s);
}

std::string format_metres_progress(std::int64_t steps, std::size_t observed, std::size_t reachable_free,
                                   double sim_time_s, double elapsed_s) {
  return fmt::format("steps {}  observed {}/{} reachable free cells ({}%)  sim {:.1f} s  elapsed {:.1f} s", steps,
                     observed, reachable_free, percent_done(observed, reachable_free), sim_time_s, elapsed_s);
}

std::string format_batch_progress(std::size_t done, std::size_t total, double elapsed_s) {
  constexpr std::size_t kWidth = 30;
  const std::size_t filled = total == 0 || done >= total ? kWidth : done * kWidth / total;
  std::string line = fmt::format("[{}{}] {:3}%  {}/{} worlds", std::string(filled, '#'), std::string(kWidth - filled, ' '),
                                 percent_done(done, total), done, total);
  if (done > 0 && done < total) {
    const double left_s = elapsed_s / static_cast<double>(done) * static_cast<double>(total - done);
    line += fmt::format("  {} left", format_clock(left_s));
  }
  return line;
}

ProgressLine::ProgressLine(int fd, int reachable_cells)
    : fd_(fd), reachable_cells_(reachable_cells), started_(std::chrono::steady_clock::now()), next_draw_(started_) {}

ProgressLine::~ProgressLine() {
  if (drawn_) write_progress(fd_, kClearLine);
}

bool ProgressLine::due() {
  const auto now = std::chrono::steady_clock::now();
  if (now < next_draw_) return false;
  next_draw_ = now + std::chrono::milliseconds(100);
  return true;
}

void ProgressLine::draw(const std::string &text) {
  write_progress(fd_, kClearLine + fitted_to_terminal(fd_, text));
  drawn_ = true;
}

void ProgressLine::update(int moves, int visited, double sim_time_s) {
  if (!due()) return;
  draw(format_run_progress(moves, visited, reachable_cells_, sim_time_s, seconds_since(started_)));
}

void ProgressLine::update_metres(std::int64_t steps, const std::function<std::size_t()> &observed, double sim_time_s) {
  if (!due()) return;
  draw(format_metres_progress(steps, observed(), static_cast<std::size_t>(reachable_cells_), sim_time_s,
                              seconds_since(started_)));
}

BatchProgressLine::BatchProgressLine(int fd) : fd_(fd), started_(std::chrono::steady_clock::now()) {}

BatchProgressLine::~BatchProgressLine() {
  if (drawn_) write_progress(fd_, kClearLine);
}

void BatchProgressLine::update(std::size_t done, std::size_t total) {
  write_progress(fd_, kClearLine + fitted_to_terminal(fd_, format_batch_progress(done, total, seconds_since(started_))));
  drawn_ = true;
}

}  // namespace app
