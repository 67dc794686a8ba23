#pragma once
// How well a run mapped the maze, measured against the truth. Only the composition root
// holds both the true maze and the learned map, so this lives in app/, not in controller/.
//
//   coverage      = visited reachable cells / reachable cells, in %
//   wall_accuracy = sides of reachable cells whose learned state (wall or open) matches the
//                   truth / all such sides, in %; each side shared by two cells counts once,
//                   the outer boundary is included, and a side never observed counts as wrong.

#include <cstddef>
#include <functional>
#include <vector>

#include "maze/maze.hpp"

namespace app {

enum class LearnedSide { unknown, open, wall };

struct MapScore {
  std::size_t reachable_cells = 0;
  std::size_t visited_reachable_cells = 0;
  std::size_t sides = 0;
  std::size_t sides_correct = 0;
  std::size_t sides_contradicted = 0;  // learned wall or open, and the truth says the other

  double coverage_percent() const;
  double wall_accuracy_percent() const;
};

// What one scored side says about the map (truth.png draws each):
//   right           the learned state matches the truth (a wall, or an opening)
//   missed          a true wall the map lacks (learned open, or never observed)
//   phantom         a wall the map invented (learned wall, truly open)
//   unseen_opening  a true opening never observed (counts as wrong, as every unknown side)
enum class SideVerdict { right, missed, phantom, unseen_opening };
SideVerdict judge_side(bool true_wall, LearnedSide learned);

// Calls scored(cell, side) once for each side wall_accuracy counts: the sides of reachable
// cells, a side shared by two reachable cells once (as the south or west cell's north or
// east side). `reachable` is truth.reachable_from_start().
void for_each_scored_side(const maze::Maze &truth, const std::vector<bool> &reachable,
                          const std::function<void(maze::Cell, maze::Side)> &scored);

// visited[y * W + x] says whether the robot stood in cell (x, y); learned(cell, side) is the
// controller's belief about that side. Costs O(W * H).
MapScore score_map(const maze::Maze &truth, const std::vector<bool> &visited,
                   const std::function<LearnedSide(maze::Cell, maze::Side)> &learned);

}  // namespace app
