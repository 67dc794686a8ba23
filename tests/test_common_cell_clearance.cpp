// The body's clearance on a grid of square cells (common/cell_clearance.hpp).

#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/cell_clearance.hpp"

TEST_CASE("clearance disc: the cells a body of the radius reaches into, by the cell's size") {
  // 0.09 m body: at 0.1 m cells the 8 neighbours (0.05 m and 0.071 m away), at 0.05 m a disc
  // of 5 x 5 less its corners (0.106 m away), at 0.2 m none but the cell (0.1 m away).
  CHECK(common::clearance_disc(0.1, 0.09).size() == 9);
  CHECK(common::clearance_disc(0.05, 0.09).size() == 21);
  CHECK(common::clearance_disc(0.2, 0.09).size() == 1);
  // Touching is clear: a 0.05 m radius reaches the 0.1 m neighbours only at their edge.
  CHECK(common::clearance_disc(0.1, 0.05).size() == 1);
}

TEST_CASE("cells without clearance: around each occupied cell and along the grid's edge") {
  // 7 x 7 cells of 0.1 m, (3, 3) occupied, a 0.09 m body: the 3 x 3 block round it and the
  // edge ring (centres 0.05 m from the edge) are blocked; the 16 cells between are clear.
  const std::vector<std::uint8_t> blocked =
      common::cells_without_clearance(7, 7, 0.1, 0.09, [](std::size_t n) { return n == 3 * 7 + 3; });
  CHECK(std::count(blocked.begin(), blocked.end(), 1) == 33);
  CHECK(blocked[2 * 7 + 2] == 1);
  CHECK(blocked[1 * 7 + 1] == 0);
  CHECK(blocked[0] == 1);
  CHECK(blocked[3 * 7 + 5] == 0);
  // Radius 0: only the occupied cell.
  const std::vector<std::uint8_t> bare =
      common::cells_without_clearance(7, 7, 0.1, 0.0, [](std::size_t n) { return n == 3 * 7 + 3; });
  CHECK(std::count(bare.begin(), bare.end(), 1) == 1);
}
