#include <doctest/doctest.h>

#include <string>

#include "common/error.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"

using mapping::Cell;
using mapping::GridGeometry;
using mapping::LocalSubCell;
using mapping::OccupancyGrid;
using mapping::SubCell;

namespace {

GridGeometry non_square(int k) {
  GridGeometry g;
  g.width_cells = 7;
  g.height_cells = 4;
  g.subcells = k;
  g.cell_size_m = 0.18;
  g.origin = {-1.25, 2.5};
  return g;
}

std::string error_of(const GridGeometry &g, std::uint64_t max_bytes = mapping::kDefaultMaxGridBytes) {
  try {
    mapping::validate(g, max_bytes);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "";
}

}  // namespace

TEST_CASE("Grid indexing: (cell, sub-cell) <-> global sub-cell <-> world point round trips") {
  for (const int k : {3, 5, 9}) {
    CAPTURE(k);
    const OccupancyGrid grid(non_square(k), 0.0f);
    REQUIRE(grid.size() == static_cast<std::size_t>(7 * 4 * k * k));
    std::size_t expected_flat = 0;
    // Storage order: cells row-major from the south-west, then i from the north, j from the west.
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 7; ++x) {
        for (int i = 0; i < k; ++i) {
          for (int j = 0; j < k; ++j) {
            const Cell c{x, y};
            const LocalSubCell local{i, j};
            CHECK(grid.index(c, local) == expected_flat++);
            const SubCell global = mapping::to_global(c, local, k);
            CHECK(grid.contains(global));
            CHECK(mapping::cell_of(global, k) == c);
            CHECK(mapping::local_of(global, k) == local);
            CHECK(grid.index(global) == grid.index(c, local));
            const mapping::Point centre = grid.centre_of(global);
            const auto back = grid.subcell_at(centre);
            REQUIRE(back.has_value());
            CHECK(*back == global);
          }
        }
      }
    }
  }
}

TEST_CASE("Grid indexing: the conventions of ARCHITECTURE.md at known points") {
  const OccupancyGrid grid(non_square(3), 0.0f);
  // Row i = 0 is the north band: its global row is the top one of the cell.
  CHECK(mapping::to_global(Cell{0, 0}, LocalSubCell{0, 0}, 3) == SubCell{0, 2});
  CHECK(mapping::to_global(Cell{0, 0}, LocalSubCell{2, 2}, 3) == SubCell{2, 0});
  CHECK(mapping::to_global(Cell{2, 1}, LocalSubCell{1, 1}, 3) == SubCell{7, 4});
  // The south-west corner of the grid is the origin; a point just inside is sub-cell (0, 0).
  CHECK(grid.subcell_at({-1.25 + 1e-9, 2.5 + 1e-9}) == SubCell{0, 0});
  CHECK_FALSE(grid.subcell_at({-1.25 - 1e-9, 2.5}).has_value());
  CHECK_FALSE(grid.subcell_at({-1.25 + 7 * 0.18 + 1e-9, 2.6}).has_value());
  CHECK_FALSE(grid.subcell_at({NAN, 2.6}).has_value());
  // Cell centre.
  const auto centre = grid.centre_of(Cell{1, 2});
  CHECK(centre.x_m == doctest::Approx(-1.25 + 1.5 * 0.18));
  CHECK(centre.y_m == doctest::Approx(2.5 + 2.5 * 0.18));
  // Sub-cells west or south of the grid belong to negative cells.
  CHECK(mapping::cell_of(SubCell{-1, -1}, 3) == Cell{-1, -1});
  CHECK(mapping::local_of(SubCell{-1, -1}, 3) == LocalSubCell{0, 2});
}

TEST_CASE("cell_matrix: a K x K view, north row first") {
  OccupancyGrid grid(non_square(3), 0.0f);
  grid.at(Cell{3, 2}, LocalSubCell{0, 1}) = 1.5f;   // north band middle
  grid.at(Cell{3, 2}, LocalSubCell{2, 0}) = -0.5f;  // south-west corner
  const auto m = grid.cell_matrix(Cell{3, 2});
  REQUIRE(m.rows() == 3);
  REQUIRE(m.cols() == 3);
  CHECK(m(0, 1) == 1.5f);
  CHECK(m(2, 0) == -0.5f);
  CHECK(m.sum() == 1.0f);
}

TEST_CASE("ScanUpdate: one update per sub-cell per scan, occupied wins") {
  const mapping::SensorModel model;
  OccupancyGrid grid(non_square(3), 0.0f);
  mapping::ScanUpdate scan;
  const auto a = grid.index(Cell{0, 0}, LocalSubCell{1, 1});
  const auto b = grid.index(Cell{0, 0}, LocalSubCell{0, 1});
  const auto c = grid.index(Cell{1, 0}, LocalSubCell{1, 2});
  scan.mark_free(a);
  scan.mark_free(a);
  scan.mark_free(a);  // seen free by three beams
  scan.mark_free(b);
  scan.mark_occupied(b);  // seen free and occupied: occupied wins
  scan.mark_occupied(c);
  scan.mark_occupied(c);
  CHECK(scan.apply(grid, model) == 3);
  CHECK(grid.at_index(a) == doctest::Approx(model.free_increment()));
  CHECK(grid.at_index(b) == doctest::Approx(model.occupied_increment()));
  CHECK(grid.at_index(c) == doctest::Approx(model.occupied_increment()));
  CHECK(scan.empty());

  // A second scan updates again, once.
  scan.mark_free(a);
  scan.mark_free(a);
  CHECK(scan.apply(grid, model) == 1);
  CHECK(grid.at_index(a) == doctest::Approx(2 * model.free_increment()));
}

TEST_CASE("ScanUpdate: clamping holds values within the bounds") {
  mapping::SensorModelOptions options;
  options.clamp = mapping::Clamp{-2.0, 3.5};
  const mapping::SensorModel model(options);
  OccupancyGrid grid(non_square(3), 0.0f);
  mapping::ScanUpdate scan;
  for (int n = 0; n < 20; ++n) {
    scan.mark_occupied(0);
    scan.mark_free(1);
    scan.apply(grid, model);
  }
  CHECK(grid.at_index(0) == doctest::Approx(3.5));
  CHECK(grid.at_index(1) == doctest::Approx(-2.0));
}

TEST_CASE("GridGeometry validation: messages to the letter") {
  GridGeometry g = non_square(3);
  CHECK(error_of(g) == "");
  g.subcells = 4;
  CHECK(error_of(g) == "error: --subcells must be odd and between 3 and 9 (got 4)");
  g.subcells = 1;
  CHECK(error_of(g) == "error: --subcells must be odd and between 3 and 9 (got 1)");
  g.subcells = 11;
  CHECK(error_of(g) == "error: --subcells must be odd and between 3 and 9 (got 11)");
  g = non_square(3);
  g.width_cells = 0;
  CHECK(error_of(g) == "error: grid size must be 1 to 4096 cells each way (got 0x4)");
  g = non_square(3);
  g.cell_size_m = -1.0;
  CHECK(error_of(g) == "error: cell size must be a positive number of metres (got -1)");
}

TEST_CASE("GridGeometry validation: a grid too large is refused before allocating") {
  GridGeometry g;
  g.width_cells = 4096;
  g.height_cells = 4096;
  g.subcells = 9;
  CHECK(mapping::grid_bytes(g) == 4096ull * 4096 * 81 * 8);
  CHECK(error_of(g) ==
        "error: a 4096x4096 grid with 9x9 sub-cells per cell needs 10.1 GiB of memory (limit 4.0 GiB)");
  CHECK_THROWS_AS(OccupancyGrid(g, 0.0f), common::InputError);
}
