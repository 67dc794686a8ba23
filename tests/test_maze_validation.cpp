// Every validation message, to the letter, from the fixtures in tests/data/worlds/.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "common/error.hpp"
#include "maze/world/validate.hpp"
#include "maze/world/world.hpp"
#include "test_values.hpp"

namespace {

struct Case {
  const char *file;
  const char *diagnostic;  // after the path
};

// What the grid maze reader says of the file (load_world reads some of these as arenas, whose
// lattice view then repeats it).
std::string load_diagnostic_of(const std::string &path) {
  try {
    const maze::WorldText file = maze::read_world_file(path);
    (void)maze::read_world(file.text, path, file.format);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("validation: every fault is named, with its place, to the letter") {
  const Case cases[] = {
      // any format
      {"empty.txt", ": error: the file is empty; expected a maze"},
      {"garbage.txt",
       ":1:1: error: cannot tell the format: expected a text map (first line 'o---o...'), num lines 'X Y N E S W', "
       "XML '<world>', a room file ('boundary XS XE YS YE', 'rect ...') or a 256-byte binary .maz"},
      // text map: known characters only
      {"bad_char.txt", ":8:7: error: unexpected 'x' in cell (1,0); expected a blank, 'S' or 'G'"},
      {"tab.txt", ":4:3: error: unexpected tab in cell (0,2); expected a blank, 'S' or 'G'"},
      {"arrow.txt", ":6:11: error: unexpected byte 0xe2 in cell (2,1); expected a blank, 'S' or 'G'"},
      {"bad_post.txt", ":5:9: error: unexpected '-' where a post 'o' or '+' belongs"},
      // text map: rectangular
      {"ragged.txt", ":6:17: error: line 6 is 16 characters long, expected 17 like the first line"},
      {"bad_width.txt",
       ":1:8: error: the first line is 7 characters long; a maze line is 4W+1 characters (5, 9, 13, ...)"},
      {"even_lines.txt", ":8:1: error: the maze's last line must be a post line ('o---o...'), not a cell line"},
      {"too_short.txt", ":2:1: error: a maze needs at least 3 lines (2H+1 for H rows), found 1"},
      // text map: consistent (a wall is drawn whole), enclosed, one start
      {"partial_wall.txt", ":3:6: error: cell (1,2): north wall partly drawn ('-- '); expected '---' or three blanks"},
      {"open_edge.txt", ":6:17: error: cell (3,1): east wall missing on the maze's edge"},
      {"two_starts.txt", ":8:3: error: a second start 'S' in cell (0,0); the first is in cell (1,2)"},
      // num
      {"inconsistent.num", ":25:11: error: cell (3,4): east wall missing on the west side of (4,4)"},
      {"inconsistent_west.num", ":18:7: error: cell (4,2): west wall missing on the east side of (3,2)"},
      {"open_edge.num", ":22:7: error: cell (4,1): east wall missing on the maze's edge"},
      {"duplicate.num", ":8:1: error: cell (0,2) listed twice; the first is on line 3"},
      {"missing.num", ": error: cell (2,3) is missing; the cells listed span 5x5"},
      {"bad_token.num", ":4:9: error: S is not an integer: 'zero'"},
      {"flag2.num", ":7:5: error: N must be 0 or 1, got 2"},
      {"too_few.num", ":5:10: error: expected 6 integers 'X Y N E S W', got 5"},
      {"too_many.num", ":5:13: error: expected 6 integers 'X Y N E S W', got more"},
      {"big_x.num", ":26:1: error: X must be 0 to 4095, got 5000"},
      // XML
      {"off_grid.xml", ":8:23: error: wall end x2=2.37 is off the grid (cells of 1 m from (0, 0))"},
      {"nan.xml", ":9:23: error: x2 is not a finite number of metres: 'nan'"},
      {"diagonal.xml", ":10:3: error: wall from (1, 3) to (2, 4) is neither horizontal nor vertical"},
      {"width.xml",
       ":12:37: error: wall width 0.02 m differs from the 0.012 m of the first wall (line 4); a maze has one wall "
       "thickness"},
      {"start_outside.xml",
       ":30:10: error: start (7.5, 0.5) is outside the maze, which spans x 0 to 4 m and y 0 to 4 m"},
      {"theta.xml",
       ":30:26: error: theta 0.3 rad is not a multiple of pi/2; the start faces north, east, south or west"},
      {"open_edge.xml", ":3:1: error: cell (3,2): east wall missing on the maze's edge"},
      {"broken.xml", ":33:3: error: not well-formed XML: mismatched tag: </world> where <startPositions> of line 29 is open"},
      {"root.xml", ":2:1: error: the root element is <maze>; expected <world>"},
      {"no_walls.xml", ":1:1: error: no <wall> elements: an open arena, not a grid maze; a maze needs walls"},
  };
  for (const Case &c : cases) {
    CAPTURE(c.file);
    CHECK(load_diagnostic_of(world_fixture(c.file)) == world_fixture(c.file) + c.diagnostic);
  }
}

TEST_CASE("validation: a file that cannot be read says why") {
  CHECK(load_diagnostic_of("/nonexistent/lab.txt") == "error: cannot read /nonexistent/lab.txt: No such file or directory");
  CHECK(load_diagnostic_of(TEST_DATA_DIR) == std::string("error: cannot read ") + TEST_DATA_DIR + ": Is a directory");
}

TEST_CASE("validation: unreachable cells are a warning, not an error") {
  const auto world = maze::load_world(world_fixture("unreachable.txt"));
  REQUIRE(world.warnings.size() == 1);
  CHECK(world.warnings[0] ==
        world_fixture("unreachable.txt") + ": warning: 1 cell cannot be reached from the start: (1,0)");
  CHECK(world.maze().reachable_count() == 15);
}

TEST_CASE("validation: notes after the maze, CRLF and unknown XML elements are accepted") {
  const auto lab = maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.txt").maze();
  CHECK(maze::load_world(world_fixture("notes.txt")).maze() == lab);
  CHECK(heightless(maze::load_world(world_fixture("unknown_elements.xml")).maze()) == lab);
}

TEST_CASE("validation: the checks, one by one, on a raw maze") {
  maze::RawMaze raw;
  raw.resize(2, 1);
  for (const maze::Side s : maze::kSides) {
    raw.set({0, 0}, s, true);
    raw.set({1, 0}, s, true);
  }
  raw.where = [](maze::Cell c, maze::Side s) {
    return common::SourceLocation{"m", c.x + 1, static_cast<int>(s) + 1};
  };
  CHECK_FALSE(maze::check_enclosed(raw));
  CHECK_FALSE(maze::check_consistent(raw));
  raw.set({1, 0}, maze::Side::west, false);
  REQUIRE(maze::check_consistent(raw));
  CHECK(maze::check_consistent(raw)->diagnostic() ==
        "m:2:4: error: cell (0,0): east wall missing on the west side of (1,0)");
  raw.start = {2, 0};
  raw.start_where = {"m", 9, 1};
  CHECK(maze::check_start_inside(raw)->diagnostic() == "m:9:1: error: start (2,0) is outside the 2x1 maze");
  raw.goals = {{0, 5}};
  raw.goal_where = {{"m", 3, 2}};
  CHECK(maze::check_goals_inside(raw)->diagnostic() == "m:3:2: error: goal (0,5) is outside the 2x1 maze");
  raw.width = 5000;
  CHECK(maze::check_size(raw)->message() == "maze is 5000x1 cells; each side must be 1 to 4096");
}
