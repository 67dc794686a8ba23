#pragma once
// The room format: an arena (maze/world/geometry.hpp) as plain lines, one statement a line, numbers in
// metres, `#` to the end of a line a comment:
//
//     # the IR room                                     y
//     name IR room                                    3 +-----------------------------+
//     boundary 0 5 0 3        # XS XE YS YE             |                          G  |
//     rect 1.5 1.0 2.0 2.2    # X0 Y0 X1 Y1             |      ##                     |
//     wall 3 0 3 1.2 0.1      # X1 Y1 X2 Y2 [WIDTH]     |      ##     #               |
//     start 0.3 0.3 0         # X Y [YAW_DEG]           |  S   ##     #               |
//     goal 4.7 2.7            # X Y                   0 +-----------------------------+ x
//                                                       0                             5
//
//   - boundary XS XE YS YE: the floor, walled all round, in the homework's order; at most one.
//     Without it: the obstacles' bounding box when they enclose the start, else the course's
//     17 x 17 m floor centred on the origin (world.hpp, apply_default_boundary).
//   - rect X0 Y0 X1 Y1: an axis-aligned solid rectangle, corners in any order, of positive area.
//   - wall X1 Y1 X2 Y2 [WIDTH]: a solid rectangle centred on the segment, WIDTH thick (default
//     0.012 m, the course's) and exactly as long as the segment, as the course's XML walls are
//     (WallEnds::flush); at any angle.
//   - start X Y [YAW_DEG]: a start pose, yaw in degrees from east, counter-clockwise (default
//     90: north); the first is the start. goal X Y: a goal point. name TEXT: the arena's name.
//   - Keywords are lower case; blanks are spaces or tabs; CRLF line ends and a UTF-8 byte-order
//     mark are accepted. Errors name the line and the column of the token at fault.
//
// Detected by content: after blank and comment lines, the first word is one of the keywords.

#include <string>
#include <string_view>

#include "maze/world/geometry.hpp"

namespace maze {

// The statements' keywords: a room file's first statement starts with one (format_detector.hpp).
inline constexpr std::string_view kRoomKeywords[] = {"name", "boundary", "rect", "wall", "start", "goal"};

// Reads a room file; `file` names it in messages. Throws common::InputError with the place
// of the first fault. The arena is not validated (validate_arena) and, without a boundary
// line, has an empty one (x_min_m == x_max_m == 0) for the loader to fill.
Arena read_room(std::string_view text, const std::string &file);

// The canonical room file: name, boundary, each obstacle (`rect` when axis-aligned, else
// `wall` along its long axis with its width), starts, goals; lengths to 12 significant digits
// (the last bits of sums and halves left out), a wall's ends to the 12th digit of its largest
// coordinate (an end at 0 is written 0, not 1.9e-15), yaws in the fewest degrees' digits that
// read back exactly. Read back: the same arena, which writes the same text again.
std::string write_room(const Arena &arena);

}  // namespace maze
