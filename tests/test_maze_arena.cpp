// Arenas: the model, its checks, the room format, the course's XML read as an arena, the
// loader's boundary rule, the truth on a grid and generated arenas. Every number below is
// worked out by hand from the fixture in the test.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <variant>

#include "common/error.hpp"
#include "maze/world/geometry.hpp"
#include "maze/generate/solids_generator.hpp"
#include "maze/world/truth_raster.hpp"
#include "maze/world/world.hpp"
#include "maze/formats/solids_format.hpp"
#include "maze/world/world.hpp"
#include "maze/formats/xml_solids.hpp"
#include "test_values.hpp"

namespace {

// The room of the format's drawing: 5 x 3 m, a 1 m box, a 0.1 m wall, start and goal.
constexpr const char *kRoom =
    "# a room\n"
    "name test room\n"
    "boundary 0 5 0 3\n"
    "rect 1 1 2 2\n"
    "wall 3 0 3 1.2 0.1   # from the south wall\n"
    "start 0.3 0.3 0\n"
    "goal 4.7 2.7\n";

std::string room_error(const std::string &text) {
  try {
    maze::validate_arena(maze::read_room(text, "f.room"), 0.1);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "no error";
}

std::string arena_error(const std::string &text, const maze::WorldOverrides &overrides = {}) {
  try {
    (void)maze::load_world_text(text, "f.room", overrides);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "no error";
}

}  // namespace

TEST_CASE("arena: obstacles from boxes and segments, flush and capped") {
  const maze::Obstacle box = maze::Obstacle::from_box(2, 1, 1, 3);
  CHECK(box.bounds() == std::array<double, 4>{1, 1, 2, 3});
  CHECK(box.axis_aligned());
  CHECK(box.contains(1, 1));  // closed
  CHECK(!box.contains(0.999, 1));
  CHECK(box.distance_m(0, 1) == 1.0);
  CHECK(box.distance_m(1.5, 2) == 0.0);

  // The course's wall: exactly as long as the segment; the maze's: half a width longer each end.
  const maze::Obstacle flush = maze::Obstacle::from_segment(0, 0, 0, 2, 0.5, maze::WallEnds::flush);
  CHECK(flush.bounds() == std::array<double, 4>{-0.25, 0, 0.25, 2});
  const maze::Obstacle capped = maze::Obstacle::from_segment(0, 0, 0, 2, 0.5, maze::WallEnds::capped);
  CHECK(capped.bounds() == std::array<double, 4>{-0.25, -0.25, 0.25, 2.25});

  // A diagonal wall from (0, 0) to (2, 2), 0.2 thick: centre (1, 1), half length sqrt(2).
  const maze::Obstacle diagonal = maze::Obstacle::from_segment(0, 0, 2, 2, 0.2, maze::WallEnds::flush);
  CHECK(!diagonal.axis_aligned());
  CHECK(diagonal.half_length_m == doctest::Approx(std::sqrt(2.0)));
  CHECK(diagonal.contains(1.05, 0.95));      // 0.07 m off the axis
  CHECK(!diagonal.contains(1.1, 0.9));       // 0.14 m off it
  CHECK(diagonal.distance_m(2, 0) == doctest::Approx(std::sqrt(2.0) - 0.1));
  const auto line = diagonal.centre_line();
  CHECK(line[0] == doctest::Approx(0.0));
  CHECK(line[3] == doctest::Approx(2.0));
  CHECK(line[4] == doctest::Approx(0.2));
  const auto b = diagonal.bounds();  // each corner 0.1 / sqrt(2) beyond the segment's ends
  CHECK(b[0] == doctest::Approx(-0.1 / std::sqrt(2.0)));
  CHECK(b[3] == doctest::Approx(2 + 0.1 / std::sqrt(2.0)));
}

TEST_CASE("room format: read, and written back as the same arena") {
  const maze::Arena a = maze::read_room(kRoom, "f.room");
  CHECK(a.name == "test room");
  CHECK(a.x_min_m == 0);
  CHECK(a.x_max_m == 5);
  CHECK(a.y_max_m == 3);
  REQUIRE(a.obstacles.size() == 2);
  CHECK(a.obstacles[0].bounds() == std::array<double, 4>{1, 1, 2, 2});
  CHECK(a.obstacles[1].bounds() == std::array<double, 4>{2.95, 0, 3.05, 1.2});
  CHECK(a.obstacles[1].where.line == 5);
  REQUIRE(a.starts.size() == 1);
  CHECK(a.starts[0].x_m == 0.3);
  CHECK(a.starts[0].yaw_rad == 0.0);
  REQUIRE(a.goals.size() == 1);
  CHECK(a.goals[0].y_m == 2.7);
  const std::string written = maze::write_room(a);
  CHECK(written ==
        "# maze_mapper arena: 2 obstacles, boundary 5 x 3 m\n"
        "name test room\n"
        "boundary 0 5 0 3\n"
        "rect 1 1 2 2\n"
        "rect 2.95 0 3.05 1.2\n"
        "start 0.3 0.3 0\n"
        "goal 4.7 2.7\n");
  CHECK(maze::write_room(maze::read_room(written, "g.room")) == written);
  // The yaw defaults to north; a start's yaw is in degrees.
  CHECK(maze::read_room("start 1 1\n", "f").starts[0].yaw_rad == doctest::Approx(kPi / 2));
  CHECK(maze::read_room("start 1 1 -90\n", "f").starts[0].yaw_rad == doctest::Approx(-kPi / 2));
  // CRLF, a byte-order mark, tabs and comments.
  CHECK(maze::read_room("\xEF\xBB\xBF# c\r\n\trect\t0 0 1 1\r\n", "f").obstacles.size() == 1);
}

TEST_CASE("room format: a slanted wall's end at 0 is written 0, and the written room writes the same text again") {
  // A wall 49 m long from (50, 0): its ends come from its centre, half length and angle, and
  // the end at y = 0 came out 1.94e-15, then 2.91e-15 on the next round (found by fuzz_room).
  const std::string written = maze::write_room(maze::read_room("boundary 1 5 0 3\nwall 50 0 1 0.2\n", "w.room"));
  CHECK(written ==
        "# maze_mapper arena: 1 obstacle, boundary 4 x 3 m\n"
        "boundary 1 5 0 3\n"
        "wall 50 0 1 0.2 0.012\n");
  CHECK(maze::write_room(maze::read_room(written, "w.room")) == written);
}

TEST_CASE("room format: a wall a picometre off an axis is written as the rectangle it reads back as") {
  // Its end at y = 4e-12 is written 0 on the wall's scale, so the text read back is a
  // horizontal wall, which the writer writes as a rect (found by fuzz_room).
  const std::string written =
      maze::write_room(maze::read_room("boundary -5 5 -5 5\nwall 1.5 .0 1.0 0.0000000000040002\n", "w.room"));
  CHECK(written ==
        "# maze_mapper arena: 1 obstacle, boundary 10 x 10 m\n"
        "boundary -5 5 -5 5\n"
        "rect 1 -0.006 1.5 0.006\n");
  CHECK(maze::write_room(maze::read_room(written, "w.room")) == written);
}

TEST_CASE("room format: a wall whose longest coordinate reads back a hair under a power of ten writes the same text again") {
  // Its end 1.0 came back 0.99999999999999989, whose rounding step is ten times finer: the end
  // 0.0800000000040002 was written 0.080000000004, then 0.08 (found by fuzz_room).
  const std::string written =
      maze::write_room(maze::read_room("boundary -5 5 -5 5\nwall .15 .0 1.0 0.0800000000040002\n", "w.room"));
  CHECK(written ==
        "# maze_mapper arena: 1 obstacle, boundary 10 x 10 m\n"
        "boundary -5 5 -5 5\n"
        "wall 0.15 0 1 0.08 0.012\n");
  CHECK(maze::write_room(maze::read_room(written, "w.room")) == written);
}

TEST_CASE("room format: a rectangle with no area at the 12 digits the format keeps is refused, as written back it would be") {
  // 4e-12 m high: written "rect -5 1 0 1", which has no area (found by fuzz_room).
  CHECK_THROWS_WITH_AS(maze::read_room("boundary -5 5 -5 5\nrect -5. 1 0.0 1.0000000000040002\n", "r.room"),
                       "the rectangle (-5, 1)-(0, 1.0000000000040001) has no area", common::InputError);
}

TEST_CASE("room format: a wall on an axis too thin for the 12 digits the format keeps is refused, as its rectangle would be") {
  // 5e-59 m wide: written "rect 1.5 0.5 1.5 1.4", which has no area (found by fuzz_room).
  CHECK_THROWS_WITH_AS(maze::read_room("boundary 0 2 0 2\nwall 1.5 0.5 1.5 1.4 5e-59\n", "w.room"),
                       "the wall from (1.5, 0.5) to (1.5, 1.4), 5e-59 m wide, has no area at the 12 significant "
                       "digits the format keeps",
                       common::InputError);
  const maze::Arena thin = maze::read_room("boundary 0 2 0 2\nwall 1.5 0.5 1.5 1.4 1e-6\n", "w.room");
  CHECK(maze::write_room(thin).find("rect 1.4999995 0.5 1.5000005 1.4\n") != std::string::npos);
}

TEST_CASE("room format: a boundary empty at the 12 digits the format keeps is refused, and a thin one's size is written as it reads back") {
  // y 5 to 5.000000000004: written "boundary -5 5 5 5" (found by fuzz_room).
  CHECK_THROWS_WITH_AS(maze::read_room("boundary -5 5 5 5.000000000004\n", "b.room"),
                       "the boundary x -5 to 5 m, y 5 to 5.000000000004 m is empty at the 12 significant digits the "
                       "format keeps",
                       common::InputError);
  // 9.14326321e-9 m high: the header's size is the written boundary's, so the text holds.
  const std::string written = maze::write_room(maze::read_room("boundary -5 5 5 5.00000000914326321\n", "b.room"));
  CHECK(written.starts_with("# maze_mapper arena: 0 obstacles, boundary 10 x 9.14e-09 m\n"));
  CHECK(maze::write_room(maze::read_room(written, "b.room")) == written);
}

TEST_CASE("room format: a name ending in a carriage return before a comment loses it, and writes the same text again") {
  // "name o \x7f\r # ..." kept "o \x7f\r", written as "name o \x7f\r\n", read back as "o \x7f"
  // (found by fuzz_room).
  const maze::Arena a = maze::read_room("name o \x7f\r #comment\nboundary 0 5 0 3\n", "n.room");
  CHECK(a.name == "o \x7f");
  const std::string written = maze::write_room(a);
  CHECK(maze::write_room(maze::read_room(written, "n.room")) == written);
  CHECK(maze::read_room("name a b\t \r\n", "n.room").name == "a b");
}

TEST_CASE("room format: detected by content, after comments and blank lines") {
  CHECK(maze::detect_format(kRoom, "f") == maze::Format::room);
  CHECK(maze::detect_format("\n\n   # x\nrect 0 0 1 1\n", "f") == maze::Format::room);
  CHECK_THROWS_AS(maze::detect_format("# only a comment\n", "f"), common::InputError);
  CHECK_THROWS_AS(maze::detect_format("bondary 0 5 0 3\n", "f"), common::InputError);
  CHECK(maze::detect_format("o---o\n", "f") == maze::Format::text_map);
  CHECK(maze::format_for_output("x/ROOM.Room") == maze::Format::room);
}

TEST_CASE("room format: errors name the line and the column of the token at fault") {
  CHECK(room_error("boundary 0 5 0\n") == "f.room:1:1: error: boundary takes 4 numbers XS XE YS YE: got 3 numbers");
  CHECK(room_error("boundary 0 5 0 3 4\n") ==
        "f.room:1:18: error: boundary takes 4 numbers XS XE YS YE: got 5 numbers");
  CHECK(room_error("# c\nrect 1 1 x 2\n") == "f.room:2:10: error: 'x' is not a number");
  CHECK(room_error("start 1 inf\n") == "f.room:1:9: error: 'inf' is not a finite number of metres");
  CHECK(room_error("start +1 1\n") == "f.room:1:7: error: '+1' is not a number");
  CHECK(room_error("wall 0 0 1 1 0\n") == "f.room:1:14: error: the width must be positive, got 0");
  CHECK(room_error("wall 1 1 1 1\n") == "f.room:1:1: error: the wall from (1, 1) to (1, 1) has zero length");
  CHECK(room_error("  rect 0 0 0 1\n") == "f.room:1:3: error: the rectangle (0, 0)-(0, 1) has no area");
  CHECK(room_error("boundary 2 1 0 3\n") ==
        "f.room:1:1: error: the boundary x 2 to 1 m, y 0 to 3 m is empty: it needs XS < XE and YS < YE");
  CHECK(room_error("boundary 0 5 0 3\nboundary 0 5 0 3\n") ==
        "f.room:2:1: error: a second boundary (the first is at line 1)");
  CHECK(room_error("rect 0 0 1 1\nbox 0 0 1 1\n") ==
        "f.room:2:1: error: unknown statement 'box': expected name, boundary, rect, wall, start or goal");
  CHECK(room_error("name\n") == "f.room:1:1: error: name takes a text: got none");
}

TEST_CASE("arena validation: each check says what failed, at the element") {
  const std::string head = "boundary 0 5 0 3\nrect 1 1 2 2\n";
  CHECK(room_error(head + "start 1.5 1.5\n") == "f.room:3:1: error: start (1.5, 1.5) is inside the obstacle at line 2");
  CHECK(room_error(head + "start 0.95 1.5\n") ==
        "f.room:3:1: error: a robot of radius 0.1 m at start (0.95, 1.5) touches the obstacle at line 2");
  CHECK(room_error(head + "start 0.05 1.5\n") ==
        "f.room:3:1: error: a robot of radius 0.1 m at start (0.05, 1.5) touches the boundary x 0 to 5 m, y 0 to 3 m");
  CHECK(room_error(head + "start 6 1\n") == "f.room:3:1: error: start (6, 1) is outside the boundary x 0 to 5 m, y 0 to 3 m");
  CHECK(room_error(head + "start 0.5 0.5\ngoal 4.7 3.2\n") ==
        "f.room:4:1: error: goal (4.7, 3.2) is outside the boundary x 0 to 5 m, y 0 to 3 m");
  CHECK(room_error(head + "start 0.5 0.5\ngoal 4.7 2.9\n") == "no error");
  maze::Arena big;
  big.x_max_m = 2000;
  big.y_max_m = 1;
  CHECK(maze::check_arena_size(big)->diagnostic() == "error: the boundary spans 2000 x 1 m; each side must be at most 1000 m");
  maze::Arena nan;
  nan.x_max_m = std::nan("");
  CHECK(maze::check_arena_finite(nan)->diagnostic() == "error: the boundary has a non-finite coordinate");
}

TEST_CASE("arena loader: the boundary is the file's, the user's, the walls' box when they enclose, else the floor") {
  // No boundary, obstacles not enclosing the start: the course's floor.
  const maze::World open = maze::load_world_text("rect 1 1 2 2\nstart 0 0\n", "f.room", {});
  CHECK(open.arena().x_min_m == -8.5);
  CHECK(open.arena().x_max_m == 8.5);
  CHECK(open.arena().y_min_m == -8.5);
  CHECK(open.arena().name == "f");
  // No boundary, four walls round the start: their box.
  const maze::World walled = maze::load_world_text(
      "wall 0 0 4 0 0.2\nwall 0 2 4 2 0.2\nwall 0 0 0 2 0.2\nwall 4 0 4 2 0.2\nstart 1 1\n", "f.room", {});
  CHECK(walled.arena().x_min_m == -0.1);
  CHECK(walled.arena().x_max_m == 4.1);
  CHECK(walled.arena().y_min_m == -0.1);
  CHECK(walled.arena().y_max_m == 2.1);
  // --boundary wins over the file's.
  maze::WorldOverrides user;
  user.boundary_m = std::array<double, 4>{-1, 6, -1, 4};
  CHECK(maze::load_world_text(kRoom, "f.room", user).arena().x_max_m == 6);
  user.boundary_m = std::array<double, 4>{1, 0, 0, 1};
  CHECK(arena_error(kRoom, user) == "error: --boundary 1,0,0,1: XS < XE and YS < YE");
  // The start is checked against the robot's radius.
  maze::WorldOverrides robot;
  robot.robot_radius_m = 0.35;
  CHECK(arena_error(kRoom, robot) ==
        "f.room:6:1: error: a robot of radius 0.35 m at start (0.3, 0.3) touches the boundary x 0 to 5 m, y 0 to 3 m");
}

TEST_CASE("course XML: thick walls, diagonal walls and no walls are arenas; a maze stays a maze") {
  CHECK(maze::xml_world_is_arena("<world/>", "f.xml", {}));
  CHECK(maze::xml_world_is_arena(R"(<world><wall x1="0" y1="0" x2="1" y2="1"/></world>)", "f.xml", {}));
  CHECK(maze::xml_world_is_arena(R"(<world><wall x1="0" y1="0" x2="2" y2="0" width="0.5"/></world>)", "f.xml", {}));
  CHECK(!maze::xml_world_is_arena(R"(<world><wall x1="0" y1="0" x2="2" y2="0" width="0.49"/></world>)", "f.xml", {}));
  // A stated cell size or --cell-size means a maze (its errors are the maze reader's).
  CHECK(!maze::xml_world_is_arena(R"(<world cellSize="1"><wall x1="0" y1="0" x2="1" y2="1"/></world>)", "f.xml", {}));
  CHECK(!maze::xml_world_is_arena("<world/>", "f.xml", maze::XmlReadOptions{1.0}));

  const maze::World thick = maze::load_world(world_fixture("thick_obstacles.xml"));
  REQUIRE(!thick.on_lattice());
  const maze::Arena &a = thick.arena();
  REQUIRE(a.obstacles.size() == 5);
  // The course's rule: a box as long as the segment, `width` across it.
  CHECK(a.obstacles[0].bounds() == std::array<double, 4>{-3, -3.5, 3, -2.5});
  CHECK(a.obstacles[2].bounds() == std::array<double, 4>{-3.5, -3, -2.5, 3});
  CHECK(a.obstacles[4].bounds() == std::array<double, 4>{-1, -0.5, 1, 0.5});
  CHECK(a.obstacles[4].where.line == 8);
  // Its four walls enclose the start: bounded by their box, not the 17 m floor.
  CHECK(a.x_min_m == -3.5);
  CHECK(a.y_max_m == 3.5);
  CHECK(a.starts[0].x_m == -2);
  CHECK(a.starts[0].yaw_rad == 1.57079633);

  const maze::World lab = maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.xml");
  REQUIRE(lab.on_lattice());
  CHECK(lab.maze() == maze::read_world(maze::read_file(std::string(WORLDS_DIR) + "/lab4x4.xml"), "lab4x4.xml"));
  // An arena's lattice view is refused, in the maze reader's own words and the command that maps it.
  CHECK_THROWS_WITH_AS((void)thick.maze(),
                       doctest::Contains("are obstacles in an arena, not a grid maze (its walls are thinner than a "
                                         "quarter of a cell); it reads as an arena (a room of obstacles): map it with "
                                         "`maze_mapper room "),
                       common::InputError);
}

TEST_CASE("course XML arenas: written and read back; options that do not apply are refused") {
  const maze::Arena a = maze::read_room(kRoom, "f.room");
  const std::string xml = maze::write_xml_arena(a);
  CHECK(xml ==
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<!-- maze_mapper arena: 2 obstacles, boundary 5 x 3 m -->\n<world name=\"test room\">\n"
        "  <boundary xs=\"0\" xe=\"5\" ys=\"0\" ye=\"3\"/>\n"
        "  <wall x1=\"1\" y1=\"1.5\" x2=\"2\" y2=\"1.5\" width=\"1\"/>\n"
        "  <wall x1=\"3\" y1=\"0\" x2=\"3\" y2=\"1.2\" width=\"0.1\"/>\n"
        "  <startPositions>\n    <pos x=\"0.3\" y=\"0.3\" theta=\"0\"/>\n  </startPositions>\n"
        "  <goal id=\"0\" x=\"4.7\" y=\"2.7\"/>\n</world>\n");
  const maze::World back = maze::load_world_text(xml, "b.xml", {});
  CHECK(back.format == maze::Format::xml);
  REQUIRE(back.arena().obstacles.size() == 2);
  CHECK(back.arena().obstacles[0].bounds() == a.obstacles[0].bounds());
  CHECK(back.arena().obstacles[1].bounds() == a.obstacles[1].bounds());
  CHECK(maze::write_room(back.arena()) == maze::write_room(maze::read_room(maze::write_room(back.arena()), "c")));
  CHECK(back.arena().x_max_m == 5);
  CHECK(back.arena().name == "test room");
  // A yaw at any angle goes through degrees and back exactly.
  maze::Arena turned = a;
  turned.starts[0].yaw_rad = 0.785398;
  CHECK(maze::read_room(maze::write_room(turned), "t").starts[0].yaw_rad == 0.785398);
  CHECK_THROWS_WITH_AS(maze::format_arena(a, maze::Format::num),
                       "a num file holds a grid maze; an arena is written as .room or .xml", common::InputError);

  maze::WorldOverrides cells;
  cells.cell_size_m = 1.0;
  // --cell-size asks for a maze: the XML is read as one (and fails as one).
  CHECK_THROWS_WITH_AS(maze::load_world(world_fixture("thick_obstacles.xml"), cells),
                       doctest::Contains("are obstacles in an arena, not a grid maze"), common::InputError);
  maze::WorldOverrides start;
  start.start = maze::Cell{1, 1};
  CHECK_THROWS_WITH_AS(maze::load_world(world_fixture("thick_obstacles.xml"), start),
                       doctest::Contains("--start names cells of a grid maze"), common::InputError);
  maze::WorldOverrides boundary;
  boundary.boundary_m = std::array<double, 4>{0, 1, 0, 1};
  CHECK_THROWS_WITH_AS(maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.txt", boundary),
                       doctest::Contains("--boundary applies to arenas"), common::InputError);
}

TEST_CASE("a maze as an arena: capped walls, the start and goals at cell centres") {
  const maze::Maze lab = maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.txt").maze();
  const maze::Arena a = maze::arena_from_maze(lab);
  CHECK(a.x_max_m == 4);
  CHECK(a.starts[0].x_m == 0.5);
  CHECK(a.starts[0].yaw_rad == doctest::Approx(kPi / 2));
  CHECK(a.goals[0].x_m == 3.5);
  // The south edge, one wall of 4 m: capped, 4.012 m long.
  bool south_edge = false;
  for (const maze::Obstacle &o : a.obstacles) {
    const auto b = o.bounds();
    south_edge = south_edge || (std::abs(b[0] + 0.006) < 1e-12 && std::abs(b[1] + 0.006) < 1e-12 &&
                                std::abs(b[2] - 4.006) < 1e-12 && std::abs(b[3] - 0.006) < 1e-12);
  }
  CHECK(south_edge);
  maze::validate_arena(a, 0.1);
}

TEST_CASE("truth: cells occupied by any overlap; reachable by the robot's body from the start") {
  // 4 x 2 m, 1 m cells; a 0.2 m wall across x = 2 from y = 0 to 1.5 (cells (1,0), (2,0),
  // (1,1) and (2,1) each overlap it); start in (0, 0).
  const maze::Arena a = maze::read_room("boundary 0 4 0 2\nwall 2 0 2 1.5 0.2\nstart 0.5 0.5\n", "f");
  const maze::TruthRaster t = maze::rasterise_truth(a, 4, 2, 0.0);
  CHECK(t.occupied == std::vector<std::uint8_t>{0, 1, 1, 0, 0, 1, 1, 0});
  CHECK(t.occupied_count == 4);
  CHECK(t.free_count == 4);
  // With radius 0 the free cells 4-connected to (0,0): only (0,1) joins it; (3,0), (3,1) are
  // cut off by the occupied column pair.
  CHECK(t.reachable == std::vector<std::uint8_t>{1, 0, 0, 0, 1, 0, 0, 0});
  // At 0.5 m cells: the wall (x 1.9 to 2.1, y 0 to 1.5) occupies columns 3 and 4, rows 0 to 2;
  // row 3 is open above it, so the east part is reachable with radius 0.
  const maze::TruthRaster fine = maze::rasterise_truth(a, 8, 4, 0.0);
  CHECK(fine.occupied_count == 6);
  CHECK(fine.reachable_count == 26);
  // A robot of radius 0.3 m: centres 0.3 m from the wall and the boundary, so only columns 1,
  // 2, 5, 6 and rows 1, 2 (the centres at 0.25 m from the boundary or 0.15 m from the wall
  // are not); from the start's cell (1, 1) the centres reach (1..2, 1..2), the wall's band cuts
  // off the east. The reach, 0.3 m and half a diagonal of 0.5 m cells (0.354 m), adds the
  // free 4-neighbours of those four (0.5 m away; the diagonals, 0.707 m, are beyond it).
  const maze::TruthRaster body = maze::rasterise_truth(a, 8, 4, 0.3);
  CHECK(body.reachable_count == 10);
  CHECK(body.is_reachable(0, 1));
  CHECK(!body.is_reachable(0, 0));
  CHECK(!body.is_reachable(5, 1));
  // A landmark's cylinder, radius 0.25 m at (3.5, 1): it overlaps cells (3,0) and (3,1) only
  // (it touches none of column 2), and cuts nothing off.
  maze::Arena with_disc = a;
  with_disc.discs.push_back({3.5, 1.0, 0.25});
  const maze::TruthRaster disc = maze::rasterise_truth(with_disc, 4, 2, 0.0);
  CHECK(disc.occupied == std::vector<std::uint8_t>{0, 1, 1, 1, 0, 1, 1, 1});
  CHECK(disc.reachable == t.reachable);
  CHECK_THROWS_WITH_AS(maze::rasterise_truth(a, 20000, 20000, 0.0),
                       "a grid of 20000 x 20000 cells is too fine: at most 67108864 cells", common::InputError);
}

TEST_CASE("truth at the map's resolution: a gap is passable when a body clear of the occupied cells fits") {
  // A wall across y = 1 with a 0.31 m gap (x 0.81 to 1.12); a 0.09 m body; the north half
  // beyond it. At 0.1 m cells the gap leaves two free columns (0.9 to 1.1): the centre clears
  // the wall itself (0.14 m) but not the occupied cells (0.05 m), so the map cannot show the
  // body passing; at 0.05 m it leaves five, the middle one 0.125 m from the occupied cells.
  const maze::Arena a = maze::read_room(
      "boundary 0 2 0 2\nrect 0 0.95 0.81 1.05\nrect 1.12 0.95 2 1.05\nstart 0.5 0.5\n", "f");
  const maze::TruthRaster to_wall = maze::rasterise_truth(a, 20, 20, 0.09);
  const maze::TruthRaster to_cells = maze::rasterise_truth(a, 20, 20, 0.09, maze::TruthClearance::to_occupied_cells);
  CHECK(to_wall.is_reachable(10, 15));
  CHECK(!to_cells.is_reachable(10, 15));
  CHECK(to_cells.is_reachable(10, 5));
  const maze::TruthRaster finer = maze::rasterise_truth(a, 40, 40, 0.09, maze::TruthClearance::to_occupied_cells);
  CHECK(finer.is_reachable(20, 30));
}

TEST_CASE("truth: a rotated obstacle marks exactly the cells its area meets") {
  // A square of side sqrt(2) m turned 45 degrees about (2, 2): a diamond reaching 1 m each way.
  maze::Arena a = maze::read_room("boundary 0 4 0 4\nstart 0.5 0.5\n", "f");
  a.obstacles.push_back(maze::Obstacle::oriented(2, 2, std::sqrt(0.5), std::sqrt(0.5), kPi / 4));
  const maze::TruthRaster t = maze::rasterise_truth(a, 4, 4, 0.0);
  // The diamond's corners touch (1, 2), (3, 2), (2, 1), (2, 3): the four central cells only.
  CHECK(t.occupied == std::vector<std::uint8_t>{0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 0, 0, 0});
}

TEST_CASE("generated arenas: the same for the same seed, start and goal clear, validated") {
  maze::ArenaGeneration g;
  g.seed = 7;
  g.width_m = 8;
  g.height_m = 6;
  g.obstacles = 12;
  g.rotated = true;
  const maze::Arena a = maze::generate_arena(g);
  CHECK(maze::write_room(a) == maze::write_room(maze::generate_arena(g)));
  g.seed = 8;
  CHECK(maze::write_room(a) != maze::write_room(maze::generate_arena(g)));
  CHECK(a.obstacles.size() == 12);
  for (const maze::Obstacle &o : a.obstacles) {
    CHECK(o.distance_m(0.5, 0.5) > 0.3);
    CHECK(o.distance_m(7.5, 5.5) > 0.3);
  }
  g.width_m = 0.5;
  CHECK_THROWS_WITH_AS(maze::generate_arena(g), "a generated arena is 1 to 1000 m a side (got 0.5 x 6 m)",
                       common::InputError);
}

TEST_CASE("shipped arenas load, validate for their robots, and reach their goals") {
  struct Shipped {
    const char *file;
    double robot_radius_m;
    std::size_t obstacles;
  };
  // ir-ring's and the homework's bumper robot's bodies (0.09 m; the Create's bump radius 0.16 m).
  for (const Shipped &s : {Shipped{"ir_room.room", 0.09, 4}, Shipped{"obstacle_field.room", 0.16, 10},
                          Shipped{"thick_arena.xml", 0.09, 9}}) {
    CAPTURE(s.file);
    maze::WorldOverrides robot;
    robot.robot_radius_m = s.robot_radius_m;
    const maze::World any = maze::load_world(std::string(WORLDS_DIR) + "/" + s.file, robot);
    REQUIRE(!any.on_lattice());
    const maze::World &w = any;
    CHECK(w.warnings.empty());
    CHECK(w.arena().obstacles.size() == s.obstacles);
    REQUIRE(w.arena().goals.size() == 1);
    const maze::Arena &a = w.arena();
    const maze::TruthRaster t = maze::rasterise_truth(a, maze::cells_along(a.width_m(), 0.1),
                                                     maze::cells_along(a.height_m(), 0.1), s.robot_radius_m);
    const int gx = static_cast<int>((a.goals[0].x_m - a.x_min_m) / t.cell_x_m);
    const int gy = static_cast<int>((a.goals[0].y_m - a.y_min_m) / t.cell_y_m);
    CHECK(t.is_reachable(gx, gy));
    CHECK(t.reachable_count > t.free_count * 8 / 10);
  }
  // The IR room is the assignment's: 5 x 3 m, start [0.3, 0.3], goal [4.7, 2.7].
  const maze::Arena room = maze::load_world(std::string(WORLDS_DIR) + "/ir_room.room").arena();
  CHECK(room.width_m() == 5);
  CHECK(room.height_m() == 3);
  CHECK(room.starts[0].x_m == 0.3);
  CHECK(room.goals[0].x_m == 4.7);
  // The course-style arena is walled all round, the walls' outer faces on the course's 17 x 17 m
  // floor, so their box is its boundary.
  const maze::Arena thick = maze::load_world(std::string(WORLDS_DIR) + "/thick_arena.xml").arena();
  CHECK(thick.x_min_m == -8.5);
  CHECK(thick.y_max_m == 8.5);
}

TEST_CASE("every file in worlds/ loads as a maze or an arena") {
  int arenas = 0;
  int mazes = 0;
  for (const auto &entry : std::filesystem::directory_iterator(WORLDS_DIR)) {
    if (entry.path().filename() == "README.md") continue;
    CAPTURE(entry.path().string());
    const maze::World world = maze::load_world(entry.path().string());
    (!world.on_lattice() ? arenas : mazes) += 1;
  }
  CHECK(arenas == 3);
  CHECK(mazes >= 8);
}

TEST_CASE("one load: the file's format told once, a world's geometry and its lattice view") {
  const std::string worlds = WORLDS_DIR;
  const maze::WorldText lab = maze::read_world_file(worlds + "/lab4x4.xml");
  CHECK(lab.format == maze::Format::xml);
  CHECK_FALSE(maze::holds_arena(lab.text, lab.format, "lab4x4.xml"));
  const maze::WorldText room = maze::read_world_file(worlds + "/ir_room.room");
  CHECK(room.format == maze::Format::room);
  CHECK(maze::holds_arena(room.text, room.format, "ir_room.room"));
  const maze::WorldText thick = maze::read_world_file(worlds + "/thick_arena.xml");
  CHECK(maze::holds_arena(thick.text, thick.format, "thick_arena.xml"));

  // A maze: its lattice is the maze, its geometry the walls as solids (arena_from_maze).
  const maze::World maze_world = maze::load_world(worlds + "/lab4x4.txt");
  REQUIRE(maze_world.lattice() != nullptr);
  CHECK(maze_world.lattice()->width() == 4);
  const maze::Arena maze_geometry = maze_world.geometry();
  CHECK(maze_geometry.obstacles.size() == maze::arena_from_maze(*maze_world.lattice()).obstacles.size());
  CHECK(maze_geometry.x_max_m == 4);
  // An arena: no lattice, its geometry its own.
  const maze::World arena_world = maze::load_world(worlds + "/ir_room.room");
  CHECK(arena_world.lattice() == nullptr);
  CHECK(arena_world.geometry().obstacles.size() == arena_world.arena().obstacles.size());
  CHECK(arena_world.warnings.empty());
}

TEST_CASE("course XML arena: a landmark is a solid cylinder in its colour, written back as it was read") {
  const std::string xml =
      "<world><wall x1=\"0\" y1=\"0\" x2=\"3\" y2=\"1\" width=\"0.1\"/>"
      "<landmark x=\"-2.5\" y=\"2.5\" height=\"1\" red=\"0\" green=\"1\" blue=\"0.5\"/>"
      "<startPositions><pos x=\"0\" y=\"2\"/></startPositions></world>";
  const maze::World world = maze::load_world_text(xml, "l.xml");
  REQUIRE(!world.on_lattice());
  CHECK(world.warnings.empty());
  REQUIRE(world.arena().discs.size() == 1);
  const maze::ArenaDisc &d = world.arena().discs[0];
  CHECK(d.centre_x_m == -2.5);
  CHECK(d.centre_y_m == 2.5);
  CHECK(d.radius_m == maze::kLandmarkRadius_m);
  REQUIRE(d.landmark.has_value());
  CHECK(d.landmark->height_m == 1.0);
  CHECK(d.landmark->green == 1.0);
  CHECK(d.landmark->blue == 0.5);
  const std::string written = maze::format_arena(world.arena(), maze::Format::xml);
  CHECK(written.find("<landmark x=\"-2.5\" y=\"2.5\" height=\"1\" red=\"0\" green=\"1\" blue=\"0.5\"/>") !=
        std::string::npos);
  CHECK(maze::load_world_text(written, "back.xml").arena().discs.size() == 1);
  CHECK(maze::dropped_by(world.arena(), maze::Format::room) ==
        "dropped 1 landmark: a room file holds the walls as rectangles, the start and the goals");
  CHECK(!maze::dropped_by(world.arena(), maze::Format::xml));
}

TEST_CASE("a maze's geometry holds its landmarks as cylinders in their colour") {
  maze::Maze m(2, 2);
  m.set_landmarks({maze::Landmark{1.5, 0.5, 0.5, 1.0, 0.0, 0.0}});
  const maze::Arena g = maze::arena_from_maze(m);
  REQUIRE(g.discs.size() == 1);
  CHECK(g.discs[0].centre_x_m == 1.5);
  CHECK(g.discs[0].radius_m == maze::kLandmarkRadius_m);
  REQUIRE(g.discs[0].landmark.has_value());
  CHECK(g.discs[0].landmark->red == 1.0);
  CHECK(g.discs[0].landmark->green == 0.0);
}
