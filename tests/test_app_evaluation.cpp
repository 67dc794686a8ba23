#include <doctest/doctest.h>

#include "app/evaluation.hpp"

namespace {

// 3 x 1 corridor, cells 0-1 open between them, a wall between 1 and 2 (so 2 is unreachable).
maze::Maze corridor() {
  maze::Maze m(3, 1);
  m.set_wall({1, 0}, maze::Side::east, true);
  m.set_start({0, 0}, maze::Side::north);
  return m;
}

app::LearnedSide truth_of(const maze::Maze &m, maze::Cell c, maze::Side s) {
  return m.has_wall(c, s) ? app::LearnedSide::wall : app::LearnedSide::open;
}

}  // namespace

TEST_CASE("score_map: coverage counts reachable cells only") {
  const maze::Maze m = corridor();
  const auto perfect = [&](maze::Cell c, maze::Side s) { return truth_of(m, c, s); };
  const app::MapScore half = app::score_map(m, {true, false, false}, perfect);
  CHECK(half.reachable_cells == 2);
  CHECK(half.visited_reachable_cells == 1);
  CHECK(half.coverage_percent() == 50.0);
}

TEST_CASE("score_map: each side once, boundary included, unknown counts as wrong") {
  const maze::Maze m = corridor();
  // Reachable cells 0 and 1: sides N0 S0 W0 N1 S1 E1 and the shared side 0|1 -> 7 sides.
  const auto perfect = [&](maze::Cell c, maze::Side s) { return truth_of(m, c, s); };
  const app::MapScore all = app::score_map(m, {true, true, false}, perfect);
  CHECK(all.sides == 7);
  CHECK(all.sides_correct == 7);
  CHECK(all.wall_accuracy_percent() == 100.0);

  const auto unknown_shared = [&](maze::Cell c, maze::Side s) {
    const bool shared = (c == maze::Cell{0, 0} && s == maze::Side::east) ||
                        (c == maze::Cell{1, 0} && s == maze::Side::west);
    return shared ? app::LearnedSide::unknown : truth_of(m, c, s);
  };
  const app::MapScore one_wrong = app::score_map(m, {true, true, false}, unknown_shared);
  CHECK(one_wrong.sides == 7);
  CHECK(one_wrong.sides_correct == 6);
  CHECK(one_wrong.wall_accuracy_percent() == doctest::Approx(600.0 / 7));
}
