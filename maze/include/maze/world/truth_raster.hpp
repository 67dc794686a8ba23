#pragma once
// The truth of a world's geometry (World::geometry()) on a grid, for scoring a metric map of it
// and for the loader's boundary rule.
//
// The grid: cells_x x cells_y cells over the geometry's boundary, cell (x, y) column x from the
// west, row y from the south (the conventions), each (x_max - x_min) / cells_x by
// (y_max - y_min) / cells_y metres.
//   - occupied: a cell is occupied when an obstacle or a disc (a landmark's cylinder)
//     overlaps it with positive area (any overlap, not the cell's centre: a 0.012 m wall
//     marks the cells it crosses at any resolution); touching along an edge or at a corner
//     is no overlap. Else it is free.
//   - reachable: the free cells the robot's body can cover from the start. A cell is
//     traversable when it is free and its centre is at least robot_radius_m from every
//     obstacle, disc and the boundary; the start's cell is always traversable; the traversable
//     cells 4-connected to the start's cell are where the robot's centre can go; a free cell
//     is reachable when it is one of those, or when a walk over free cells (4-neighbours, so
//     never through a wall) joins it to one of those, every cell of the walk within the reach
//     of that one's centre: robot_radius_m plus half a cell's diagonal (the body of a centre
//     anywhere in the cell). With radius 0 and square cells: the free cells 4-connected to
//     the start's. The map's "observed share of the reachable free area" is over these cells.
//     With TruthClearance::to_occupied_cells the centre's clearance is measured to the
//     occupied cells' squares instead of the obstacles (common/cell_clearance.hpp; square
//     cells): the truth at the map's resolution, where a map can say no more than that an
//     obstacle lies somewhere in a cell, so the gaps it calls passable are those a robot
//     planning on a perfect map at that resolution can pass.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "maze/world/geometry.hpp"

namespace maze {

struct TruthRaster {
  int cells_x = 0;
  int cells_y = 0;
  double x_min_m = 0.0;
  double y_min_m = 0.0;
  double cell_x_m = 0.0;
  double cell_y_m = 0.0;
  std::vector<std::uint8_t> occupied;   // [y * cells_x + x]: 1 occupied, 0 free
  std::vector<std::uint8_t> reachable;  // [y * cells_x + x]: 1 reachable (and free)
  std::size_t occupied_count = 0;
  std::size_t free_count = 0;
  std::size_t reachable_count = 0;

  bool is_occupied(int x, int y) const { return occupied[index(x, y)] != 0; }
  bool is_reachable(int x, int y) const { return reachable[index(x, y)] != 0; }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(cells_x) + static_cast<std::size_t>(x);
  }
};

// How a centre's clearance of robot_radius_m is measured (see reachable above).
enum class TruthClearance { to_obstacles, to_occupied_cells };

// At most this many cells (64 Mi): a grid finer is refused.
inline constexpr std::size_t kMaxTruthCells = std::size_t{1} << 26;

// The arena (validated, with a boundary) on a cells_x x cells_y grid, as above, its start the
// arena's start(). O(cells + the cells each obstacle's bounding box covers). Throws
// common::InputError "a grid of 20000 x 20000 cells is too fine: at most 67108864 cells" when
// the grid is empty or too fine.
TruthRaster rasterise_truth(const Arena &arena, int cells_x, int cells_y, double robot_radius_m,
                           TruthClearance clearance = TruthClearance::to_obstacles);

// The number of cells of `cell_m` (> 0) along a side of `side_m`: round(side / cell), at least 1.
int cells_along(double side_m, double cell_m);

}  // namespace maze
