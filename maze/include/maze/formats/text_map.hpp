#pragma once
// The micromouse text map: the format of the public micromouse maze collections and of the
// mms simulator. A W x H maze is 2H + 1 lines of 4W + 1 characters, north edge first:
//
//     o---o---o---o      <- post line: a post 'o' (or '+') at every corner, and between
//     | G     |   |         two posts '---' for a wall or three blanks for an opening
//     o   o---o   o
//     |   |       |      <- cell line: '|' or one blank for each west/east side, and three
//     o   o   o---o         characters per cell centre: blanks, 'S' (start) or 'G' (goal)
//     | S         |
//     o---o---o---o      this is a 3 x 3 maze; (0,0) is the south-west cell, with the S
//
//   - The start faces north; without an 'S' it is the south-west cell, facing north.
//   - Reading stops at the first line that starts with neither 'o'/'+' nor '|'/blank, so
//     notes may follow the maze. CRLF line ends and a UTF-8 byte-order mark are accepted.
//   - Columns in messages count bytes from 1, as compilers do.
//
// The canonical form (what write_text_map gives) uses 'o', '---', '|', ' S ', ' G ' (' SG' for
// a start that is also a goal) and '\n'.

#include <string>
#include <string_view>

#include "maze/world/maze.hpp"

namespace maze {

// Reads a text map; `file` names it in messages. Throws common::InputError with the place of
// the first fault: unknown characters, ragged lines, partly drawn walls, size, enclosure.
Maze read_text_map(std::string_view text, const std::string &file);

// The canonical text map, every line ending in '\n'.
std::string write_text_map(const Maze &maze);

}  // namespace maze
