// Wall-segment XML as the course writes it (FAIRIS-Lite): a frame on 1 m, inner walls on a
// 0.5 m lattice, starts on lattice nodes. The cell size is the lattice of the wall ends; the
// maps below are drawn by hand from the segments in the fixtures' comments.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "common/error.hpp"
#include "maze/text_map.hpp"
#include "maze/world.hpp"
#include "maze/xml_format.hpp"

namespace {

std::string fixture(const std::string &name) { return std::string(TEST_DATA_DIR) + "/worlds/" + name; }

std::string diagnostic_of(const std::string &xml) {
  try {
    (void)maze::read_xml(xml, "f.xml");
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "no error";
}

// A 2 x 2 m frame (0.5 m lattice by its inner wall) with the start at (x, y) facing theta.
maze::Maze with_start(const char *x, const char *y, const char *theta) {
  const std::string xml = std::string(R"(<world>
<wall x1="0" y1="0" x2="2" y2="0"/><wall x1="0" y1="2" x2="2" y2="2"/>
<wall x1="0" y1="0" x2="0" y2="2"/><wall x1="2" y1="0" x2="2" y2="2"/>
<wall x1="0.5" y1="1" x2="1.5" y2="1"/>
<startPositions><pos x=")") + x + "\" y=\"" + y + "\" theta=\"" + theta + "\"/></startPositions></world>";
  return maze::read_xml(xml, "f.xml");
}

}  // namespace

TEST_CASE("course XML: a 5 x 5 m frame with inner walls on 0.5 m reads as 10 x 10 cells of 0.5 m") {
  const maze::World world = maze::load_world(fixture("course_lattice.xml"));
  CHECK(world.warnings.empty());
  const maze::Maze &m = world.maze;
  CHECK(m.cell_size_m() == 0.5);
  CHECK(m.origin_x_m() == -2.5);
  CHECK(m.origin_y_m() == -2.5);
  CHECK(m.wall_thickness_m() == maze::kDefaultWallThickness_m);
  // The start (-2, -2) is a lattice node: the cell north-east of it (facing north).
  CHECK(m.start() == maze::Cell{1, 1});
  CHECK(m.start_heading() == maze::Side::north);
  CHECK(m.goals() == std::vector<maze::Cell>{{1, 9}, {8, 8}});
  CHECK(maze::write_text_map(m) ==
        "o---o---o---o---o---o---o---o---o---o---o\n"
        "|     G                                 |\n"
        "o   o   o   o   o   o   o   o   o   o   o\n"
        "|               |                 G     |\n"
        "o   o   o   o   o   o   o   o   o   o   o\n"
        "|               |       |               |\n"
        "o   o   o   o   o   o   o   o   o   o   o\n"
        "|                       |               |\n"
        "o---o---o---o---o---o   o   o   o   o   o\n"
        "|                       |               |\n"
        "o   o   o   o   o   o   o   o   o---o---o\n"
        "|                       |               |\n"
        "o   o   o   o   o   o   o   o   o   o   o\n"
        "|                       |               |\n"
        "o   o   o---o---o---o---o---o---o---o---o\n"
        "|                                       |\n"
        "o   o   o   o   o   o   o   o   o   o   o\n"
        "|     S |                               |\n"
        "o   o   o   o   o   o   o   o   o   o   o\n"
        "|       |                               |\n"
        "o---o---o---o---o---o---o---o---o---o---o\n");
}

TEST_CASE("course XML: a frame in 1 m pieces with 0.5 m inner walls, the start on a node facing west") {
  const maze::Maze m = maze::load_world(fixture("course_frame_1m.xml")).maze;
  CHECK(m.cell_size_m() == 0.5);
  CHECK(m.start() == maze::Cell{5, 3});
  CHECK(m.start_heading() == maze::Side::west);
  CHECK(maze::write_text_map(m) ==
        "o---o---o---o---o---o---o---o---o\n"
        "|                               |\n"
        "o   o   o   o   o   o   o   o   o\n"
        "|     G                         |\n"
        "o   o   o   o   o   o   o   o   o\n"
        "|                               |\n"
        "o   o   o---o---o---o---o---o   o\n"
        "|                               |\n"
        "o   o   o   o   o   o   o   o   o\n"
        "|                     S         |\n"
        "o   o   o   o   o   o   o   o   o\n"
        "|           |                   |\n"
        "o   o   o   o   o   o---o---o---o\n"
        "|           |                   |\n"
        "o   o   o   o   o   o   o   o   o\n"
        "|           |                   |\n"
        "o---o---o---o---o---o---o---o---o\n");
}

TEST_CASE("course XML: written and read back, the 0.5 m maze is the same") {
  const maze::Maze m = maze::load_world(fixture("course_lattice.xml")).maze;
  CHECK(maze::read_xml(maze::write_xml(m), "again.xml") == m);
}

TEST_CASE("course XML: a start on a grid line or node takes the cell ahead of it, else north-east") {
  // Cells of 0.5 m from (0, 0); the node (1, 1) touches cells (1,1), (2,1), (1,2), (2,2).
  CHECK(with_start("1", "1", "1.5708").start() == maze::Cell{2, 2});     // north: north-east
  CHECK(with_start("1", "1", "0").start() == maze::Cell{2, 2});          // east
  CHECK(with_start("1", "1", "3.14159").start() == maze::Cell{1, 2});    // west: north-west
  CHECK(with_start("1", "1", "-1.5708").start() == maze::Cell{2, 1});    // south: south-east
  CHECK(with_start("1", "0.25", "3.14159").start() == maze::Cell{1, 0});  // on a line, facing west
  CHECK(with_start("0.3", "1.7", "0").start() == maze::Cell{0, 3});      // anywhere: its cell
  CHECK(with_start("0.25", "0.25", "0").start() == maze::Cell{0, 0});    // a centre
}

TEST_CASE("course XML: the lattice tolerates decimal rounding, and the stated cellSize wins") {
  // 0.1 m cells written with rounding errors of 1e-9 m.
  const maze::Maze m = maze::read_xml(R"(<world>
<wall x1="0" y1="0" x2="0.3000000001" y2="0"/><wall x1="0" y1="0.2" x2="0.3" y2="0.2"/>
<wall x1="0" y1="0" x2="0" y2="0.2"/><wall x1="0.2999999999" y1="0" x2="0.2999999999" y2="0.2"/>
<wall x1="0.1" y1="0" x2="0.1" y2="0.1" width="0.012"/></world>)",
                                      "f.xml");
  CHECK(m.width() == 3);
  CHECK(m.height() == 2);
  CHECK(m.cell_size_m() == doctest::Approx(0.1).epsilon(1e-9));
  const maze::Maze stated = maze::read_xml(R"(<world cellSize="0.5">
<wall x1="0" y1="0" x2="1" y2="0"/><wall x1="0" y1="1" x2="1" y2="1"/>
<wall x1="0" y1="0" x2="0" y2="1"/><wall x1="1" y1="0" x2="1" y2="1"/></world>)",
                                           "f.xml");
  CHECK(stated.width() == 2);
  CHECK(stated.cell_size_m() == 0.5);
}

TEST_CASE("course XML: arenas are not grid mazes, and a wall end off every lattice says where") {
  CHECK(diagnostic_of(maze::read_file(fixture("thick_obstacles.xml"))) ==
        "f.xml:8:40: error: walls 1 m thick, the shortest 2 m long, are obstacles in an arena, not a grid maze "
        "(its walls are thinner than a quarter of a cell)");
  CHECK(diagnostic_of("<world>\n  <startPositions><pos x='0' y='0'/></startPositions>\n</world>") ==
        "f.xml:1:1: error: no <wall> elements: an open arena, not a grid maze; a maze needs walls");
  CHECK(diagnostic_of(R"(<world>
<wall x1="0" y1="0" x2="2" y2="0"/><wall x1="0" y1="2" x2="2" y2="2"/>
<wall x1="0" y1="0" x2="0" y2="2"/><wall x1="2" y1="0" x2="2" y2="2"/>
<wall x1="0.5" y1="1" x2="1.53" y2="1"/></world>)") ==
        "f.xml:4:23: error: wall end x2=1.53 is off the grid (cells of 0.5 m from (0, 0))");
  CHECK(diagnostic_of(R"(<world cellSize="0.04">
<wall x1="0" y1="0" x2="1" y2="0"/><wall x1="0" y1="1" x2="1" y2="1"/>
<wall x1="0" y1="0" x2="0" y2="1"/><wall x1="1" y1="0" x2="1" y2="1"/></world>)") ==
        "f.xml:1:8: error: wall width 0.012 m is not less than a quarter of the cell size 0.04 m");
}
