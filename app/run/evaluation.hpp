#pragma once
// How well a run mapped the maze, measured against the truth. Only the composition root
// holds both the true maze and the learned map, so this lives in app/, not in controller/.
//
//   coverage      = visited reachable cells / reachable cells, in %
//   wall_accuracy = sides of reachable cells whose learned state (wall or open) matches the
//                   truth / all such sides, in %; each side shared by two cells counts once,
//                   the outer boundary is included, and a side never observed counts as wrong.
//   wrong sides where it looked = those wrong sides that belong to a cell the robot stood in
//                   and scanned (wrong_sides_where_looked).

#include <cstddef>
#include <functional>
#include <vector>

#include "explore/visits.hpp"
#include "mapping/walls.hpp"
#include "maze/world/maze.hpp"

namespace app {

// What the map says of a side: the robot side's own state (mapping/walls.hpp), one enum for both.
using LearnedSide = mapping::SideState;

// What one scored side says about the map (truth.png draws each):
//   right           the learned state matches the truth (a wall, or an opening)
//   missed          a true wall the map lacks (learned open, or never observed)
//   phantom         a wall the map invented (learned wall, truly open)
//   unseen_opening  a true opening never observed (counts as wrong, as every unknown side)
enum class SideVerdict { right, missed, phantom, unseen_opening };

// A side the map got wrong, for the summary to name.
struct WrongSide {
  maze::Cell cell;
  maze::Side side;
  SideVerdict verdict;
};

struct MapScore {
  std::size_t reachable_cells = 0;
  std::size_t visited_reachable_cells = 0;
  std::size_t sides = 0;
  std::size_t sides_correct = 0;

  double coverage_percent() const;
  double wall_accuracy_percent() const;
};

SideVerdict judge_side(bool true_wall, LearnedSide learned);

// Calls scored(cell, side) once for each side wall_accuracy counts: the sides of reachable
// cells, a side shared by two reachable cells once (as the south or west cell's north or
// east side). `reachable` is truth.reachable_from_start().
void for_each_scored_side(const maze::Maze &truth, const std::vector<bool> &reachable,
                          const std::function<void(maze::Cell, maze::Side)> &scored);
// The same for the cells of row y alone (south to north, the rows together give every side
// once, in for_each_scored_side's order).
void for_each_scored_side_in_row(const maze::Maze &truth, const std::vector<bool> &reachable, int y,
                                 const std::function<void(maze::Cell, maze::Side)> &scored);

// The scored sides that are not right (unknown included) of the cells looked[y * W + x] marks,
// either cell of a shared side: a run may leave cells unvisited by design, never a wrong side
// where it stood and looked. Counted, and the first three in scan order named.
struct WrongSides {
  std::size_t count = 0;
  std::vector<WrongSide> first;
};
WrongSides wrong_sides_where_looked(const maze::Maze &truth, const std::vector<bool> &looked,
                                    const std::function<LearnedSide(maze::Cell, maze::Side)> &learned);

// The cells reachable from the start: the most a run can visit, coverage's denominator.
int count_reachable_cells(const maze::Maze &truth);

// visited[y * W + x] says whether the robot stood in cell (x, y); learned(cell, side) is the
// controller's belief about that side. Costs O(W * H).
MapScore score_map(const maze::Maze &truth, const std::vector<bool> &visited,
                   const std::function<LearnedSide(maze::Cell, maze::Side)> &learned);

// visited[y * W + x]: whether the robot stood in cell (x, y), as score_map() takes it.
std::vector<bool> visited_cells(const explore::Visits &visits);

}  // namespace app
