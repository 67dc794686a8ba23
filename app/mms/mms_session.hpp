#pragma once
// `maze_mapper mms [WORLD] -- COMMAND [ARGS...]`: an mms-protocol algorithm (a child
// process, app/mms/child_process.hpp) drives the simulated robot cell by cell. Each of its
// moves is one driven move of the robot (robot::CommandController: turn in place, drive a
// cell, arrive and scan as in `run`); its wall questions are answered from the maze, as mms
// does (--walls truth), or from what the robot's sensors mapped into the grid (--walls
// sensed). mms's stats and score are kept as mms keeps them (app/mms/mms_protocol.hpp).
//
// The conversation ends when the algorithm exits (or closes its output), when --until's
// cell is reached (the goal; or the start, after the goal), at the time limit, on a line
// that is no command (the line and its number say where), on a half step or 45-degree turn
// (not simulated), or when the robot cannot go on (no progress, the step limit, Ctrl-C).
// Whatever ends it, the child's process group is killed and reaped.

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/mms/child_process.hpp"
#include "app/mms/mms_marks.hpp"
#include "app/mms/mms_protocol.hpp"
#include "app/run/run.hpp"
#include "maze/world/maze.hpp"

namespace app {

enum class MmsWalls { truth, sensed };
enum class MmsUntil { exit, goal, start };

struct MmsOptions {
  std::vector<std::string> command;       // the algorithm and its arguments
  MmsWalls walls = MmsWalls::sensed;
  MmsUntil until = MmsUntil::exit;
  double wall_limit_s = 60.0;             // --wall-limit: wall clock, the whole conversation; inf: none
  std::size_t max_line_bytes = 4096;      // a longer line ends it (a flood)
  bool ignore_invalid = false;            // --ignore-invalid: skip lines that are no command, as mms does
  bool transcript = false;                // --transcript: the conversation on stderr
};

// Throws common::InputError for an empty command, a time limit <= 0 or NaN, a line cap < 64.
// A time limit past what the clock counts (1e10 s, inf) is no limit.
void validate(const MmsOptions &options);

enum class MmsEnd {
  exited,          // the algorithm ended (exit status 0)
  reached,         // --until goal / start: reached
  failed,          // the algorithm ended otherwise (status, signal) or closed its output and hung
  wall_limit,      // --wall-limit ran out (wall-clock seconds: the guard against a hung program)
  protocol_error,  // a line that is no command, too long, or a move not simulated
  robot,           // the robot could not go on (no progress, step limit)
  interrupted,     // Ctrl-C, SIGTERM or SIGHUP
};
std::string_view to_string(MmsEnd end);  // "exited", "reached", "failed", "wall limit", ...

struct MmsReport {
  MmsEnd end = MmsEnd::exited;
  std::string message;            // why it ended, e.g. `line 12 "wallFrnt": unknown command`
  std::optional<ChildExit> exit;  // how the child ended
  long lines = 0;                 // lines the algorithm wrote
  int crashes = 0;                // moveForward answered crash
  MmsStats stats;
  MmsMarks marks{0, 0};
};

struct MmsRun {
  RunSummary summary;   // the robot's run: moves, coverage, wall accuracy, times
  MmsReport mms;
};

// Runs the algorithm on one maze; prints the progress (unless quiet), the final map, the
// algorithm's marks and the summary to out; draws the progress line on
// controls.progress_fd (-1: none). Throws common::InputError when the options do
// not fit the maze or robot, or the command cannot be started. A maze without goals gets
// its centre cells (mms's goal). With --out, a full disk throws common::NoSpaceError after
// the summary is printed.
MmsRun run_mms(const RunOptions &options, const MmsOptions &mms, const maze::Maze &truth, std::ostream &out,
               const RunControls &controls = {});
// Loads options.world and runs run_mms.
MmsRun run_mms_world(const RunOptions &options, const MmsOptions &mms, std::ostream &out,
                     const RunControls &controls = {});

// 0 when the algorithm ended as asked (exited 0, or --until reached) and the robot reached
// the goal; 128 + the signal when interrupted (143 for SIGTERM); 1 otherwise.
int exit_status(const MmsRun &run);

// "python3 algo.py" (arguments with blanks quoted).
std::string command_line(const std::vector<std::string> &command);

}  // namespace app
