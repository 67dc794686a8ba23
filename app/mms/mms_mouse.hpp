#pragma once
// The mouse an mms-protocol algorithm drives: the protocol's pose (cell, heading), mms's
// stats and the algorithm's marks, over the robot (robot::CommandController). It carries
// out one command at a time (app/mms/mms_protocol.hpp), as mms does:
//   wall questions  from the maze (MmsWalls::truth) or from the robot's grid (sensed: a side
//                   of its own cell it has not seen yet is looked at first, and one still
//                   unknown counts as a wall; a side further on, wallFront 3 and beyond,
//                   comes from the grid as it is, unknown counting as no wall; the maze's
//                   edge is a wall, however far N reaches)
//   wallFrontLeft and the other diagonals: true, as from any cell centre in mms (they aim
//                   at a corner post)
//   moveForward N   crash when N < 1, N > kMaxMoveCells or a wall is right ahead (nothing
//                   moves, nothing counted); else the robot drives the straight in legs
//                   over the cells known open (the truth; sensed: its grid and its last
//                   scan down the straight), each leg accelerating and decelerating once
//                   with the robot's speed profile, looking at each side not known before
//                   crossing it, and stops before a wall on the way (crash), else ack
//   turns           the robot turns in place; ack
//   wasReset        false (there is no reset button); ackReset drives the robot back to the
//                   start on the known way (mms lifts it there), the 15-point penalty; ack
//   half steps and 45-degree turns end the run: the robot moves cell by cell
// A cell outside the maze in setWall, setColor, setText and the clears is ignored, as mms
// ignores it.

#include <optional>
#include <string>

#include "app/mms/mms_session.hpp"
#include "maze/world/maze.hpp"
#include "robot/command_controller.hpp"

namespace app {

// How one command went: its answer (none for the display commands), or the end it makes.
struct MmsOutcome {
  std::optional<std::string> answer;
  std::optional<MmsEnd> end;
  std::string message;  // why it ends (empty for the robot's own endings)
};

class MmsMouse {
 public:
  // Everything must outlive the mouse; truth's goals are the run's goals.
  MmsMouse(const maze::Maze &truth, const MmsOptions &options, robot::CommandController &controller,
           const robot::ControllerOptions &controller_options, MmsReport &report);

  MmsOutcome execute(const MmsCommand &c);
  // The --until cell is reached.
  bool until_reached() const;
  // Why the robot stopped, when a command ended the run with MmsEnd::robot (else ok).
  robot::Motion robot_motion() const { return robot_motion_; }

 private:
  MmsOutcome mark(const MmsCommand &c);
  bool in_goal(mapping::Cell c) const;
  MmsOutcome motion_failed(robot::Motion m);
  std::optional<bool> wall(mapping::Cell c, mapping::Heading h, bool own_cell);
  MmsOutcome wall_query(mapping::Heading h, int half_steps);
  MmsOutcome turn(mapping::Heading h);
  // moveForward N: the straight in legs over the cells known open (one ramped leg when all
  // are), checking each side it has not known before; N cells of mms's distance either way.
  MmsOutcome move_forward(int cells);
  int straight_known_open(int most) const;
  MmsOutcome crash();
  MmsOutcome ack_reset();

  const maze::Maze &truth_;
  const MmsOptions &options_;
  robot::CommandController &controller_;
  mapping::Cell start_;
  mapping::Heading start_heading_;
  mapping::Heading heading_;
  MmsReport &report_;
  robot::Motion robot_motion_ = robot::Motion::ok;
};

}  // namespace app
