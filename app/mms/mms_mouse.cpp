#include "app/mms/mms_mouse.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace app {
namespace {

using mapping::Cell;
using mapping::Heading;
using mapping::SideState;

maze::Side to_side(Heading h) {
  switch (h) {
    case Heading::north: return maze::Side::north;
    case Heading::east: return maze::Side::east;
    case Heading::south: return maze::Side::south;
    case Heading::west: return maze::Side::west;
  }
  return maze::Side::north;
}

MmsOutcome answer(std::string text) { return MmsOutcome{std::move(text), std::nullopt, {}}; }

}  // namespace

MmsMouse::MmsMouse(const maze::Maze &truth, const MmsOptions &options, robot::CommandController &controller,
                   const robot::ControllerOptions &controller_options, MmsReport &report)
    : truth_(truth),
      options_(options),
      controller_(controller),
      start_(controller_options.start),
      start_heading_(controller_options.start_heading),
      heading_(controller_options.start_heading),
      report_(report) {}

MmsOutcome MmsMouse::execute(const MmsCommand &c) {
  switch (c.verb) {
    case MmsVerb::maze_width: return answer(std::to_string(truth_.width()));
    case MmsVerb::maze_height: return answer(std::to_string(truth_.height()));
    case MmsVerb::wall_front: return wall_query(heading_, c.count);
    case MmsVerb::wall_right: return wall_query(mapping::turned_right(heading_), c.count);
    case MmsVerb::wall_left: return wall_query(mapping::turned_left(heading_), c.count);
    case MmsVerb::wall_back: return wall_query(mapping::opposite(heading_), c.count);
    case MmsVerb::wall_front_left:
    case MmsVerb::wall_front_right:
    case MmsVerb::wall_back_left:
    case MmsVerb::wall_back_right: return answer("true");
    case MmsVerb::move_forward: return move_forward(c.count);
    case MmsVerb::turn_left: return turn(mapping::turned_left(heading_));
    case MmsVerb::turn_right: return turn(mapping::turned_right(heading_));
    case MmsVerb::move_forward_half:
    case MmsVerb::turn_left_45:
    case MmsVerb::turn_right_45:
      return MmsOutcome{std::nullopt, MmsEnd::protocol_error,
                        "half steps and 45-degree turns are not simulated (the robot moves cell by cell)"};
    case MmsVerb::was_reset: return answer("false");  // no reset button here
    case MmsVerb::ack_reset: return ack_reset();
    case MmsVerb::get_stat: {
      std::optional<std::string> value = report_.stats.stat(c.stat);
      if (!value) return MmsOutcome{std::nullopt, MmsEnd::protocol_error, fmt::format("getStat: no stat '{}'", c.stat)};
      return answer(*value);
    }
    default: return mark(c);
  }
}

MmsOutcome MmsMouse::mark(const MmsCommand &c) {
  report_.marks.apply(c);
  return {};
}

bool MmsMouse::until_reached() const {
  const Cell at = controller_.cell();
  switch (options_.until) {
    case MmsUntil::exit: return false;
    case MmsUntil::goal: return in_goal(at);
    case MmsUntil::start: return report_.stats.solved() && at == start_;
  }
  return false;
}

bool MmsMouse::in_goal(Cell c) const { return truth_.is_goal(maze::Cell{c.x, c.y}); }

MmsOutcome MmsMouse::motion_failed(robot::Motion m) {
  robot_motion_ = m;
  return MmsOutcome{std::nullopt, MmsEnd::robot, {}};
}

std::optional<bool> MmsMouse::wall(Cell c, Heading h, bool own_cell) {
  if (options_.walls == MmsWalls::truth) return truth_.has_wall(maze::Cell{c.x, c.y}, to_side(h));
  if (!own_cell) return controller_.side(c, h) == SideState::wall;
  SideState state = SideState::unknown;
  if (const robot::Motion m = controller_.look(h, state); m != robot::Motion::ok) {
    robot_motion_ = m;
    return std::nullopt;
  }
  return state != SideState::open;
}

// N half steps away: the sides of ceil(N / 2) cells on (mms counts from the cell's centre,
// and a half step reaches the next side).
MmsOutcome MmsMouse::wall_query(Heading h, int half_steps) {
  const int cells = std::max(1, half_steps / 2 + half_steps % 2);
  Cell c = controller_.cell();
  for (int i = 0; i < cells; ++i) {
    const std::optional<bool> is_wall = wall(c, h, i == 0);
    if (!is_wall) return motion_failed(robot_motion_);
    if (*is_wall) return answer("true");
    c = mapping::neighbour(c, h);
    if (!truth_.contains(maze::Cell{c.x, c.y})) return answer("true");  // the maze's edge: walled
  }
  return answer("false");
}

MmsOutcome MmsMouse::turn(Heading h) {
  report_.stats.add_turn();
  heading_ = h;
  if (const robot::Motion m = controller_.turn_to(h); m != robot::Motion::ok) return motion_failed(m);
  return answer("ack");
}

// How many cells from the robot's on along its heading, at most `most`, can be driven in one
// leg: the side ahead of its own cell has been checked open; each further one must be known
// open already, as a leg does not stop to look: the truth, or in --walls sensed what the
// robot knows (its grid, and its last scan down the straight: CommandController::open_ahead).
int MmsMouse::straight_known_open(int most) const {
  if (options_.walls == MmsWalls::sensed) return std::max(1, controller_.open_ahead(heading_, most));
  int cells = 1;
  Cell c = mapping::neighbour(controller_.cell(), heading_);
  while (cells < most && !truth_.has_wall(maze::Cell{c.x, c.y}, to_side(heading_))) {
    ++cells;
    c = mapping::neighbour(c, heading_);
  }
  return cells;
}

MmsOutcome MmsMouse::move_forward(int cells) {
  if (cells < 1 || cells > kMaxMoveCells) return crash();
  const std::optional<bool> ahead = wall(controller_.cell(), heading_, true);
  if (!ahead) return motion_failed(robot_motion_);
  if (*ahead) return crash();
  if (controller_.cell() == start_) report_.stats.start_run();
  report_.stats.add_distance(cells);
  bool crashed = false;
  for (int driven = 0; driven < cells;) {
    if (driven > 0) {
      const std::optional<bool> next = wall(controller_.cell(), heading_, true);
      if (!next) return motion_failed(robot_motion_);
      crashed = *next;
      if (crashed) break;
    }
    // The straight as one leg: the robot's speed-run ramp over the cells known open.
    const int leg = straight_known_open(cells - driven);
    if (const robot::Motion m = controller_.move_straight(heading_, leg); m != robot::Motion::ok) return motion_failed(m);
    driven += leg;
  }
  if (in_goal(controller_.cell())) {
    report_.stats.finish_run();
  } else if (controller_.cell() == start_) {
    report_.stats.end_unfinished_run();
  }
  return crashed ? crash() : answer("ack");
}

MmsOutcome MmsMouse::crash() {
  ++report_.crashes;
  return answer("crash");
}

MmsOutcome MmsMouse::ack_reset() {
  bool found = false;
  if (const robot::Motion m = controller_.return_to_start(found); m != robot::Motion::ok) return motion_failed(m);
  if (!found) return MmsOutcome{std::nullopt, MmsEnd::robot, "ackReset: no way back to the start through sides known open"};
  heading_ = start_heading_;
  report_.stats.penalize_for_reset();
  report_.stats.end_unfinished_run();
  return answer("ack");
}

}  // namespace app
