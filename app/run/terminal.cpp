#include "app/run/terminal.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/standard_streams.hpp"

namespace app {

bool is_terminal(int fd) { return ::isatty(fd) == 1; }

int progress_fd(bool quiet, bool animate) {
  if (animate || !is_terminal(STDERR_FILENO)) return -1;
  return quiet || !is_terminal(STDOUT_FILENO) ? STDERR_FILENO : -1;
}

ColorChoice parse_color_choice(const std::string &text) {
  for (const ColorWord &w : kColorWords) {
    if (text == w.word) return w.choice;
  }
  throw common::InputError(fmt::format("--color must be auto, always or never (got '{}')", text));
}

bool use_color(ColorChoice choice, int fd) {
  if (choice != ColorChoice::automatic) return choice == ColorChoice::always;
  const char *no_color = std::getenv("NO_COLOR");
  return (no_color == nullptr || *no_color == '\0') && is_terminal(fd);
}

TerminalSize terminal_size(int fd) {
  winsize ws{};
  if (::ioctl(fd, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0 && ws.ws_row > 0) {
    return {ws.ws_col, ws.ws_row};
  }
  return {};
}

int subcell_columns(std::optional<int> asked, int fd, int map_subcells_wide) {
  if (asked) return *asked;
  if (fd < 0 || !is_terminal(fd)) return 1;
  return 2 * map_subcells_wide <= terminal_size(fd).columns ? 2 : 1;
}

void note_if_too_wide(int fd, int map_subcells_wide, int columns) {
  if (fd < 0 || !is_terminal(fd)) return;
  const int width = map_subcells_wide * columns;
  const int terminal = terminal_size(fd).columns;
  if (width <= terminal) return;
  common::print_stderr(
      "note: the map is {} columns wide and this terminal {}: its lines wrap; see it whole in a file "
      "(run ... > run.txt), follow the robot with --animate, or open --out's map.png and replay.html\n",
      width, terminal);
}

std::optional<robot::ProgressPrinter::View> view_for_terminal(int fd, int k, int map_rows, int map_cols,
                                                              int subcell_columns) {
  if (fd < 0 || !is_terminal(fd)) return std::nullopt;
  const TerminalSize screen = terminal_size(fd);
  // 20 blocks a second at most: what a reader can follow, and far less than the run costs.
  const robot::ProgressPrinter::View view{std::max(3, screen.rows - (k + 3)),
                                          std::max(3, screen.columns / std::max(1, subcell_columns)),
                                          std::chrono::milliseconds(50)};
  if (view.rows >= map_rows && view.cols >= map_cols) return std::nullopt;
  common::print_stderr(
      "note: the map is {}x{} sub-cells, the terminal shows {}x{}: up to 20 moves a second print the part around "
      "the robot; the final map is printed whole\n",
      map_cols, map_rows, view.cols, view.rows);
  return view;
}

ScreenGuard::ScreenGuard(std::ostream &out) : out_(out) {
  out_ << "\x1b[?1049h\x1b[?25l\x1b[H\x1b[2J" << std::flush;
}

ScreenGuard::~ScreenGuard() { out_ << "\x1b[0m\x1b[?25h\x1b[?1049l" << std::flush; }

Animator::Animator(std::ostream &out, const render::MapStyle &style, const AnimationOptions &options)
    : out_(out), style_(style), options_(options), next_frame_(std::chrono::steady_clock::now()) {}

void Animator::on_step(const robot::StepReport &step, double x_m, double y_m) {
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](double s) { return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s)); };
  if (!started_) {
    started_ = true;
    start_sim_s_ = step.sim_time_s;
    start_wall_ = Clock::now();
    next_frame_ = start_wall_;
  }
  const Clock::time_point due = start_wall_ + seconds((step.sim_time_s - start_sim_s_) / options_.speed);
  if (due > Clock::now()) std::this_thread::sleep_until(due);
  const Clock::time_point now = Clock::now();
  if (now < next_frame_) return;
  next_frame_ = now + seconds(1.0 / options_.fps);
  draw(step, x_m, y_m);
}

void Animator::draw(const robot::StepReport &step, double x_m, double y_m) {
  const mapping::OccupancyGrid &grid = *step.grid;
  const int map_rows = grid.height() * grid.k();
  const int map_cols = grid.width() * grid.k();
  const int rows = std::min(map_rows, std::max(1, options_.screen.rows - 2));
  const int cols = std::min(map_cols, std::max(1, options_.screen.columns / style_.subcell_columns));
  render::MapStyle style = style_;
  mapping::SubCell at{map_cols / 2, map_rows / 2};
  if (const auto s = grid.subcell_at(mapping::Point{x_m, y_m})) {
    style.robot = render::RobotMark{*s, "@"};
    at = *s;
  }
  const render::MapWindow window = render::window_around(grid, at, rows, cols);
  std::string frame = "\x1b[H";
  frame += render::format_status(static_cast<long>(step.step), step.cell, step.heading,
                                 step.visits->count(), grid.width() * grid.height());
  frame += fmt::format("  t {:.1f} s", step.sim_time_s);
  if (rows < map_rows || cols < map_cols) {
    frame += fmt::format("  view {},{} of {}x{}", window.first_col, window.first_row, map_cols, map_rows);
  }
  if (frame.size() > static_cast<std::size_t>(options_.screen.columns) + 3) {
    frame.resize(static_cast<std::size_t>(options_.screen.columns) + 3);
  }
  frame += "\x1b[K\n";
  std::string map;
  render::render_window(map, grid, *step.visits, style, window);
  for (const char ch : map) {
    if (ch == '\n') frame += "\x1b[K";
    frame += ch;
  }
  frame += "\x1b[J";
  out_ << frame << std::flush;
}

}  // namespace app
