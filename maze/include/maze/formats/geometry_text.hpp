#pragma once
// An arena drawn as text for `show`: its truth on a grid of square cells (truth_raster.hpp,
// occupied by any overlap), north up, two characters a cell so the drawing keeps its shape
// in a terminal:
//
//     IR room (5 x 3 m): x 0 to 5 m, y 0 to 3 m; 10 x 6 cells of 0.5 m, north up
//     +--------------------+
//     |    ####        G   |      ## solid   (blank) free
//     |    ####            |      S  the start's cell
//     |  ##        ######  |      G  a goal's cell
//     |S ##                |      the frame is the boundary
//     +--------------------+

#include <string>

#include "maze/world/geometry.hpp"

namespace maze {

// The default resolution: the finest of 0.05, 0.1, 0.2, 0.25, 0.5, 1, 2, 5, 10, 20, 50 m that
// draws the boundary's longer side in at most 60 cells (100 m for larger arenas).
double default_arena_resolution_m(const Arena &arena);

// The drawing above at resolution_m (> 0): the boundary's sides in cells_along(side,
// resolution) cells each. Throws common::InputError when resolution_m is not a positive
// number or the drawing would exceed 2000 cells a side.
std::string draw_arena(const Arena &arena, double resolution_m);

}  // namespace maze
