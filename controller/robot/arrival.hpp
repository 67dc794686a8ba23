#pragma once
// What the robot does in a cell after driving into it, as its set-up's row says
// (sensing::Arrival): first a scan at rest (a rotating lidar: after a whole revolution), then
//   resolve   while a side of the cell is unknown (every beam towards it filtered out as a
//             fault, every range reading about it ignored), rest a step and scan again: the
//             next reading is a new draw of the sensor, not the same faulty one; then face
//             each side still unknown and do the same (other beams look at it, the cell
//             model's beams point straight at it). A side still unknown that leads to a cell
//             inside the maze is listed (unresolved_sides): the run then ends incomplete.
//   confirm   (lidar, after resolve) a side the grid calls open while the last scan, taken
//             here, reads a wall on it (the cell model's reading) is scanned again until the
//             grid agrees: a band freed by a faulty beam from afar must not send the robot
//             into the wall. Each scan adds one occupied update; 3 * max_rescans at most.
//   probe     (bumpers) each unknown side: turn to it, creep forward until a bumper presses
//             or the centre is half a sub-cell into the neighbour, back to the centre. Each
//             pass (forward, back) is one scan: the bump readings of every step, applied once.
//   look      (depth: rays over the front 120 deg only, and a ray grazing a side frees its
//   around    band) in a new cell, face each other side in turn and scan, which puts the
//             straight-ahead ray on every band middle.

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "explore/strategies.hpp"
#include "explore/visits.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "robot/drive.hpp"
#include "robot/options.hpp"
#include "robot/senses.hpp"

namespace robot {

class Arrival {
 public:
  // Everything must outlive the Arrival; steps() is the control steps so far.
  Arrival(const ControllerOptions &options, Drive &drive, Senses &senses, const mapping::OccupancyGrid &grid,
          explore::Visits &visits, explore::WallQuery walls, std::function<std::int64_t()> steps);

  // Scans in cell c and does the set-up's arrival behaviour; `facing` follows the turns.
  Motion arrive(mapping::Cell c, mapping::Heading &facing, bool new_cell);
  // The sides listed as unresolved that are still unknown and lead to a cell never visited,
  // as "2 sides of visited cells still unknown: E of (3,4), N of (5,1)" (the first three), or empty.
  std::string unresolved_sides() const;

 private:
  Motion await_revolution();
  Motion rest_and_scan(mapping::Cell c);
  void scan(mapping::Cell c) { senses_.scan(c, steps_()); }
  bool unknown(mapping::Cell c, mapping::Heading h) const;
  Motion rescan_while_unknown(mapping::Cell c, const std::function<bool()> &still_unknown);
  Motion resolve(mapping::Cell c, mapping::Heading &facing);
  Motion confirm(mapping::Cell c);
  Motion probe_unknown_sides(mapping::Cell c, mapping::Heading &facing);
  Motion probe(mapping::Cell c, mapping::Heading h);
  Motion look_around(mapping::Cell c, mapping::Heading &facing);
  void face(mapping::Cell c, mapping::Heading h, mapping::Heading &facing);

  const ControllerOptions &options_;
  sensing::Arrival behaviour_;
  Drive &drive_;
  Senses &senses_;
  const mapping::OccupancyGrid &grid_;
  explore::Visits &visits_;
  explore::WallQuery walls_;
  std::function<std::int64_t()> steps_;
  // Sides the robot looked at in every way it has and still does not know (cell, side).
  std::vector<std::pair<mapping::Cell, mapping::Heading>> unresolved_;
};

}  // namespace robot
