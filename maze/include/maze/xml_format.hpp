#pragma once
// Wall-segment XML, as used by Webots maze courses: walls are segments in metres on a
// regular grid; cell size and origin are inferred from them.
//
//     <world>                                             y
//       <wall x1="0" y1="0" x2="2" y2="0" width="0.012"/>  2 +-------+
//       <wall x1="0" y1="2" x2="2" y2="2"/>                  |   |   |
//       <wall x1="0" y1="0" x2="0" y2="2"/>                1 +   +   +
//       <wall x1="2" y1="0" x2="2" y2="2"/>                  | S |   |
//       <wall x1="1" y1="0" x2="1" y2="2"/>                0 +---+---+ x
//       <startPositions>                                     0   1   2
//         <pos x="0.5" y="0.5" theta="1.5708"/>
//       </startPositions>                              a 2 x 2 maze of 1 m cells,
//       <goal id="0" x="1.5" y="1.5"/>                   goal in (1,1)
//     </world>
//
//   - A wall is horizontal or vertical and runs between grid points; it may span several
//     cells. `width` (m, default 0.012) is the wall thickness; all walls share one.
//   - Origin: the smallest x and y of any wall end. Cell size: the shortest wall's length
//     (write walls one cell side each, as write_xml does, and any maze reads back). Every
//     wall end must then lie on that grid, else it is "off the grid".
//   - The first <pos> is the start: its cell, and theta (rad, 0 east, pi/2 north, default
//     pi/2) rounded to N, E, S or W; no <startPositions>: (0,0) facing north.
//   - <goal x y> marks the cell holding that point. Other elements are ignored.

#include <string>
#include <string_view>

#include "maze/maze.hpp"

namespace maze {

// Reads wall-segment XML; `file` names it in messages. Throws common::InputError at the
// faulty element (line, and the column of the attribute when it is on that line).
Maze read_xml(std::string_view text, const std::string &file);

// One <wall> per walled cell side (so the grid can be inferred back), the start, the goals.
std::string write_xml(const Maze &maze);

}  // namespace maze
