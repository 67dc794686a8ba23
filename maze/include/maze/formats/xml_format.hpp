#pragma once
// Wall-segment XML, as used by Webots maze courses (FAIRIS-Lite): walls are segments in metres
// on a regular lattice; cell size and origin are inferred from them.
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
//   - Origin: the smallest x and y of any wall end. Cell size (docs/formats.md, "The cell
//     size of an XML world"): `<world cellSize="...">` when the file states it (write_xml
//     does); else the one chosen (--cell-size); else the coarsest lattice that puts every
//     start position on a cell centre, when every wall end lies on it (a walled open 11 x 11 m
//     arena with a start at 0.5 m from two walls reads as 11 x 11 cells of 1 m); else the
//     lattice of the wall ends: the largest length dividing every end's offset from the origin
//     (and so every wall's length), to within 1e-6 m (1e-6 of the maze's extent above 1 m),
//     with a warning naming the walls off the start positions' lattice when they have one.
//     The course's 5 x 5 m frames with inner walls on a 0.5 m lattice read as 10 x 10 cells of
//     0.5 m. A lattice no coarser than 4 wall thicknesses is none: the first wall end that
//     breaks it is "off the grid".
//   - Not grid mazes: no <wall> (an open arena); walls at least a quarter as thick as the
//     shortest wall is long (an arena of obstacles, e.g. width="1"), or a quarter of a stated
//     cellSize.
//   - The first <pos> is the start: the cell holding it (a pose on a grid line or a lattice
//     node: the cell ahead of it along its heading, else the one east or north of it), and
//     theta (rad, 0 east, pi/2 north, default pi/2) rounded to N, E, S or W; no
//     <startPositions>: (0,0) facing north. A run starts the robot at that cell's centre.
//   - <goal x y> marks the cell holding that point. Other elements are ignored.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "maze/world/maze.hpp"

namespace maze {

// Reads wall-segment XML; `file` names it in messages. Throws common::InputError at the
// faulty element (line, and the column of the attribute when it is on that line).
Maze read_xml(std::string_view text, const std::string &file);

struct XmlReadOptions {
  // The cells' size when the file states none (--cell-size): the walls must lie on its
  // lattice. One that differs from a stated cellSize is an error.
  std::optional<double> cell_size_m;
};
// A maze read, and what the user should hear about it: whole lines "FILE: warning: ...".
struct XmlRead {
  Maze maze;
  std::vector<std::string> warnings;
};
XmlRead read_xml(std::string_view text, const std::string &file, const XmlReadOptions &options);

// The course's own layout: the maze centred on (0, 0) (the course's floor is a square centred
// on the origin), cellSize stated, each run of collinear walls one <wall>, the landmarks,
// every start position (the start first, each on its cell's centre facing its heading),
// the goals. Read back, it is the same maze, moved to the new origin (and to be exact, the
// start position list reordered so that the start is first).
std::string write_xml(const Maze &maze);
// The same at the maze's own origin: read back, the very same maze.
std::string write_xml_keeping_origin(const Maze &maze);

}  // namespace maze
