// The wavefront planner: on a fully mapped maze its path length in cells equals
// the true shortest path (breadth-first search on the true maze), over 100 generated mazes.

#include <doctest/doctest.h>

#include <deque>
#include <vector>

#include "common/error.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "mapping/walls.hpp"
#include "maze/generate/generator.hpp"
#include "maze/world/maze.hpp"
#include "plan/cell/wavefront.hpp"

namespace {


// The grid a perfect cell-model run leaves: each cell's centre free; per side, a wall's band
// (middle and corners) occupied, an opening's band middle free; the rest never observed.
mapping::OccupancyGrid fully_mapped(const maze::Maze &m, int k) {
  mapping::GridGeometry g;
  g.width_cells = m.width();
  g.height_cells = m.height();
  g.subcells = k;
  mapping::OccupancyGrid grid(g, 0.0f);
  const int mid = k / 2;
  for (int y = 0; y < m.height(); ++y) {
    for (int x = 0; x < m.width(); ++x) {
      const mapping::Cell c{x, y};
      grid.at(c, {mid, mid}) = -1.0f;
      for (const maze::Side s : maze::kSides) {
        const mapping::LocalSubCell b = mapping::band_middle(s, k);
        if (!m.has_wall(maze::Cell{x, y}, s)) {
          grid.at(c, b) = -1.0f;
          continue;
        }
        const bool along_j = s == maze::Side::north || s == maze::Side::south;
        for (int n = 0; n < k; ++n) {
          grid.at(c, along_j ? mapping::LocalSubCell{b.i, n} : mapping::LocalSubCell{n, b.j}) = 2.0f;
        }
      }
    }
  }
  return grid;
}

int bfs_cells(const maze::Maze &m, maze::Cell from, maze::Cell to) {
  std::vector<int> distance(static_cast<std::size_t>(m.width() * m.height()), -1);
  const auto at = [&](maze::Cell c) -> int & {
    return distance[static_cast<std::size_t>(c.y * m.width() + c.x)];
  };
  std::deque<maze::Cell> queue{from};
  at(from) = 0;
  while (!queue.empty()) {
    const maze::Cell c = queue.front();
    queue.pop_front();
    for (const maze::Side s : maze::kSides) {
      if (m.has_wall(c, s)) continue;
      const maze::Cell n = maze::neighbour(c, s);
      if (at(n) >= 0) continue;
      at(n) = at(c) + 1;
      queue.push_back(n);
    }
  }
  return at(to);
}

}  // namespace

TEST_CASE("wavefront: path length in cells equals BFS on the true maze, 100 generated mazes") {
  const mapping::SensorModel model;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    maze::GeneratorOptions o;
    o.width = 6 + static_cast<int>(seed % 5);
    o.height = 5 + static_cast<int>(seed % 4);
    o.seed = seed;
    o.loops = seed % 2 == 0 ? 0.0 : 0.2;
    o.algorithm = static_cast<maze::Algorithm>(seed % 3);
    const maze::Maze m = maze::generate_maze(o);
    const int k = seed % 3 == 0 ? 5 : 3;
    const mapping::OccupancyGrid grid = fully_mapped(m, k);
    const maze::Cell to{o.width - 1, o.height - 1};
    const auto path = plan::wavefront(grid, model, {m.start().x, m.start().y}, {to.x, to.y}, {});
    CAPTURE(seed);
    REQUIRE(path.has_value());
    CHECK(path->length_cells == bfs_cells(m, m.start(), to));
    CHECK(path->length_subcells == static_cast<int>(path->subcells.size()) - 1);
  }
}

TEST_CASE("wavefront: dilation closes a corridor one sub-cell wide; unreachable goals") {
  const mapping::SensorModel model;
  maze::GeneratorOptions o;
  o.width = 4;
  o.height = 4;
  const maze::Maze m = maze::generate_maze(o);
  const mapping::OccupancyGrid grid = fully_mapped(m, 3);
  plan::WavefrontOptions wide;
  wide.dilate = 1;
  CHECK_FALSE(plan::wavefront(grid, model, {0, 0}, {3, 3}, wide).has_value());
  CHECK(plan::wavefront(grid, model, {0, 0}, {0, 0}, {})->length_subcells == 0);
  wide.dilate = 9;
  CHECK_THROWS_AS(plan::validate(wide), common::InputError);
}
