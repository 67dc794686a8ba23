#pragma once
// Shortest cell-to-cell paths over what the robot knows of the walls, and the micromouse's
// proof that the known path is the shortest one.
//
// A path moves between adjacent cells through sides that are open; a side leading out of
// the W x H grid is always a wall. An unknown side counts as open or closed as asked:
//
//   optimistic  (UnknownSides::open)   no path through the unknown can be shorter than this
//   known       (UnknownSides::closed) a path the robot can drive now, on what it has seen
//
// The known path is provably a shortest path of the true maze when it exists and is no
// longer than the optimistic one: whatever the unknown sides turn out to be, no path is
// shorter. Cost: one breadth-first search, O(W * H), per call.

#include <optional>
#include <vector>

#include "explore/strategies.hpp"
#include "mapping/grid_types.hpp"

namespace explore {

enum class UnknownSides { open, closed };

struct MazeSize {
  int width_cells = 0;
  int height_cells = 0;
};

// The headings of a shortest path from `from` to the nearest of `to` (all inside the
// grid), first move first; empty when `from` is one of them; nothing when none is
// reachable. Of the shortest paths it takes, cell by cell, the move straight on first
// (starting `facing`), then N, E, S, W: fewer turns, the same for the same walls.
std::optional<std::vector<mapping::Heading>> shortest_route(MazeSize size, mapping::Cell from,
                                                            const std::vector<mapping::Cell> &to,
                                                            const WallQuery &walls, UnknownSides unknown,
                                                            mapping::Heading facing = mapping::Heading::north);

// Moves of a shortest path, as shortest_route; nothing when none.
std::optional<int> shortest_moves(MazeSize size, mapping::Cell from, const std::vector<mapping::Cell> &to,
                                  const WallQuery &walls, UnknownSides unknown);

// From the start to the nearest goal: the known shortest path's moves, the optimistic one's,
// and whether the known one is proven shortest (it exists and is no longer).
struct ShortestPathProof {
  std::optional<int> known_moves;
  std::optional<int> optimistic_moves;
  bool proven() const { return known_moves && optimistic_moves && *known_moves <= *optimistic_moves; }
};
ShortestPathProof prove_shortest_path(const ExplorerOptions &maze, const WallQuery &walls);

// Changes of heading between consecutive moves (the way the robot faces before the first
// move is not counted): 0 for a straight path.
int turns(const std::vector<mapping::Heading> &route);

}  // namespace explore
