#pragma once
// The true maze's shortest number of moves from a cell to the first cell `is_goal` accepts,
// by a breadth-first search of the maze itself (the tests' independent reference for the
// micromouse search); -1 when none is reachable.

#include <cstddef>
#include <vector>

#include "maze/world/maze.hpp"

namespace test_maze {

template <typename IsGoal>
int true_shortest_moves(const maze::Maze &m, maze::Cell from, IsGoal &&is_goal) {
  const auto flat = [&](maze::Cell c) { return static_cast<std::size_t>(c.y * m.width() + c.x); };
  std::vector<int> distance(static_cast<std::size_t>(m.width() * m.height()), -1);
  std::vector<maze::Cell> queue{from};
  distance[flat(from)] = 0;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const maze::Cell u = queue[head];
    if (is_goal(u)) return distance[flat(u)];
    for (const maze::Side s : maze::kSides) {
      if (m.has_wall(u, s)) continue;
      const maze::Cell v = maze::neighbour(u, s);
      if (distance[flat(v)] >= 0) continue;
      distance[flat(v)] = distance[flat(u)] + 1;
      queue.push_back(v);
    }
  }
  return -1;
}

}  // namespace test_maze
