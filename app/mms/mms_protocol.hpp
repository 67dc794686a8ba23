#pragma once
// The mms protocol (mackorone/mms, the micromouse simulator): an algorithm, any program,
// writes one command a line on its standard output and reads the answer, when the command
// has one, a line on its standard input. This file holds what the protocol is apart from
// any robot: reading a line into a command, and mms's stats and score.
//
//   command            answer                 command             answer
//   mazeWidth          16                     setWall X Y D       none (D: n e s w)
//   mazeHeight         16                     clearWall X Y D     none
//   wallFront [N]      true | false           setColor X Y C      none (C: a colour letter)
//   wallRight [N]      true | false           clearColor X Y      none
//   wallLeft [N]       true | false           clearAllColor       none
//   wallBack [N]       true | false           setText X Y TEXT    none
//   wallFrontLeft [N]  (also FrontRight,      clearText X Y       none
//                      BackLeft, BackRight)   clearAllText        none
//   moveForward [N]    ack | crash            wasReset            true | false
//   turnLeft|turnLeft90, turnRight|turnRight90  ack               ackReset  ack
//   getStat NAME       a number, -1 when it has no value yet
//   moveForwardHalf [N], turnLeft45, turnRight45: half steps and diagonals (read, then
//                      refused by the session: the robot moves cell by cell)
//
// The words are mms's (its README and its source): tokens are separated by blanks, a
// number is a decimal integer with an optional sign, an argument that is not one counts as
// 0 where mms reads it so (moveForward abc is moveForward 0: crash). mms ignores a line it
// cannot read without a word; here that is a ParsedLine with an error, and the session
// decides.

#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace app {

enum class MmsVerb {
  maze_width, maze_height,
  wall_front, wall_right, wall_left, wall_back,
  wall_front_left, wall_front_right, wall_back_left, wall_back_right,
  move_forward, move_forward_half, turn_right, turn_left, turn_right_45, turn_left_45,
  set_wall, clear_wall, set_color, clear_color, clear_all_color, set_text, clear_text, clear_all_text,
  was_reset, ack_reset, get_stat,
};

// The longest moveForward N carried out: mms counts a move in half steps in an int, so a
// larger N overflows there and crashes; here it is answered crash, nothing moved or counted.
// N beyond an int reads as 0, as Qt's toInt reads it (crash too).
inline constexpr int kMaxMoveCells = std::numeric_limits<int>::max() / 2;

struct MmsCommand {
  MmsVerb verb = MmsVerb::maze_width;
  int x = 0;
  int y = 0;
  int count = 1;         // moveForward N, wall* N (half steps away), moveForwardHalf N
  char side = 'n';       // setWall, clearWall: n e s w (lower case; mms's README example writes W)
  char color = 'k';      // setColor
  std::string text;      // setText (printable ASCII, others replaced by '?', at most 10)
  std::string stat;      // getStat
};

// One line read: a command, or why it is none ("unknown command", "setColor takes X Y C").
struct ParsedLine {
  std::optional<MmsCommand> command;
  std::string error;
};
ParsedLine parse_mms_line(std::string_view line);

// Whether a command is answered (all but setWall ... clearAllText).
bool has_answer(MmsVerb verb);

// The colours mms knows, by letter (its README's table, and O, V from its source), and the
// red, green, blue mms draws each in.
std::optional<std::string_view> mms_color_name(char letter);
struct MmsRgb {
  int r = 0;
  int g = 0;
  int b = 0;
};
std::optional<MmsRgb> mms_color_rgb(char letter);

// mms's stats and score, as its Stats tab and getStat compute them:
//   distance            cells asked to move (moveForward N adds N, also when it crashes
//                       on the way; a crash on a wall right ahead adds nothing)
//   effective distance  each moveForward N adds N when N <= 2, else N / 2 + 1 (a straight run
//                       is driven faster); an ackReset adds 15 to the next run's
//   turns               one a turn command
//   a run               starts with a move from the start cell and ends, finished, when a
//                       move comes to rest in a goal cell, or, unfinished, back in the start
//                       cell; the best run is the finished one with the fewest
//                       turns + effective distance
//   score               best run turns + best run effective distance
//                       + 0.1 * (total turns + total effective distance),
//                       2000 until a run has finished; lower is better
class MmsStats {
 public:
  void start_run();
  void add_distance(long long cells);
  void add_turn();
  void finish_run();
  void end_unfinished_run();
  void penalize_for_reset();

  bool running() const { return started_run_; }
  bool solved() const { return solved_; }
  long long total_distance() const { return total_distance_; }
  int total_turns() const { return total_turns_; }
  float total_effective_distance() const { return total_effective_; }
  std::optional<long long> best_run_distance() const;
  std::optional<int> best_run_turns() const;
  std::optional<float> best_run_effective_distance() const;
  long long current_run_distance() const { return current_distance_; }
  int current_run_turns() const { return current_turns_; }
  float current_run_effective_distance() const { return current_effective_; }
  float score() const;

  // getStat's answer for a stat name (total-distance, best-run-turns, score, ...): the
  // value as mms prints it, "-1" when it has none yet; nothing for an unknown name.
  std::optional<std::string> stat(std::string_view name) const;

 private:
  bool started_run_ = false;
  bool solved_ = false;
  float penalty_ = 0.0F;
  long long total_distance_ = 0;  // 64 bits: moveForward adds up to kMaxMoveCells a line
  int total_turns_ = 0;
  float total_effective_ = 0.0F;
  long long current_distance_ = 0;
  int current_turns_ = 0;
  float current_effective_ = 0.0F;
  long long best_distance_ = 0;
  int best_turns_ = 0;
  float best_effective_ = 0.0F;
};

// A number as mms prints it (Qt's QString::number: %g, 6 significant digits).
std::string mms_number(double value);

}  // namespace app
