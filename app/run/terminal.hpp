#pragma once
// The terminal side of `run`: its size, the alternate screen for --animate. (Ctrl-C and the
// other stop signals: common/interrupt.hpp.)

#include <string>
#include <string_view>

#include <atomic>
#include <chrono>
#include <iosfwd>
#include <optional>

#include "render/ascii_map.hpp"
#include "robot/cell/controller.hpp"
#include "robot/progress_printer.hpp"

namespace app {

bool is_terminal(int fd);

// --color WHEN: auto colours when the output is a terminal and NO_COLOR is unset or empty
// (no-color.org); always and never as they say (the command line over the environment).
enum class ColorChoice { automatic, always, never };
struct ColorWord {
  std::string_view word;
  ColorChoice choice;
};
// The words --color takes, in the order its help names them (parsing and completion read them).
inline constexpr ColorWord kColorWords[] = {
    {"auto", ColorChoice::automatic}, {"always", ColorChoice::always}, {"never", ColorChoice::never}};
// A word of kColorWords; anything else throws common::InputError naming --color.
ColorChoice parse_color_choice(const std::string &text);
bool use_color(ColorChoice choice, int fd);

struct TerminalSize {
  int columns = 80;
  int rows = 24;
};
// ioctl(TIOCGWINSZ) on fd; 80 x 24 when fd is not a terminal or reports 0.
TerminalSize terminal_size(int fd);

// The terminal columns a sub-cell is drawn with: `asked` (--narrow 1, --wide 2) when given;
// else 2 when fd is a terminal at least 2 * map_subcells_wide columns wide, else 1 (a pipe
// or a file, where the golden outputs live, or a map too wide: the classroom look).
int subcell_columns(std::optional<int> asked, int fd, int map_subcells_wide);

// When fd is a terminal narrower than the map drawn `columns` a sub-cell: one line on stderr
// saying how to see the map whole (a file, --animate's window, --out's pictures).
void note_if_too_wide(int fd, int map_subcells_wide, int columns);

// The terminal `run` draws its progress line on: standard error when it is a terminal and
// the map does not go to that screen (--quiet, or standard output redirected) and --animate
// is off; -1 (none) otherwise.
int progress_fd(bool quiet, bool animate);

// The part of the map `run` prints in each block when standard output (fd) is a terminal
// smaller than the map: the terminal's rows less the status line, the cell's K x K matrix
// and the blank line, and its columns; none (the whole map) in pipes, files and where the
// map fits. Such a view prints at most 20 blocks a second. When there is one, says so once on
// stderr.
std::optional<robot::ProgressPrinter::View> view_for_terminal(int fd, int k, int map_rows, int map_cols,
                                                              int subcell_columns);

// While alive: the alternate screen, the cursor hidden. Destroying it (also on an exception
// or after Ctrl-C) shows the cursor and returns to the normal screen, which is unchanged.
class ScreenGuard {
 public:
  explicit ScreenGuard(std::ostream &out);
  ~ScreenGuard();
  ScreenGuard(const ScreenGuard &) = delete;
  ScreenGuard &operator=(const ScreenGuard &) = delete;

 private:
  std::ostream &out_;
};

struct AnimationOptions {
  double fps = 30.0;          // frames per wall-clock second, at most
  double speed = 10.0;        // simulated seconds per wall-clock second
  TerminalSize screen;
};

// Draws frames in place: cursor home, a status line, the part of the map that fits the
// screen, following the robot (drawn as @ at its true position).
class Animator {
 public:
  Animator(std::ostream &out, const render::MapStyle &style, const AnimationOptions &options);

  // Keeps the run at --speed (waits while the simulated time is ahead of speed x the wall
  // time since the first step) and draws a frame when 1 / fps wall seconds have passed since
  // the last one: frames are skipped, never waited for, so a --speed the terminal cannot
  // draw at still runs at that speed. The first step always draws.
  void on_step(const robot::StepReport &step, double x_m, double y_m);

 private:
  void draw(const robot::StepReport &step, double x_m, double y_m);

  std::ostream &out_;
  render::MapStyle style_;
  AnimationOptions options_;
  bool started_ = false;
  double start_sim_s_ = 0.0;
  std::chrono::steady_clock::time_point start_wall_;
  std::chrono::steady_clock::time_point next_frame_;
};

}  // namespace app
