// Wall-segment XML as the course writes it (FAIRIS-Lite): a frame on 1 m, inner walls on a
// 0.5 m lattice, starts on lattice nodes. The cell size is the lattice of the wall ends; the
// maps below are drawn by hand from the segments in the fixtures' comments.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "maze/formats/text_map.hpp"
#include "maze/world/world.hpp"
#include "maze/formats/xml_format.hpp"
#include "test_values.hpp"

namespace {

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
  const maze::World world = maze::load_world(world_fixture("course_lattice.xml"));
  // Its starts sit on 1 m centres, which most inner walls are off: the walls' lattice, said.
  REQUIRE(world.warnings.size() == 1);
  CHECK(
      world.warnings[0].starts_with(world_fixture("course_lattice.xml") +
                                    ": warning: the start positions sit on the centres of 1 m cells, but the walls "
                                    "(-1.5, -1)-(2.5, -1) at line 14, (-2.5, 0.5)-(0, 0.5) at line 15, (0.5, -1)-(0.5, "
                                    "1.5) at line 16 and 2 more are off that lattice: read as 10x10 cells of 0.5 m"));
  const maze::Maze &m = world.maze();
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
  const maze::Maze m = maze::load_world(world_fixture("course_frame_1m.xml")).maze();
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
  const maze::Maze m = maze::load_world(world_fixture("course_lattice.xml")).maze();
  CHECK(maze::read_xml(maze::write_xml_keeping_origin(m), "again.xml") == m);
  // Centred (the default), the same maze with its centre on (0, 0): already so.
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
  CHECK(diagnostic_of(maze::read_file(world_fixture("thick_obstacles.xml"))) ==
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

TEST_CASE("course XML: a walled open arena reads on the lattice of its start positions") {
  const maze::World arena = maze::load_world(world_fixture("course_arena11.xml"));
  CHECK(arena.warnings.empty());
  const maze::Maze &m = arena.maze();
  CHECK(m.width() == 11);
  CHECK(m.height() == 11);
  CHECK(m.cell_size_m() == 1.0);
  CHECK(m.origin_x_m() == -5.5);
  // (5, -5) facing west (theta 3.14): the south-east cell.
  CHECK(m.start() == maze::Cell{10, 0});
  CHECK(m.start_heading() == maze::Side::west);
  REQUIRE(m.landmarks().size() == 1);
  CHECK(m.landmarks()[0] == maze::Landmark{-2.0, 3.0, 2.0, 0.0, 0.0, 1.0});

  const maze::Maze five = maze::load_world(world_fixture("course_arena5_starts.xml")).maze();
  CHECK(five.width() == 5);
  CHECK(five.height() == 5);
  CHECK(five.cell_size_m() == 1.0);
  const std::vector<maze::StartPosition> starts = five.start_positions();
  REQUIRE(starts.size() == 25);
  // Numbered from the south-west, row by row, as the course's students number the cells.
  CHECK(starts[0] == maze::StartPosition{{0, 0}, maze::Side::north});
  CHECK(starts[2] == maze::StartPosition{{2, 0}, maze::Side::north});
  CHECK(starts[24] == maze::StartPosition{{4, 4}, maze::Side::north});
  CHECK(five.landmarks().size() == 4);
}

TEST_CASE("course XML: a half wall keeps the walls' finer lattice, with one warning that says how to choose") {
  const std::string file = world_fixture("course_half_wall.xml");
  const maze::World world = maze::load_world(file);
  CHECK(world.maze().width() == 10);
  CHECK(world.maze().cell_size_m() == 0.5);
  REQUIRE(world.warnings.size() == 1);
  CHECK(world.warnings[0] ==
        file + ": warning: the start positions sit on the centres of 1 m cells, but the wall (-1, 1.5)-(1.5, 1.5) at "
               "line 17 is off that lattice: read as 10x10 cells of 0.5 m, the walls' own lattice; --cell-size 0.5 "
               "keeps this reading without the warning, --cell-size 1 asks for 1 m cells (the walls off them are "
               "then errors)");
  // The 25 starts are lattice nodes of the 0.5 m cells: the cell north-east of each (facing north).
  CHECK(world.maze().start() == maze::Cell{1, 1});
  CHECK(world.maze().start_positions().size() == 25);
  // Exactly the file: the half wall runs from x = -1 (grid line 3) to 1.5 (line 8) at y = 1.5
  // (line 8): the south sides of cells (3,8) to (7,8), not (2,8).
  CHECK(world.maze().has_wall({3, 8}, maze::Side::south));
  CHECK(world.maze().has_wall({7, 8}, maze::Side::south));
  CHECK_FALSE(world.maze().has_wall({2, 8}, maze::Side::south));

  maze::WorldOverrides walls_lattice;
  walls_lattice.cell_size_m = 0.5;
  const maze::World chosen = maze::load_world(file, walls_lattice);
  CHECK(chosen.warnings.empty());
  CHECK(chosen.maze() == world.maze());
  maze::WorldOverrides starts_lattice;
  starts_lattice.cell_size_m = 1.0;
  try {
    (void)maze::load_world(file, starts_lattice);
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == file + ":17:11: error: wall end x1=-1 is off the grid (cells of 1 m from (-2.5, -2.5))");
  }
}

TEST_CASE("course XML: --start pos:N and random pick among the start positions") {
  const std::string file = world_fixture("course_arena5_starts.xml");
  maze::WorldOverrides third;
  third.start_position = 3;
  CHECK(maze::load_world(file, third).maze().start() == maze::Cell{2, 0});
  maze::WorldOverrides too_far;
  too_far.start_position = 26;
  CHECK_THROWS_WITH_AS(maze::load_world(file, too_far),
                       ("--start pos:26: " + file + " states 25 start positions (pos:1 to pos:25)").c_str(),
                       common::InputError);
  // random: the same seed, the same start; over seeds, more than one start.
  maze::WorldOverrides random;
  random.random_start = true;
  random.random_start_seed = 7;
  const maze::Cell once = maze::load_world(file, random).maze().start();
  CHECK(maze::load_world(file, random).maze().start() == once);
  const std::vector<maze::StartPosition> starts = maze::load_world(file).maze().start_positions();
  CHECK(once == starts[maze::random_start_index(7, 25)].cell);
  std::vector<maze::Cell> seen;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    random.random_start_seed = seed;
    const maze::Cell c = maze::load_world(file, random).maze().start();
    if (std::find(seen.begin(), seen.end(), c) == seen.end()) seen.push_back(c);
  }
  CHECK(seen.size() > 5);
  // A world with one start: pos:1 is it, pos:2 is an error.
  maze::WorldOverrides second;
  second.start_position = 2;
  CHECK_THROWS_WITH_AS(maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.xml", second),
                       ("--start pos:2: " + std::string(WORLDS_DIR) +
                        "/lab4x4.xml states 1 start position (pos:1 to pos:1)").c_str(),
                       common::InputError);
}

TEST_CASE("course XML: bad landmarks and start positions are located") {
  const std::string frame = R"(<world>
<wall x1="0" y1="0" x2="2" y2="0"/><wall x1="0" y1="2" x2="2" y2="2"/>
<wall x1="0" y1="0" x2="0" y2="2"/><wall x1="2" y1="0" x2="2" y2="2"/>
)";
  CHECK(diagnostic_of(frame + R"(<landmark x="1" y="1" red="2"/></world>)") ==
        "f.xml:4:23: error: red must be 0 to 1, got 2");
  CHECK(diagnostic_of(frame + R"(<landmark x="1" y="1" height="0"/></world>)") ==
        "f.xml:4:23: error: height must be positive, got 0");
  CHECK(diagnostic_of(frame + R"(<landmark y="1"/></world>)") == "f.xml:4:1: error: <landmark> needs the attribute x");
  CHECK(diagnostic_of(frame + R"(<startPositions><pos x="0.5" y="0.5"/><pos x="0.5" y="9"/></startPositions></world>)") ==
        "f.xml:4:44: error: start (0.5, 9) is outside the maze, which spans x 0 to 2 m and y 0 to 2 m");
}

TEST_CASE("course XML: a landmark may stand on or beyond the maze's edge") {
  const std::string text = R"(<world>
<wall x1="0" y1="0" x2="2" y2="0"/><wall x1="0" y1="2" x2="2" y2="2"/>
<wall x1="0" y1="0" x2="0" y2="2"/><wall x1="2" y1="0" x2="2" y2="2"/>
<landmark x="-0.5" y="2.5"/><landmark x="2" y="0"/></world>)";
  const maze::Maze m = maze::read_xml(text, "f.xml");
  REQUIRE(m.landmarks().size() == 2);
  CHECK(m.landmarks()[0].x_m == -0.5);
  CHECK(m.landmarks()[0].y_m == 2.5);
}

TEST_CASE("course XML: landmarks and every start position survive a round trip") {
  for (const char *name : {"course_arena5_starts.xml", "course_half_wall.xml", "course_arena11.xml"}) {
    CAPTURE(name);
    const maze::Maze m = maze::load_world(world_fixture(name)).maze();
    const maze::Maze kept = maze::read_xml(maze::write_xml_keeping_origin(m), "x.xml");
    CHECK(kept == m);
  }
}
