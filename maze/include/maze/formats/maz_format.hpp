#pragma once
// The binary maze format of micromouseonline's maze collection (its mazetool, 400+ classic
// mazes): exactly 256 bytes, one byte a cell of a 16 x 16 maze, four wall bits a byte,
//
//     bit 0x01 north   0x02 east   0x04 south   0x08 west       (0x0E: walls E, S and W)
//
// in columns: byte 0 is the start cell (0,0) in the south-west corner, byte 1 the cell
// north of it (0,1), byte 16 the cell east of it (1,0): byte x * 16 + y is cell (x, y). A
// wall between two cells is stored in both. The format has no start or goal: the start is
// (0,0) facing north and the goal the centre 2 x 2, the classic contest's.
//
// A message about byte i says where as FILE:1:(i + 1) (column = byte number, from 1).

#include <string>
#include <string_view>

#include "maze/world/maze.hpp"

namespace maze {

inline constexpr int kMazCells = 16;
inline constexpr std::size_t kMazBytes = 256;

// Throws common::InputError with the place of the first fault: a size other than 256 bytes,
// a byte with bits above 0x0F, an open edge, two cells that disagree about the wall between
// them.
Maze read_maz(std::string_view text, const std::string &file);

// The 256 bytes. Throws common::InputError for a maze that is not 16 x 16.
std::string write_maz(const Maze &maze);

}  // namespace maze
