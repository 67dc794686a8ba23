#include "explore/shortest_path.hpp"

#include <cassert>
#include <cstddef>
#include <cstdint>

namespace explore {

using mapping::Cell;
using mapping::Heading;
using mapping::SideState;

namespace {

bool inside(MazeSize size, Cell c) { return c.x >= 0 && c.y >= 0 && c.x < size.width_cells && c.y < size.height_cells; }

std::size_t flat(MazeSize size, Cell c) {
  return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(size.width_cells) + static_cast<std::size_t>(c.x);
}

bool passable(MazeSize size, const WallQuery &walls, Cell c, Heading h, UnknownSides unknown) {
  if (!inside(size, mapping::neighbour(c, h))) return false;
  const SideState s = walls(c, h);
  return s == SideState::open || (s == SideState::unknown && unknown == UnknownSides::open);
}

constexpr std::int32_t kUnreached = -1;

// Moves from every cell to the nearest of `to` (kUnreached where none is reachable).
std::vector<std::int32_t> distances_to(MazeSize size, const std::vector<Cell> &to, const WallQuery &walls,
                                       UnknownSides unknown) {
  std::vector<std::int32_t> distance(flat(size, {0, size.height_cells}), kUnreached);
  std::vector<Cell> queue;
  queue.reserve(distance.size());
  for (const Cell g : to) {
    assert(inside(size, g));
    if (distance[flat(size, g)] != kUnreached) continue;
    distance[flat(size, g)] = 0;
    queue.push_back(g);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const Cell u = queue[head];
    for (const Heading h : mapping::kHeadings) {
      // Sides are read from the cell the path leaves: v -> u crosses v's side opposite(h).
      const Cell v = mapping::neighbour(u, h);
      if (!inside(size, v) || distance[flat(size, v)] != kUnreached) continue;
      if (!passable(size, walls, v, mapping::opposite(h), unknown)) continue;
      distance[flat(size, v)] = distance[flat(size, u)] + 1;
      queue.push_back(v);
    }
  }
  return distance;
}

}  // namespace

std::optional<std::vector<Heading>> shortest_route(MazeSize size, Cell from, const std::vector<Cell> &to,
                                                   const WallQuery &walls, UnknownSides unknown, Heading facing) {
  assert(inside(size, from));
  const std::vector<std::int32_t> distance = distances_to(size, to, walls, unknown);
  if (distance[flat(size, from)] == kUnreached) return std::nullopt;
  std::vector<Heading> route;
  Cell c = from;
  Heading ahead = facing;
  while (distance[flat(size, c)] > 0) {
    const std::int32_t want = distance[flat(size, c)] - 1;
    const Heading order[] = {ahead, Heading::north, Heading::east, Heading::south, Heading::west};
    [[maybe_unused]] const Cell was = c;
    for (const Heading h : order) {
      const Cell n = mapping::neighbour(c, h);
      if (passable(size, walls, c, h, unknown) && distance[flat(size, n)] == want) {
        route.push_back(h);
        c = n;
        ahead = h;
        break;
      }
    }
    assert(c != was && "a reached cell always has a neighbour one move nearer");
  }
  return route;
}

std::optional<int> shortest_moves(MazeSize size, Cell from, const std::vector<Cell> &to, const WallQuery &walls,
                                  UnknownSides unknown) {
  const std::int32_t d = distances_to(size, to, walls, unknown)[flat(size, from)];
  if (d == kUnreached) return std::nullopt;
  return d;
}

ShortestPathProof prove_shortest_path(const ExplorerOptions &maze, const WallQuery &walls) {
  const MazeSize size{maze.width_cells, maze.height_cells};
  return ShortestPathProof{shortest_moves(size, maze.start, maze.goals, walls, UnknownSides::closed),
                           shortest_moves(size, maze.start, maze.goals, walls, UnknownSides::open)};
}

int turns(const std::vector<Heading> &route) {
  int n = 0;
  for (std::size_t i = 1; i < route.size(); ++i) n += route[i] != route[i - 1] ? 1 : 0;
  return n;
}

}  // namespace explore
