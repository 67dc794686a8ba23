#pragma once
// How the arena writers (room_format.cpp, xml_arena.cpp) write a length or a coordinate.

#include <string>

#include <fmt/format.h>

namespace maze {

// 12 significant digits (a picometre on a metre; the rounding of sums and halves in doubles
// left out), -0 as 0.
inline std::string metres_text(double v) { return fmt::format("{:.12g}", v + 0.0); }

}  // namespace maze
