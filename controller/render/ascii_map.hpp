#pragma once
// The map as text (docs/output.md): H*K lines of W*K characters, north at the top, one character
// a sub-cell (the classroom look), each line ending in '\n'; with subcell_columns 2, each
// sub-cell is two columns, so that the maze has its true aspect in a terminal (W, *, the
// unknown character and blanks doubled; an arrow or the robot followed by a blank):
//   *         a sub-cell of a planned path, when one is given (over everything else)
//   an arrow  at the centre of a visited cell: the last heading the robot had there
//             (↑ → ↓ ←, or ^ > v < with ascii)
//   W         an observed sub-cell whose log-odds is above 0 (more likely occupied), or
//             at least the --threshold when one is given
//   unknown   a never-observed sub-cell (value still the initial l(prior)), when asked
//   ' '       anything else (free, or never observed without an unknown character)
// A never-observed sub-cell is never drawn as W, even when the prior is above 0.5.

#include <optional>
#include <string>
#include <vector>

#include "explore/visits.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"

namespace render {

// The robot drawn over the map at a sub-cell (instead of what is there).
struct RobotMark {
  mapping::SubCell at;
  const char *glyph = "@";       // one column wide (UTF-8 allowed)
};

struct MapStyle {
  bool ascii = false;            // --ascii: ^ > v < instead of ↑ → ↓ ←
  std::optional<char> unknown;   // --unknown CHAR
  float initial_log_odds = 0.0f; // the grid's initial value, to tell never-observed sub-cells
  // ANSI colours (a terminal): W bold blue, never-observed sub-cells on a dark grey
  // background, arrows green, the robot bold red. Off: plain text, as in the golden files.
  bool color = false;
  std::optional<RobotMark> robot;
  std::optional<float> threshold;  // --threshold: W when log-odds >= this (default: > 0)
  const std::vector<bool> *path = nullptr;  // per flat grid index: '*' (a planned path)
  int subcell_columns = 1;       // 1 (the classroom look, the golden files) or 2 (true aspect)
};

// The part of the map drawn: sub-cell rows and columns counted from the north-west corner
// (a column is a sub-cell, whatever subcell_columns).
struct MapWindow {
  int first_row = 0;
  int row_count = 0;
  int first_col = 0;
  int col_count = 0;
};

// The window of at most rows x cols sub-cells that keeps sub-cell `at` in its middle, moved
// back inside the map at its edges; the whole map where it fits.
MapWindow window_around(const mapping::OccupancyGrid &grid, mapping::SubCell at, int rows, int cols);

// Appends the window's rows, each ending in '\n'; the window must lie within the map
// (H*K rows, W*K columns). Cost: row_count * col_count.
void render_window(std::string &out, const mapping::OccupancyGrid &grid,
                   const explore::Visits &visits, const MapStyle &style, const MapWindow &window);

// Appends sub-cell rows [first_row, first_row + row_count) counted from the top (north) line
// of the map; the range must lie within 0 ... H*K. Cost: row_count * W * K.
void render_rows(std::string &out, const mapping::OccupancyGrid &grid, const explore::Visits &visits,
                 const MapStyle &style, int first_row, int row_count);

// The whole map (all H*K lines).
std::string render_map(const mapping::OccupancyGrid &grid, const explore::Visits &visits,
                       const MapStyle &style);

// One cell's K x K log-odds, north row first: each value signed with 2 decimals, right-aligned
// to the widest value in the matrix, separated by one space, each row ending in '\n':
//   +0.41 +0.41 +0.41
//   +0.41 -0.85 -0.85
//   +0.41 -0.85 +0.00
// A value that rounds to zero prints as +0.00.
std::string format_cell_matrix(const mapping::OccupancyGrid &grid, mapping::Cell c);

// "step 412  cell (2,3)  heading N  visited 7/16" (no newline).
std::string format_status(long step, mapping::Cell c, mapping::Heading h, int visited, int total);

// The arrow for a heading: "↑" "→" "↓" "←", or "^" ">" "v" "<" with ascii.
const char *arrow(mapping::Heading h, bool ascii);

}  // namespace render
