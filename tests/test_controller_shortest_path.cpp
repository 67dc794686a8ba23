// explore/shortest_path.hpp on hand-made wall tables, and the floodfill search that ends when
// the known path is proven shortest, against a breadth-first search of the truth.
#include <doctest/doctest.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "true_shortest.hpp"
#include "explore/shortest_path.hpp"
#include "explore/strategies.hpp"
#include "maze/generate/generator.hpp"
#include "maze/world/maze.hpp"
#include "synthetic_world.hpp"

using explore::ShortestPathProof;
using explore::UnknownSides;
using mapping::Cell;
using mapping::Heading;
using mapping::SideState;

namespace {

// A wall table as the robot knows it: a text map where '-' or '|' is a wall, a blank an
// opening and '?' a side never seen.
struct KnownWalls {
  testing_world::TextMaze map;
  explicit KnownWalls(std::string_view drawing) : map(drawing) {}

  SideState operator()(Cell c, Heading h) const {
    const int row = 2 * (map.height - 1 - c.y) + 1;
    const int col = 4 * c.x + 2;
    const int r = row + (h == Heading::north ? -1 : h == Heading::south ? 1 : 0);
    const int k = col + (h == Heading::east ? 2 : h == Heading::west ? -2 : 0);
    const char ch = map.lines[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)];
    return ch == '?' ? SideState::unknown : ch == ' ' ? SideState::open : SideState::wall;
  }
  explore::ExplorerOptions maze(Cell start, std::vector<Cell> goals) const {
    return {explore::StrategyKind::floodfill, map.width, map.height, start, std::move(goals)};
  }
};

ShortestPathProof proof_of(const KnownWalls &k, Cell start, std::vector<Cell> goals) {
  return explore::prove_shortest_path(k.maze(start, std::move(goals)), k);
}

}  // namespace

TEST_CASE("proof: all sides known - the known path is the shortest") {
  const KnownWalls walls(
      "o---o---o---o\n"
      "|       |   |\n"
      "o   o---o   o\n"
      "|   |       |\n"
      "o   o   o---o\n"
      "|       |   |\n"
      "o---o---o---o");
  const ShortestPathProof p = proof_of(walls, {0, 0}, {{2, 2}});
  CHECK(p.known_moves == 4);
  CHECK(p.optimistic_moves == 4);
  CHECK(p.proven());
}

TEST_CASE("proof: an unknown side could open a shorter way - not proven; closed, proven") {
  // Known: round the east side, 5 moves; the unknown side under (1,2) may cut it to 3.
  const KnownWalls maybe_shorter(
      "o---o---o---o\n"
      "|           |\n"
      "o---o???o   o\n"
      "|       |   |\n"
      "o   o---o   o\n"
      "|           |\n"
      "o---o---o---o");
  const ShortestPathProof open = proof_of(maybe_shorter, {0, 0}, {{1, 2}});
  CHECK(open.known_moves == 5);
  CHECK(open.optimistic_moves == 3);
  CHECK_FALSE(open.proven());
  // The same side seen to be a wall: the long way is the shortest there is.
  const KnownWalls seen(
      "o---o---o---o\n"
      "|           |\n"
      "o---o---o   o\n"
      "|       |   |\n"
      "o   o---o   o\n"
      "|           |\n"
      "o---o---o---o");
  const ShortestPathProof closed = proof_of(seen, {0, 0}, {{1, 2}});
  CHECK(closed.known_moves == 5);
  CHECK(closed.optimistic_moves == 5);
  CHECK(closed.proven());
}

TEST_CASE("proof: unknown sides that cannot shorten the path leave it proven") {
  // The unknown sides lie off every path shorter than the known 2 moves.
  const KnownWalls walls(
      "o---o---o---o\n"
      "|   ?   ?   |\n"
      "o???o???o???o\n"
      "|       |   |\n"
      "o---o   o---o\n"
      "|   |   |   |\n"
      "o---o---o---o");
  const ShortestPathProof p = proof_of(walls, {0, 1}, {{1, 0}});
  CHECK(p.known_moves == 2);
  CHECK(p.optimistic_moves == 2);
  CHECK(p.proven());
}

TEST_CASE("proof: no known path - not proven; no path at all - neither") {
  const KnownWalls unknown(
      "o---o---o\n"
      "|   ?   |\n"
      "o---o---o");
  const ShortestPathProof p = proof_of(unknown, {0, 0}, {{1, 0}});
  CHECK(p.known_moves == std::nullopt);
  CHECK(p.optimistic_moves == 1);
  CHECK_FALSE(p.proven());
  const KnownWalls walled(
      "o---o---o\n"
      "|   |   |\n"
      "o---o---o");
  CHECK(proof_of(walled, {0, 0}, {{1, 0}}).optimistic_moves == std::nullopt);
  CHECK_FALSE(proof_of(walled, {0, 0}, {{1, 0}}).proven());
  // The start on a goal: 0 moves, proven.
  CHECK(proof_of(walled, {0, 0}, {{0, 0}}).proven());
}

TEST_CASE("shortest_route: straight on first, then N, E, S, W; turns") {
  const KnownWalls open(
      "o---o---o---o\n"
      "|           |\n"
      "o   o   o   o\n"
      "|           |\n"
      "o   o   o   o\n"
      "|           |\n"
      "o---o---o---o");
  const explore::MazeSize size{3, 3};
  using H = std::vector<Heading>;
  // Facing east, the route keeps east while a shortest path allows it: one turn.
  CHECK(explore::shortest_route(size, {0, 0}, {{2, 2}}, open, UnknownSides::closed, Heading::east) ==
        H{Heading::east, Heading::east, Heading::north, Heading::north});
  CHECK(explore::shortest_route(size, {0, 0}, {{2, 2}}, open, UnknownSides::closed, Heading::north) ==
        H{Heading::north, Heading::north, Heading::east, Heading::east});
  CHECK(explore::shortest_route(size, {1, 1}, {{1, 1}}, open, UnknownSides::closed) == H{});
  CHECK(explore::turns(H{Heading::east, Heading::east, Heading::north, Heading::north}) == 1);
  CHECK(explore::turns(H{Heading::north, Heading::east, Heading::north, Heading::east}) == 3);
  CHECK(explore::turns(H{}) == 0);
}

namespace {

// The true maze's shortest moves from `from` to `goal` (tests/true_shortest.hpp).
int true_shortest(const maze::Maze &m, maze::Cell from, maze::Cell goal) {
  return test_maze::true_shortest_moves(m, from, [&](maze::Cell c) { return c.x == goal.x && c.y == goal.y; });
}

}  // namespace

TEST_CASE("floodfill searches until the known path is the true shortest, with loops and without") {
  for (const int size : {8, 16, 32}) {
    for (const double loops : {0.0, 0.1, 0.5}) {
      for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        CAPTURE(size);
        CAPTURE(loops);
        CAPTURE(seed);
        maze::GeneratorOptions g;
        g.width = size;
        g.height = size;
        g.seed = seed;
        g.loops = loops;
        const maze::Maze m = maze::generate_maze(g);
        const Cell goal{size / 2, size / 2};
        // The robot knows the sides of the cells it has stood in.
        std::vector<char> stood(static_cast<std::size_t>(size * size), 0);
        const auto flat = [&](Cell c) { return static_cast<std::size_t>(c.y * size + c.x); };
        const explore::WallQuery walls = [&](Cell c, Heading h) {
          const Cell n = mapping::neighbour(c, h);
          const bool inside = n.x >= 0 && n.y >= 0 && n.x < size && n.y < size;
          if (stood[flat(c)] == 0 && !(inside && stood[flat(n)] != 0)) return SideState::unknown;
          return m.has_wall({c.x, c.y}, static_cast<maze::Side>(h)) ? SideState::wall : SideState::open;
        };
        const explore::ExplorerOptions options{explore::StrategyKind::floodfill, size, size, {0, 0}, {goal}};
        explore::Explorer explorer(options);
        Cell c{0, 0};
        Heading heading = Heading::north;
        for (int moves = 0;; ++moves) {
          REQUIRE(moves < 20 * size * size);
          stood[flat(c)] = 1;
          const auto next = explorer.next(c, heading, walls);
          if (!next) break;
          REQUIRE(walls(c, *next) != SideState::wall);
          heading = *next;
          c = mapping::neighbour(c, heading);
        }
        CHECK(explorer.reached_goal());
        CHECK(explorer.proven());
        const ShortestPathProof p = explore::prove_shortest_path(options, walls);
        CHECK(p.proven());
        CHECK(p.known_moves == true_shortest(m, {0, 0}, {goal.x, goal.y}));
      }
    }
  }
}
