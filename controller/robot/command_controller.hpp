#pragma once
// A cell controller driven by commands from outside instead of a strategy: an algorithm
// speaking the mms protocol (app/mms/mms_session.hpp) tells it to look at a side, turn, or
// move one cell; it does each as CellController would (turn in place, drive one cell, arrive
// and scan as the set-up says), and answers only from what its sensors mapped into the
// grid. Like every controller it is told the maze's geometry, start and goals, never the
// walls.

#include <cstdint>
#include <memory>
#include <string>

#include "explore/visits.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/walls.hpp"
#include "robot/cell/controller.hpp"
#include "robot/options.hpp"

namespace webots {
class Robot;
}

namespace robot {

struct CellRobot;

class CommandController {
 public:
  // Validates the options (common::InputError) and finds the devices; the robot must
  // outlive the controller.
  CommandController(webots::Robot &robot, const ControllerOptions &options);
  ~CommandController();
  CommandController(const CommandController &) = delete;
  CommandController &operator=(const CommandController &) = delete;

  // Takes the first step and arrives in the start cell. Call once, first.
  Motion start(const RunHooks &hooks);

  mapping::Cell cell() const;
  // The side's state as the grid holds it now (no looking).
  mapping::SideState side(mapping::Cell c, mapping::Heading h) const;
  // How many cells along h, at most `most`, the robot knows it can drive without stopping:
  // the sides from its own cell's on, each held open by the grid or seen clear by its last
  // lidar scan when that was taken in this cell (the beams down the straight: Senses::
  // sees_side_ahead), and called a wall by neither; the first other side, or the grid's
  // edge, ends them. No looking: 0 when its own side is not known open.
  int open_ahead(mapping::Heading h, int most) const;
  // Side h of the robot's cell as its sensors tell it: a side the grid does not know yet is
  // looked at first (face it, scan again up to max_rescans times at rest); `state` is
  // unknown only when it stayed unknown. The robot may be left facing h.
  Motion look(mapping::Heading h, mapping::SideState &state);
  // Turns in place to heading h (nothing when facing it already).
  Motion turn_to(mapping::Heading h);
  // Turns to h if needed and drives one cell along it, then arrives (scan, the set-up's
  // arrival). The caller checks the side first: a wall there stalls the drive (no_progress).
  Motion move(mapping::Heading h);
  // Turns to h if needed and drives `cells` cells along it in one leg, then arrives in the
  // last (scan, the set-up's arrival; the cells passed are recorded as visited, no stop or
  // scan in them). The leg accelerates once, cruises and decelerates once: with the robot's
  // speed-run profile (ControllerOptions::motion's ramp) its trapezoid, as the speed run's
  // straights, one cell too; else the drive's own speed law to the last cell (one cell is
  // then move()). The caller checks every side on the way is open.
  Motion move_straight(mapping::Heading h, int cells);
  // Drives back to the start cell on the shortest route through sides known open (without
  // mapping) and turns to the start heading; `found` false (nothing driven) when there is
  // no such route.
  Motion return_to_start(bool &found);

  // The grid, visits and counts so far.
  const mapping::OccupancyGrid &grid() const;
  const explore::Visits &visits() const;
  std::int64_t steps() const;
  double time_s() const;
  // The ending a motion that was not ok stands for, and its message (what stalled, where).
  EndReason ended(Motion s, std::string &message);
  // Flushes the last step's report and hands over the run: grid, visits, path, counts.
  // Call once, last; `reason` and `message` are the caller's.
  RunResult finish(EndReason reason, std::string message);

 private:
  std::unique_ptr<CellRobot> body_;
};

}  // namespace robot
