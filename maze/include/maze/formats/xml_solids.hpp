#pragma once
// The course's XML worlds as arenas (maze/world/geometry.hpp): the same file as a wall-segment maze
// (xml_format.hpp), read as solid obstacles in metres on no lattice.
//
//     <world>
//       <wall x1="-3" y1="-1" x2="-3" y2="3" width="1"/>    a Webots box centred on the
//       <wall x1="0" y1="-4" x2="2" y2="-2" width="0.5"/>   segment, `width` across it (default
//       <startPositions>                                    0.012 m) and exactly as long as
//         <pos x="-6" y="-6" theta="0.785"/>                the segment (WallEnds::flush), at
//       </startPositions>                                   any angle; each wall its own width
//       <goal id="0" x="6" y="6"/>
//     </world>
//
//   - Which reading: a file is an arena, not a grid maze, when it states no cellSize, no
//     --cell-size is given, and it has no <wall>, or a wall neither horizontal nor vertical, or
//     a wall at least a quarter as thick as the shortest wall is long (xml_world_is_arena).
//     Every other file is read as a maze, exactly as before.
//   - The boundary: <boundary xs="0" xe="5" ys="0" ye="3"/> (maze_mapper's own element, which
//     the course's tools ignore, as they ignore every element they do not know); without it
//     the loader gives the obstacles' bounding box when they enclose the start, else the
//     course's 17 x 17 m floor centred on the origin, unless the user gives one
//     (world.hpp).
//   - <world name="...">: the arena's name (maze_mapper's own attribute; else the file's name).
//   - <pos x y theta>: start poses (theta in radians, default pi/2, any angle); <goal x y>:
//     goal points; <landmark x y [height] [red green blue]/>: a solid cylinder of the course's
//     0.25 m radius (as in a maze's XML), written back as it was read; other elements are
//     ignored.

#include <string>
#include <string_view>
#include <vector>

#include "maze/world/geometry.hpp"
#include "maze/formats/xml_format.hpp"

namespace maze {

// Whether the XML world reads as an arena by the rule above. Throws common::InputError for a
// file that is not well-formed, or a wall with a bad number or width (the maze reader's words).
bool xml_world_is_arena(std::string_view text, const std::string &file, const XmlReadOptions &options);

struct XmlArenaRead {
  Arena arena;  // boundary empty (the loader's), not validated
  std::vector<std::string> warnings;  // whole lines, "FILE: warning: ..."
};
// Reads the XML world as an arena. Throws common::InputError at the faulty element.
XmlArenaRead read_xml_arena(std::string_view text, const std::string &file);

// The arena in the course's XML: the <boundary>, each obstacle one <wall> along its long axis
// with its width, the start poses, the goals; lengths to 12 significant digits, theta exact.
// Read back: the same arena.
std::string write_xml_arena(const Arena &arena);

}  // namespace maze
