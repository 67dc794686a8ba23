#pragma once
// The mms num format: one line per cell, six integers separated by blanks,
//
//     X Y N E S W        0 0 1 0 1 1      cell (0,0): walls north, south and west,
//                        0 1 0 1 1 1      cell (0,1): east, south and west; ...
//
// X is the column from the west, Y the row from the south, then 1 (wall) or 0 (opening) for
// the north, east, south and west sides. Every cell of the W x H rectangle appears exactly
// once, in any order; the size is the largest X and Y plus one. A wall between two cells is
// written twice (once for each cell) and the two must agree. Blank lines are skipped; CRLF
// line ends are accepted. The format has no start or goal: the start is (0,0) facing north.

#include <string>
#include <string_view>

#include "maze/world/maze.hpp"

namespace maze {

// Reads a num file; `file` names it in messages. Throws common::InputError with the place of
// the first fault: a malformed line, a value out of range, a cell listed twice or missing, an
// open edge, two cells that disagree about the wall between them.
Maze read_num(std::string_view text, const std::string &file);

// One line per cell, X from west to east and, within a column, Y from south to north.
std::string write_num(const Maze &maze);

}  // namespace maze
