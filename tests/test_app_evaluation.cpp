#include <doctest/doctest.h>

#include "app/run/evaluation.hpp"

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

TEST_CASE("wrong_sides_where_looked: a wrong side counts against the run only where the robot looked") {
  const maze::Maze m = corridor();
  // A phantom wall on the shared side 0|1, and a missed wall on cell 1's east side.
  const auto two_wrong = [&](maze::Cell c, maze::Side s) {
    if ((c == maze::Cell{0, 0} && s == maze::Side::east) || (c == maze::Cell{1, 0} && s == maze::Side::west)) {
      return app::LearnedSide::wall;
    }
    if (c == maze::Cell{1, 0} && s == maze::Side::east) return app::LearnedSide::open;
    return truth_of(m, c, s);
  };
  const app::WrongSides both = app::wrong_sides_where_looked(m, {true, true, false}, two_wrong);
  CHECK(both.count == 2);
  REQUIRE(both.first.size() == 2);
  CHECK(both.first[0].cell == maze::Cell{0, 0});
  CHECK(both.first[0].side == maze::Side::east);
  CHECK(both.first[0].verdict == app::SideVerdict::phantom);
  CHECK(both.first[1].verdict == app::SideVerdict::missed);
  // Looked from cell 0 only: the shared side is still where the robot looked, cell 1's east is not.
  CHECK(app::wrong_sides_where_looked(m, {true, false, false}, two_wrong).count == 1);
  CHECK(app::wrong_sides_where_looked(m, {false, false, false}, two_wrong).count == 0);
  const auto perfect = [&](maze::Cell c, maze::Side s) { return truth_of(m, c, s); };
  CHECK(app::wrong_sides_where_looked(m, {true, true, false}, perfect).count == 0);
}
