#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "common/random.hpp"
#include "maze/generate/generator.hpp"
#include "maze/world/maze.hpp"
#include "maze/sim/wall_grid.hpp"
#include "test_values.hpp"

namespace {

// 2 x 2 cells of 1 m; one interior wall: the north side of (0, 0), from x = 0 to 1, so
// its east end (the post at (1, 1)) is free-standing in the middle of the maze.
maze::Maze stub_maze() {
  maze::Maze m(2, 2);
  m.set_wall({0, 0}, maze::Side::north, true);
  return m;
}

}  // namespace

TEST_CASE("WallGrid::cast: an enclosed cell, beams along the walls and into the corners") {
  const maze::sim::WallGrid walls(maze::Maze(1, 1));
  const double free = 0.5 - kHalfWall_m;  // centre to each inner face
  CHECK(walls.cast(0.5, 0.5, 0.0, 12.0) == doctest::Approx(free).epsilon(1e-12));
  CHECK(walls.cast(0.5, 0.5, kPi / 2, 12.0) == doctest::Approx(free).epsilon(1e-12));
  CHECK(walls.cast(0.5, 0.5, kPi, 12.0) == doctest::Approx(free).epsilon(1e-12));
  CHECK(walls.cast(0.5, 0.5, -kPi / 2, 12.0) == doctest::Approx(free).epsilon(1e-12));
  // Exactly through the grid vertex: the beam meets the corner of the corner post.
  for (const double a : {kPi / 4, 3 * kPi / 4, -3 * kPi / 4, -kPi / 4}) {
    CHECK(walls.cast(0.5, 0.5, a, 12.0) == doctest::Approx(std::sqrt(2.0) * free).epsilon(1e-12));
  }
  // Off-centre, oblique: x = 0.2 + t cos a reaches the east face 0.994 first.
  const double a = 0.3;
  CHECK(walls.cast(0.2, 0.3, a, 12.0) == doctest::Approx((1.0 - kHalfWall_m - 0.2) / std::cos(a)).epsilon(1e-12));
}

TEST_CASE("WallGrid::cast: max range, and no return beyond it") {
  const maze::sim::WallGrid walls(maze::Maze(8, 1));
  CHECK(walls.cast(0.5, 0.5, 0.0, 12.0) == doctest::Approx(8.0 - kHalfWall_m - 0.5).epsilon(1e-12));
  CHECK(walls.cast(0.5, 0.5, 0.0, 7.0) == kInf);
  CHECK(walls.cast(0.5, 0.5, 0.0, 8.0 - kHalfWall_m - 0.5) == doctest::Approx(8.0 - kHalfWall_m - 0.5));
}

TEST_CASE("WallGrid::cast: wall ends, faces and beams that just miss them") {
  const maze::sim::WallGrid walls(stub_maze());
  // Along the wall's centre line y = 1 from the east: the end face at x = 1 + kHalfWall_m.
  CHECK(walls.cast(1.5, 1.0, kPi, 12.0) == doctest::Approx(0.5 - kHalfWall_m).epsilon(1e-12));
  // Along the wall's south face y = 1 - kHalfWall_m: a touch counts, at the end post's corner.
  CHECK(walls.cast(1.5, 1.0 - kHalfWall_m, kPi, 12.0) == doctest::Approx(0.5 - kHalfWall_m).epsilon(1e-12));
  // Just below the face: under the wall all the way to the west outer wall.
  CHECK(walls.cast(1.5, 1.0 - kHalfWall_m - 1e-9, kPi, 12.0) == doctest::Approx(1.5 - kHalfWall_m).epsilon(1e-12));
  // Just above the top face (y = 1 + kHalfWall_m): over the wall, to the west outer wall.
  CHECK(walls.cast(1.5, 1.0 + kHalfWall_m + 1e-9, kPi, 12.0) == doctest::Approx(1.5 - kHalfWall_m).epsilon(1e-12));
  // Obliquely onto the middle of the end face (1 + kHalfWall_m, 1).
  const double to_end = std::atan2(0.5, -(0.5 - kHalfWall_m));
  CHECK(walls.cast(1.5, 0.5, to_end, 12.0) == doctest::Approx(std::hypot(0.5 - kHalfWall_m, 0.5)).epsilon(1e-12));
  // Passing 1 mm above the end's top-right corner (1 + kHalfWall_m, 1 + kHalfWall_m): on to the north wall.
  const double past = std::atan2(0.5 + kHalfWall_m + 0.001, -(0.5 - kHalfWall_m));
  CHECK(walls.cast(1.5, 0.5, past, 12.0) == doctest::Approx((2.0 - kHalfWall_m - 0.5) / std::sin(past)).epsilon(1e-12));
  // From the cell north of the wall, straight down onto its top face.
  CHECK(walls.cast(0.5, 1.5, -kPi / 2, 12.0) == doctest::Approx(0.5 - kHalfWall_m).epsilon(1e-12));
  // Straight down past the end (x = 1.1 > 1 + kHalfWall_m): to the south outer wall.
  CHECK(walls.cast(1.1, 1.5, -kPi / 2, 12.0) == doctest::Approx(1.5 - kHalfWall_m).epsilon(1e-12));
}

TEST_CASE("WallGrid: cell size, thickness and origin from the maze") {
  maze::Maze m(3, 2);
  m.set_physical(0.18, 0.012, -1.0, 2.0);  // micromouse cells, origin moved
  const maze::sim::WallGrid walls(m);
  CHECK(walls.cast(-1.0 + 0.09, 2.0 + 0.09, 0.0, 12.0) ==
        doctest::Approx(3 * 0.18 - 0.09 - kHalfWall_m).epsilon(1e-12));
  CHECK(walls.cast(-1.0 + 0.09, 2.0 + 0.09, kPi / 2, 12.0) ==
        doctest::Approx(2 * 0.18 - 0.09 - kHalfWall_m).epsilon(1e-12));
}

TEST_CASE("WallGrid: inside_maze and inside_wall") {
  const maze::sim::WallGrid walls(stub_maze());
  CHECK(walls.inside_maze(0.0, 0.0));
  CHECK(walls.inside_maze(2.0, 2.0));
  CHECK_FALSE(walls.inside_maze(-0.01, 1.0));
  CHECK_FALSE(walls.inside_maze(1.0, 2.01));
  CHECK(walls.inside_wall(0.5, 1.0));
  CHECK(walls.inside_wall(0.5, 1.0 - kHalfWall_m));  // on the face
  CHECK(walls.inside_wall(1.0 + kHalfWall_m, 1.0));  // on the end face
  CHECK_FALSE(walls.inside_wall(1.0 + kHalfWall_m + 1e-9, 1.0));
  CHECK_FALSE(walls.inside_wall(1.5, 1.0));     // no wall north of (1, 0)
  CHECK(walls.inside_wall(0.003, 1.5));         // the west outer wall
}

TEST_CASE("WallGrid::push_out: a disc is moved clear of a wall along the normal") {
  const maze::sim::WallGrid walls(maze::Maze(1, 1));
  double x = 0.5, y = 1.0 - kHalfWall_m - 0.05;  // 4 cm into the north wall for a 9 cm disc
  CHECK(walls.push_out(x, y, 0.09));
  CHECK(x == doctest::Approx(0.5));
  CHECK(y == doctest::Approx(1.0 - kHalfWall_m - 0.09));
  CHECK_FALSE(walls.push_out(x, y, 0.09));
}

TEST_CASE("WallGrid::cast_direction: bit for bit the reference on random rays through generated mazes") {
  // The fast cast shares the edge arithmetic per cell; the reference runs one slab test per
  // box. Random origins (many on cell centres, where the robot scans), random directions,
  // loops so that beams travel far, a small wall-to-cell ratio and a thick one.
  common::Rng rng(8);
  for (const double thickness : {maze::kDefaultWallThickness_m, 0.2}) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
      maze::GeneratorOptions g;
      g.width = 12;
      g.height = 9;
      g.seed = seed;
      g.loops = seed == 3 ? 0.5 : 0.0;
      maze::Maze m = maze::generate_maze(g);
      m.set_physical(0.7, thickness, -1.25, 2.5);
      const maze::sim::WallGrid walls(m);
      int compared = 0;
      int hits = 0;
      for (int i = 0; i < 20000; ++i) {
        double x = -1.25 + rng.uniform(0.0, 12 * 0.7);
        double y = 2.5 + rng.uniform(0.0, 9 * 0.7);
        if (i % 2 == 0) {  // a cell centre
          x = -1.25 + (std::floor((x + 1.25) / 0.7) + 0.5) * 0.7;
          y = 2.5 + (std::floor((y - 2.5) / 0.7) + 0.5) * 0.7;
        }
        if (walls.inside_wall(x, y)) continue;
        const double a = rng.uniform(-kPi, kPi);
        const double dx = std::cos(a);
        const double dy = std::sin(a);
        const double max_range = i % 3 == 0 ? 1.0 : 12.0;
        const double fast = walls.cast_direction(x, y, dx, dy, max_range);
        const double reference = walls.cast_reference(x, y, dx, dy, max_range);
        CAPTURE(x);
        CAPTURE(y);
        CAPTURE(a);
        REQUIRE(std::bit_cast<std::uint64_t>(fast) == std::bit_cast<std::uint64_t>(reference));
        ++compared;
        hits += fast < kInf ? 1 : 0;
      }
      CHECK(compared > 15000);
      CHECK(hits > compared / 2);
      CHECK(hits < compared);  // max range 1 leaves some beams without a return
    }
  }
}

TEST_CASE("WallGrid::cast_direction: a direction with a subnormal component casts as the reference does") {
  // 1 / dx overflows to infinity for a subnormal dx; the quadrant walk's slab arithmetic then
  // differs from the reference's (an inf * 0 is NaN), so such rays take the reference's path.
  maze::GeneratorOptions g;
  g.width = 12;
  g.height = 9;
  g.seed = 4;
  maze::Maze m = maze::generate_maze(g);
  m.set_physical(0.7, maze::kDefaultWallThickness_m, -1.25, 2.5);
  const maze::sim::WallGrid walls(m);
  common::Rng rng(12);
  int compared = 0;
  for (int i = 0; i < 4000; ++i) {
    double x = -1.25 + rng.uniform(0.0, 12 * 0.7);
    double y = 2.5 + rng.uniform(0.0, 9 * 0.7);
    // Half the origins on a box's edge across the tiny component: (edge - origin) is 0 there.
    const double edge = std::floor(rng.uniform(0.0, 9.0)) * 0.7 + (i % 3 == 0   ? kHalfWall_m
                                                                   : i % 3 == 1 ? 0.7 - kHalfWall_m
                                                                                : 0.0);
    if (i % 32 >= 16) (i % 16 < 8 ? x : y) = (i % 16 < 8 ? -1.25 : 2.5) + edge;
    if (walls.inside_wall(x, y)) continue;
    const double tiny = (i % 4 < 2 ? 1e-320 : 4.9e-324) * (i % 2 == 0 ? 1.0 : -1.0);
    const double one = i % 8 < 4 ? 1.0 : -1.0;
    const bool tiny_x = i % 16 < 8;
    const double dx = tiny_x ? tiny : one;
    const double dy = tiny_x ? one : tiny;
    const double fast = walls.cast_direction(x, y, dx, dy, 12.0);
    const double reference = walls.cast_reference(x, y, dx, dy, 12.0);
    CAPTURE(x);
    CAPTURE(y);
    CAPTURE(dx);
    CAPTURE(dy);
    REQUIRE(std::bit_cast<std::uint64_t>(fast) == std::bit_cast<std::uint64_t>(reference));
    ++compared;
  }
  CHECK(compared > 2000);
}

TEST_CASE("WallGrid::free_centres: a disc centred inside the box touches no wall") {
  // Conservative by construction; checked against contacts() at random points, with the
  // pair-of-cells boxes near open sides included.
  common::Rng rng(9);
  maze::GeneratorOptions g;
  g.width = 10;
  g.height = 10;
  g.seed = 4;
  const maze::Maze m = maze::generate_maze(g);
  const maze::sim::WallGrid walls(m);
  const double radius = 0.09;
  int boxes = 0, pairs = 0, checked = 0;
  for (int i = 0; i < 20000; ++i) {
    const double x = rng.uniform(0.0, 10.0);
    const double y = rng.uniform(0.0, 10.0);
    const auto box = walls.free_centres(x, y, radius);
    if (!box) continue;
    ++boxes;
    pairs += (box->x_max_m - box->x_min_m > 1.0 || box->y_max_m - box->y_min_m > 1.0) ? 1 : 0;
    // Points anywhere in the box, not only the one it was asked about.
    for (int j = 0; j < 4; ++j) {
      const double px = rng.uniform(box->x_min_m, box->x_max_m);
      const double py = rng.uniform(box->y_min_m, box->y_max_m);
      if (!box->strictly_contains(px, py)) continue;
      for (const maze::sim::Contact &c : walls.contacts(px, py, radius + 1e-6)) {
        CAPTURE(px);
        CAPTURE(py);
        CHECK(c.distance_m > radius);
      }
      double qx = px, qy = py;
      CHECK_FALSE(walls.push_out(qx, qy, radius));
      ++checked;
    }
  }
  CHECK(boxes == 20000);
  CHECK(pairs > 1000);
  CHECK(checked > 70000);
  CHECK_FALSE(walls.free_centres(-0.5, 3.0, radius).has_value());
  CHECK_FALSE(walls.free_centres(3.0, 3.0, 0.6).has_value());  // a disc wider than a cell
}
