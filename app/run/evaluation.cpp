#include "app/run/evaluation.hpp"

#include <algorithm>
#include <cassert>

namespace app {
namespace {

double percent(std::size_t part, std::size_t whole) {
  return whole == 0 ? 100.0 : 100.0 * static_cast<double>(part) / static_cast<double>(whole);
}

}  // namespace

double MapScore::coverage_percent() const { return percent(visited_reachable_cells, reachable_cells); }
double MapScore::wall_accuracy_percent() const { return percent(sides_correct, sides); }

SideVerdict judge_side(bool true_wall, LearnedSide learned) {
  if (learned == (true_wall ? LearnedSide::wall : LearnedSide::open)) return SideVerdict::right;
  if (true_wall) return SideVerdict::missed;
  return learned == LearnedSide::wall ? SideVerdict::phantom : SideVerdict::unseen_opening;
}

void for_each_scored_side_in_row(const maze::Maze &truth, const std::vector<bool> &reachable, int y,
                                 const std::function<void(maze::Cell, maze::Side)> &scored) {
  const auto w = static_cast<std::size_t>(truth.width());
  auto at = [w](maze::Cell c) { return static_cast<std::size_t>(c.y) * w + static_cast<std::size_t>(c.x); };
  auto is_reachable = [&](maze::Cell c) { return truth.contains(c) && reachable[at(c)]; };
  for (int x = 0; x < truth.width(); ++x) {
    const maze::Cell c{x, y};
    if (!reachable[at(c)]) continue;
    for (const maze::Side s : maze::kSides) {
      // A side shared with another reachable cell is counted by the cell to its south or
      // west, i.e. as that cell's north or east side.
      const bool counted_by_neighbour =
          (s == maze::Side::south || s == maze::Side::west) && is_reachable(maze::neighbour(c, s));
      if (!counted_by_neighbour) scored(c, s);
    }
  }
}

void for_each_scored_side(const maze::Maze &truth, const std::vector<bool> &reachable,
                          const std::function<void(maze::Cell, maze::Side)> &scored) {
  for (int y = 0; y < truth.height(); ++y) for_each_scored_side_in_row(truth, reachable, y, scored);
}

int count_reachable_cells(const maze::Maze &truth) {
  const std::vector<bool> reachable = truth.reachable_from_start();
  return static_cast<int>(std::count(reachable.begin(), reachable.end(), true));
}

MapScore score_map(const maze::Maze &truth, const std::vector<bool> &visited,
                   const std::function<LearnedSide(maze::Cell, maze::Side)> &learned) {
  assert(visited.size() == static_cast<std::size_t>(truth.width()) * static_cast<std::size_t>(truth.height()));
  const std::vector<bool> reachable = truth.reachable_from_start();
  MapScore score;
  for (std::size_t i = 0; i < reachable.size(); ++i) {
    if (!reachable[i]) continue;
    ++score.reachable_cells;
    if (visited[i]) ++score.visited_reachable_cells;
  }
  for_each_scored_side(truth, reachable, [&](maze::Cell c, maze::Side s) {
    ++score.sides;
    if (judge_side(truth.has_wall(c, s), learned(c, s)) == SideVerdict::right) ++score.sides_correct;
  });
  return score;
}

WrongSides wrong_sides_where_looked(const maze::Maze &truth, const std::vector<bool> &looked,
                                    const std::function<LearnedSide(maze::Cell, maze::Side)> &learned) {
  assert(looked.size() == static_cast<std::size_t>(truth.width()) * static_cast<std::size_t>(truth.height()));
  const auto w = static_cast<std::size_t>(truth.width());
  const auto looked_in = [&](maze::Cell c) {
    return truth.contains(c) && looked[static_cast<std::size_t>(c.y) * w + static_cast<std::size_t>(c.x)];
  };
  WrongSides wrong;
  for_each_scored_side(truth, truth.reachable_from_start(), [&](maze::Cell c, maze::Side s) {
    if (!looked_in(c) && !looked_in(maze::neighbour(c, s))) return;
    const SideVerdict verdict = judge_side(truth.has_wall(c, s), learned(c, s));
    if (verdict == SideVerdict::right) return;
    ++wrong.count;
    if (wrong.first.size() < 3) wrong.first.push_back({c, s, verdict});
  });
  return wrong;
}

std::vector<bool> visited_cells(const explore::Visits &visits) {
  std::vector<bool> visited(static_cast<std::size_t>(visits.width()) * static_cast<std::size_t>(visits.height()));
  for (int y = 0; y < visits.height(); ++y) {
    for (int x = 0; x < visits.width(); ++x) {
      visited[static_cast<std::size_t>(y) * static_cast<std::size_t>(visits.width()) + static_cast<std::size_t>(x)] =
          visits.visited({x, y});
    }
  }
  return visited;
}

}  // namespace app
