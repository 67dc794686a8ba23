#include "app/evaluation.hpp"

#include <cassert>

namespace app {
namespace {

double percent(std::size_t part, std::size_t whole) {
  return whole == 0 ? 100.0 : 100.0 * static_cast<double>(part) / static_cast<double>(whole);
}

}  // namespace

double MapScore::coverage_percent() const { return percent(visited_reachable_cells, reachable_cells); }
double MapScore::wall_accuracy_percent() const { return percent(sides_correct, sides); }

MapScore score_map(const maze::Maze &truth, const std::vector<bool> &visited,
                   const std::function<LearnedSide(maze::Cell, maze::Side)> &learned) {
  const auto w = static_cast<std::size_t>(truth.width());
  assert(visited.size() == w * static_cast<std::size_t>(truth.height()));
  const std::vector<bool> reachable = truth.reachable_from_start();
  auto at = [w](maze::Cell c) { return static_cast<std::size_t>(c.y) * w + static_cast<std::size_t>(c.x); };
  auto is_reachable = [&](maze::Cell c) { return truth.contains(c) && reachable[at(c)]; };

  MapScore score;
  for (int y = 0; y < truth.height(); ++y) {
    for (int x = 0; x < truth.width(); ++x) {
      const maze::Cell c{x, y};
      if (!reachable[at(c)]) continue;
      ++score.reachable_cells;
      if (visited[at(c)]) ++score.visited_reachable_cells;
      for (const maze::Side s : maze::kSides) {
        // A side shared with another reachable cell is counted by the cell to its south or
        // west, i.e. as that cell's north or east side.
        const bool counted_by_neighbour =
            (s == maze::Side::south || s == maze::Side::west) && is_reachable(maze::neighbour(c, s));
        if (counted_by_neighbour) continue;
        ++score.sides;
        const LearnedSide belief = learned(c, s);
        const LearnedSide actual = truth.has_wall(c, s) ? LearnedSide::wall : LearnedSide::open;
        if (belief == actual) ++score.sides_correct;
      }
    }
  }
  return score;
}

}  // namespace app
