#include <doctest/doctest.h>

#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "common/random.hpp"
#include "explore/strategies.hpp"
#include "synthetic_world.hpp"

using explore::Explorer;
using explore::StrategyKind;
using mapping::Cell;
using mapping::Heading;
using mapping::SideState;

namespace {

// A tree of 8 cells plus the cell (2,0), walled in.
const char *const kSmall =
    "o---o---o---o\n"
    "|       |   |\n"
    "o   o---o   o\n"
    "|   |       |\n"
    "o   o   o---o\n"
    "|       |   |\n"
    "o---o---o---o";

// The truth, for the test only: any maze as W, H and a wall predicate.
struct Truth {
  int width = 0;
  int height = 0;
  std::function<bool(Cell, Heading)> wall;
};

Truth truth_of(const testing_world::TextMaze &m) {
  return {m.width, m.height, [&m](Cell c, Heading h) { return m.wall(c, h); }};
}

struct Outcome {
  std::vector<Cell> path;      // cells in order of arrival, start first
  std::vector<Cell> first_visits;
  Cell end;
  int moves = 0;
};

// Runs a strategy as the robot would: it knows the sides of the cells it has stood in
// (their scans), nothing else. Every move must go through a true opening.
Outcome explore_truth(const Truth &t, StrategyKind kind, Cell start, Heading heading,
                      std::vector<Cell> goals = {}, int max_moves = 100000) {
  Explorer explorer({kind, t.width, t.height, start, std::move(goals)});
  std::vector<char> scanned(static_cast<std::size_t>(t.width * t.height), 0);
  const auto flat = [&](Cell c) { return static_cast<std::size_t>(c.y * t.width + c.x); };
  const auto inside = [&](Cell c) { return c.x >= 0 && c.y >= 0 && c.x < t.width && c.y < t.height; };
  const explore::WallQuery walls = [&](Cell c, Heading h) {
    const Cell n = mapping::neighbour(c, h);
    const bool known = scanned[flat(c)] != 0 || (inside(n) && scanned[flat(n)] != 0);
    if (!known) return SideState::unknown;
    return t.wall(c, h) ? SideState::wall : SideState::open;
  };
  Outcome out;
  Cell c = start;
  out.path.push_back(c);
  for (;;) {
    if (scanned[flat(c)] == 0) out.first_visits.push_back(c);
    scanned[flat(c)] = 1;
    const auto next = explorer.next(c, heading, walls);
    if (!next) break;
    REQUIRE_FALSE(t.wall(c, *next));
    heading = *next;
    c = mapping::neighbour(c, heading);
    REQUIRE(inside(c));
    out.path.push_back(c);
    REQUIRE(++out.moves <= max_moves);
  }
  out.end = c;
  return out;
}

// A perfect maze (every cell reachable, one path between two cells) carved depth-first.
struct Generated {
  int width, height;
  std::vector<char> east, north;  // 1 = wall on the cell's east / north side
  bool wall(Cell c, Heading h) const {
    switch (h) {
      case Heading::east: return c.x == width - 1 || east[idx(c)] != 0;
      case Heading::north: return c.y == height - 1 || north[idx(c)] != 0;
      case Heading::west: return c.x == 0 || east[idx({c.x - 1, c.y})] != 0;
      case Heading::south: return c.y == 0 || north[idx({c.x, c.y - 1})] != 0;
    }
    return true;
  }
  std::size_t idx(Cell c) const { return static_cast<std::size_t>(c.y * width + c.x); }
};

Generated generate(int w, int h, std::uint64_t seed) {
  Generated g{w, h, std::vector<char>(static_cast<std::size_t>(w * h), 1),
              std::vector<char>(static_cast<std::size_t>(w * h), 1)};
  common::Rng rng(seed);
  std::vector<char> seen(static_cast<std::size_t>(w * h), 0);
  std::vector<Cell> stack{{0, 0}};
  seen.at(0) = 1;
  while (!stack.empty()) {
    const Cell c = stack.back();
    std::vector<Heading> options;
    for (const Heading d : mapping::kHeadings) {
      const Cell n = mapping::neighbour(c, d);
      if (n.x >= 0 && n.y >= 0 && n.x < w && n.y < h && seen[g.idx(n)] == 0) options.push_back(d);
    }
    if (options.empty()) {
      stack.pop_back();
      continue;
    }
    const Heading d = options[rng.below(options.size())];
    const Cell n = mapping::neighbour(c, d);
    if (d == Heading::east) g.east[g.idx(c)] = 0;
    if (d == Heading::west) g.east[g.idx(n)] = 0;
    if (d == Heading::north) g.north[g.idx(c)] = 0;
    if (d == Heading::south) g.north[g.idx(n)] = 0;
    seen[g.idx(n)] = 1;
    stack.push_back(n);
  }
  return g;
}

Truth truth_of(const Generated &g) {
  return {g.width, g.height, [&g](Cell c, Heading h) { return g.wall(c, h); }};
}

using Cells = std::vector<Cell>;

}  // namespace

TEST_CASE("dfs: ahead, right, left, back; backtracks; ends when nothing reachable is left") {
  const testing_world::TextMaze maze(kSmall);
  const Outcome o = explore_truth(truth_of(maze), StrategyKind::dfs, {0, 0}, Heading::north);
  CHECK(o.first_visits == Cells{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {1, 0}, {1, 1}, {2, 1}, {2, 2}});
  CHECK(o.path == Cells{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {0, 2}, {0, 1}, {0, 0}, {1, 0}, {1, 1},
                        {2, 1}, {2, 2}});
}

TEST_CASE("frontier: nearest unvisited cell through known openings; ends with all reachable visited") {
  const testing_world::TextMaze maze(kSmall);
  const Outcome o = explore_truth(truth_of(maze), StrategyKind::frontier, {0, 0}, Heading::north);
  CHECK(o.first_visits.size() == 8);  // (2,0) is walled in
  CHECK(o.path == Cells{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {0, 2}, {0, 1}, {0, 0}, {1, 0}, {1, 1},
                        {2, 1}, {2, 2}});
  // From the middle of a corridor it goes to the nearer end first.
  const Outcome mid = explore_truth(truth_of(maze), StrategyKind::frontier, {1, 1}, Heading::north);
  CHECK(mid.first_visits == Cells{{1, 1}, {2, 1}, {2, 2}, {1, 0}, {0, 0}, {0, 1}, {0, 2}, {1, 2}});
}

TEST_CASE("wall followers: a full circuit of a tree, back at the start") {
  const testing_world::TextMaze maze(kSmall);
  for (const StrategyKind kind : {StrategyKind::left_wall, StrategyKind::right_wall}) {
    CAPTURE(explore::to_string(kind));
    const Outcome o = explore_truth(truth_of(maze), kind, {0, 0}, Heading::north);
    CHECK(o.end == Cell{0, 0});
    CHECK(o.moves == 14);  // each of the 7 passages once each way
    CHECK(o.first_visits.size() == 8);
  }
  const Outcome left = explore_truth(truth_of(maze), StrategyKind::left_wall, {0, 0}, Heading::north);
  CHECK(left.first_visits == Cells{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {1, 0}, {1, 1}, {2, 1}, {2, 2}});
  const Outcome right = explore_truth(truth_of(maze), StrategyKind::right_wall, {0, 0}, Heading::north);
  CHECK(right.first_visits == Cells{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}});
}

TEST_CASE("floodfill: reaches the goal, re-planning as walls appear; stops when it cannot") {
  // Every path shorter than the one it found would cross a side it has seen closed, so the
  // search ends on the goal.
  const testing_world::TextMaze maze(kSmall);
  const Outcome o = explore_truth(truth_of(maze), StrategyKind::floodfill, {0, 0}, Heading::north,
                                  {{2, 2}});
  CHECK(o.end == Cell{2, 2});
  // Optimistic about unknown sides, it first heads up the west column, finds it closed,
  // and comes back round through the bottom.
  CHECK(o.path == Cells{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {0, 2}, {0, 1}, {0, 0}, {1, 0}, {1, 1},
                        {2, 1}, {2, 2}});
  const Outcome walled_in = explore_truth(truth_of(maze), StrategyKind::floodfill, {0, 0},
                                          Heading::north, {{2, 0}});
  CHECK(walled_in.end != Cell{2, 0});
  // Several goal cells: any of them ends the run.
  const Outcome two = explore_truth(truth_of(maze), StrategyKind::floodfill, {0, 0}, Heading::north,
                                    {{2, 2}, {1, 0}});
  CHECK(two.end == Cell{1, 0});
  CHECK(two.moves == 1);
}

TEST_CASE("strategies on generated perfect mazes: coverage, circuits, goals") {
  for (const int size : {2, 5, 16}) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      CAPTURE(size);
      CAPTURE(seed);
      const Generated g = generate(size, size, seed);
      const Truth t = truth_of(g);
      const std::size_t cells = static_cast<std::size_t>(size * size);
      for (const StrategyKind kind : {StrategyKind::dfs, StrategyKind::frontier}) {
        CHECK(explore_truth(t, kind, {0, 0}, Heading::north).first_visits.size() == cells);
      }
      for (const StrategyKind kind : {StrategyKind::left_wall, StrategyKind::right_wall}) {
        const Outcome o = explore_truth(t, kind, {0, 0}, Heading::north);
        CHECK(o.end == Cell{0, 0});
        CHECK(o.moves == 2 * (size * size - 1));
        CHECK(o.first_visits.size() == cells);
      }
      // floodfill reaches the goal, then searches on until its path is proven shortest
      // (test_controller_shortest_path.cpp checks the proof).
      const Cell goal{size / 2, size / 2};
      const Outcome flood = explore_truth(t, StrategyKind::floodfill, {0, 0}, Heading::north, {goal});
      CHECK(std::find(flood.path.begin(), flood.path.end(), goal) != flood.path.end());
    }
  }
}

TEST_CASE("dfs moves are bounded: each passage at most twice each way") {
  const Generated g = generate(32, 32, 99);
  const Outcome o = explore_truth(truth_of(g), StrategyKind::dfs, {0, 0}, Heading::east);
  CHECK(o.first_visits.size() == 32u * 32u);
  CHECK(o.moves <= 2 * (32 * 32 - 1));
}

TEST_CASE("strategy names and options") {
  CHECK(explore::parse_strategy("left-wall") == StrategyKind::left_wall);
  CHECK(explore::to_string(StrategyKind::floodfill) == "floodfill");
  const auto message = [](auto &&f) -> std::string {
    try {
      f();
    } catch (const common::InputError &e) {
      return e.diagnostic();
    }
    return "";
  };
  CHECK(message([] { explore::parse_strategy("bfs"); }) ==
        "error: unknown --strategy 'bfs' (choose dfs, frontier, left-wall, right-wall or floodfill)");
  CHECK(message([] { explore::validate({StrategyKind::floodfill, 4, 4, {0, 0}, {}}); }) ==
        "error: --strategy floodfill needs a goal cell (the world has none: no G in a text map, none in a num "
        "file): give --goal X,Y, or --goal centre for the maze's centre cells");
  CHECK(message([] { explore::validate({StrategyKind::dfs, 4, 4, {4, 0}, {}}); }) ==
        "error: start cell (4,0) is outside the 4x4 maze");
  CHECK(message([] { explore::validate({StrategyKind::dfs, 4, 4, {0, 0}, {{0, 9}}}); }) ==
        "error: goal cell (0,9) is outside the 4x4 maze");
}

TEST_CASE("wall followers: a circuit that misses the start, made by walls learned on the way, ends after one lap") {
  // A 3 x 2 room, the robot at (0,0). Once it has left, its start cell turns out walled in
  // (the map changed under it): the hand it follows can never bring it back to the start.
  for (const StrategyKind kind : {StrategyKind::left_wall, StrategyKind::right_wall}) {
    const Cell start{0, 0};
    Explorer explorer({kind, 3, 2, start, {}});
    bool start_walled_in = false;
    const explore::WallQuery walls = [&](Cell c, Heading h) {
      const Cell n = mapping::neighbour(c, h);
      if (n.x < 0 || n.y < 0 || n.x >= 3 || n.y >= 2) return SideState::wall;
      if (start_walled_in && (c == start || n == start)) return SideState::wall;
      return SideState::open;
    };
    Cell at = start;
    Heading heading = Heading::north;
    int moves = 0;
    while (moves < 100) {
      const std::optional<Heading> d = explorer.next(at, heading, walls);
      if (!d) break;
      at = mapping::neighbour(at, *d);
      heading = *d;
      start_walled_in = true;
      ++moves;
    }
    CAPTURE(static_cast<int>(kind));
    CHECK(moves < 100);
    // One lap of the 5 cells left visits each (cell, heading) it arrives with at most twice.
    CHECK(moves <= 2 * 5 * 4);
    CHECK(explorer.visited_count() == 6);
    CHECK(at != start);
  }
}
