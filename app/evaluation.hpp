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

  double coverage_percent() const;
  double wall_accuracy_percent() const;
};

// visited[y * W + x] says whether the robot stood in cell (x, y); learned(cell, side) is the
// controller's belief about that side. Costs O(W * H).
MapScore score_map(const maze::Maze &truth, const std::vector<bool> &visited,
                   const std::function<LearnedSide(maze::Cell, maze::Side)> &learned);

}  // namespace app
