#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>

#include "explore/visits.hpp"
#include "mapping/occupancy_grid.hpp"
#include "render/ascii_map.hpp"
#include "robot/progress_printer.hpp"

using mapping::Cell;
using mapping::Heading;
using mapping::LocalSubCell;

namespace {

// Two cells side by side, K = 3. Cell (0,0) seen: north and west bands walls, centre and
// east middle free, the rest of it never observed; cell (1,0) seen only at its north middle.
struct Tiny {
  mapping::OccupancyGrid grid;
  explore::Visits visits;
  Tiny() : grid(geometry(), 0.0f), visits(2, 1) {
    const Cell a{0, 0}, b{1, 0};
    for (int j = 0; j < 3; ++j) grid.at(a, LocalSubCell{0, j}) = 0.41f;
    grid.at(a, LocalSubCell{1, 0}) = 0.41f;
    grid.at(a, LocalSubCell{2, 0}) = 0.41f;
    grid.at(a, LocalSubCell{1, 1}) = -0.85f;
    grid.at(a, LocalSubCell{1, 2}) = -0.85f;
    grid.at(b, LocalSubCell{0, 1}) = 0.41f;
    visits.record(a, Heading::north);
    visits.record(a, Heading::east);  // the last heading there is the one shown
  }
  static mapping::GridGeometry geometry() {
    mapping::GridGeometry g;
    g.width_cells = 2;
    g.height_cells = 1;
    g.subcells = 3;
    return g;
  }
};

}  // namespace

TEST_CASE("render_map: W, arrows at visited centres, blanks; north at the top") {
  const Tiny t;
  CHECK(render::render_map(t.grid, t.visits, {}) ==
        "WWW W \n"
        "W\u2192    \n"
        "W     \n");
  render::MapStyle ascii;
  ascii.ascii = true;
  CHECK(render::render_map(t.grid, t.visits, ascii) ==
        "WWW W \n"
        "W>    \n"
        "W     \n");
}

TEST_CASE("render_map: two columns a sub-cell (the true aspect): W, blanks, unknown doubled; the arrow then a blank") {
  const Tiny t;
  render::MapStyle style;
  style.ascii = true;
  style.subcell_columns = 2;
  CHECK(render::render_map(t.grid, t.visits, style) ==
        "WWWWWW  WW  \n"
        "WW>         \n"
        "WW          \n");
  style.unknown = '?';
  style.robot = render::RobotMark{mapping::SubCell{4, 1}, "@"};
  CHECK(render::render_map(t.grid, t.visits, style) ==
        "WWWWWW??WW??\n"
        "WW>   ??@ ??\n"
        "WW??????????\n");
}

TEST_CASE("render_map: --unknown marks never-observed sub-cells") {
  const Tiny t;
  render::MapStyle style;
  style.ascii = true;
  style.unknown = '?';
  CHECK(render::render_map(t.grid, t.visits, style) ==
        "WWW?W?\n"
        "W> ???\n"
        "W?????\n");
}

TEST_CASE("render_map: all four arrows; several rows of cells") {
  mapping::GridGeometry g;
  g.width_cells = 2;
  g.height_cells = 2;
  g.subcells = 3;
  const mapping::OccupancyGrid grid(g, 0.0f);
  explore::Visits visits(2, 2);
  visits.record({0, 1}, Heading::north);
  visits.record({1, 1}, Heading::east);
  visits.record({1, 0}, Heading::south);
  visits.record({0, 0}, Heading::west);
  CHECK(render::render_map(grid, visits, {}) ==
        "      \n"
        " \u2191  \u2192 \n"
        "      \n"
        "      \n"
        " \u2190  \u2193 \n"
        "      \n");
  render::MapStyle ascii;
  ascii.ascii = true;
  ascii.unknown = '.';
  CHECK(render::render_map(grid, visits, ascii) ==
        "......\n"
        ".^..>.\n"
        "......\n"
        "......\n"
        ".<..v.\n"
        "......\n");
  // A window of rows, appended.
  std::string out = "x\n";
  render::render_rows(out, grid, visits, ascii, 3, 2);
  CHECK(out ==
        "x\n"
        "......\n"
        ".<..v.\n");
}

TEST_CASE("render_map: a never-observed sub-cell is not W even with a prior above 0.5") {
  mapping::GridGeometry g;
  g.width_cells = 1;
  g.height_cells = 1;
  g.subcells = 3;
  mapping::OccupancyGrid grid(g, 0.405f);
  grid.at(Cell{0, 0}, LocalSubCell{0, 1}) = 0.9f;
  const explore::Visits visits(1, 1);
  render::MapStyle style;
  style.initial_log_odds = 0.405f;
  CHECK(render::render_map(grid, visits, style) ==
        " W \n"
        "   \n"
        "   \n");
}

TEST_CASE("format_cell_matrix: signed, 2 decimals, aligned; no -0.00") {
  mapping::GridGeometry g;
  g.width_cells = 1;
  g.height_cells = 1;
  g.subcells = 3;
  mapping::OccupancyGrid grid(g, 0.0f);
  grid.at(Cell{0, 0}, LocalSubCell{0, 0}) = 0.405465f;
  grid.at(Cell{0, 0}, LocalSubCell{1, 1}) = -12.5f;
  grid.at(Cell{0, 0}, LocalSubCell{2, 2}) = -0.001f;
  CHECK(render::format_cell_matrix(grid, {0, 0}) ==
        " +0.41  +0.00  +0.00\n"
        " +0.00 -12.50  +0.00\n"
        " +0.00  +0.00  +0.00\n");
}

TEST_CASE("format_status") {
  CHECK(render::format_status(412, {2, 3}, Heading::north, 7, 16) ==
        "step 412  cell (2,3)  heading N  visited 7/16");
}

TEST_CASE("window_around: the part of the map around a sub-cell, moved back inside at the edges") {
  mapping::GridGeometry g;
  g.width_cells = 10;
  g.height_cells = 4;
  g.subcells = 3;  // 30 x 12 sub-cells
  const mapping::OccupancyGrid grid(g, 0.0f);
  // In the middle: centred (row 12 - 1 - 6 = 5 from the north, less half of 4).
  const render::MapWindow middle = render::window_around(grid, mapping::SubCell{15, 6}, 4, 10);
  CHECK(middle.first_row == 3);
  CHECK(middle.row_count == 4);
  CHECK(middle.first_col == 10);
  CHECK(middle.col_count == 10);
  // At the south-west corner: the window's south-west corner is the map's.
  const render::MapWindow corner = render::window_around(grid, mapping::SubCell{0, 0}, 4, 10);
  CHECK(corner.first_row == 8);
  CHECK(corner.first_col == 0);
  // Larger than the map: the whole map.
  const render::MapWindow whole = render::window_around(grid, mapping::SubCell{29, 11}, 100, 100);
  CHECK(whole.first_row == 0);
  CHECK(whole.row_count == 12);
  CHECK(whole.first_col == 0);
  CHECK(whole.col_count == 30);
}

TEST_CASE("ProgressPrinter: with a view smaller than the map, the part around the robot and which part") {
  mapping::GridGeometry g;
  g.width_cells = 10;
  g.height_cells = 4;
  g.subcells = 3;  // 30 x 12 sub-cells
  const mapping::OccupancyGrid grid(g, 0.0f);
  explore::Visits visits(10, 4);
  visits.record(Cell{5, 2}, Heading::north);
  robot::MoveReport report;
  report.step = 7;
  report.moves = 1;
  report.cell = Cell{5, 2};
  report.grid = &grid;
  report.visits = &visits;
  std::ostringstream out;
  robot::ProgressPrinter printer(out, {}, 40, robot::ProgressPrinter::View{4, 10, std::chrono::milliseconds(0)});
  printer(report);
  // The robot's centre sub-cell (16, 7) is row 4 from the north: rows 2-5, columns 11-20.
  CHECK(out.str() ==
        "step 7  cell (5,2)  heading N  visited 1/40  view 11,2 of 30x12\n"
        "          \n"
        "          \n"
        "     \u2191    \n"
        "          \n"
        "\n");
  std::ostringstream whole;
  robot::ProgressPrinter no_view(whole, {}, 40);
  no_view(report);
  const std::string text = whole.str();
  CHECK(text.find("view") == std::string::npos);
  CHECK(std::count(text.begin(), text.end(), '\n') == 1 + 12 + 1);
}
