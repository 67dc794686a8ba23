// Round trips between the formats, for every file in worlds/ and for generated mazes; the
// canonical text map; the Webots writer; safe writes.
#include <doctest/doctest.h>

#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "maze/generate/generator.hpp"
#include "maze/formats/num_format.hpp"
#include "maze/formats/text_map.hpp"
#include "maze/formats/wbt_format.hpp"
#include "maze/world/world.hpp"
#include "maze/formats/xml_solids.hpp"
#include "maze/formats/xml_format.hpp"
#include "test_values.hpp"

namespace {

// The mazes in worlds/ (its arenas have their own tests: test_maze_arena.cpp).
std::vector<std::string> world_files() {
  std::vector<std::string> files;
  for (const auto &entry : std::filesystem::directory_iterator(WORLDS_DIR)) {
    const auto ext = entry.path().extension();
    const std::string file = entry.path().string();
    if (ext == ".xml" && maze::xml_world_is_arena(maze::read_file(file), file, {})) continue;
    if (ext == ".txt" || ext == ".num" || ext == ".xml") files.push_back(file);
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool same_walls(const maze::Maze &a, const maze::Maze &b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      for (const maze::Side s : maze::kSides) {
        if (a.has_wall({x, y}, s) != b.has_wall({x, y}, s)) return false;
      }
    }
  }
  return a.start() == b.start() && a.start_heading() == b.start_heading();
}

// m moved so that its centre is the origin, as convert writes XML by default.
maze::Maze centred(maze::Maze m) {
  const double s = m.cell_size_m();
  m.set_physical(s, m.wall_thickness_m(), -m.width() * s / 2.0, -m.height() * s / 2.0);
  return m;
}

void check_round_trips(const maze::Maze &m) {
  // The text map and XML keep everything our worlds use; num keeps walls and the start.
  // (The text map states no wall height, the XML the course's 0.5 m: compared without it.)
  CHECK(maze::read_text_map(maze::write_text_map(m), "t") == heightless(m));
  CHECK(heightless(maze::read_xml(maze::write_xml_keeping_origin(m), "x")) == heightless(m));
  CHECK(maze::read_xml(maze::write_xml_keeping_origin(m), "x").wall_height_m() == maze::kCourseWallHeight_m);
  const std::string xml = maze::write_xml(m);
  CHECK(heightless(maze::read_xml(xml, "x")) == heightless(centred(m)));
  CHECK(maze::write_xml(maze::read_xml(xml, "x")) == xml);
  // Each run of collinear walls is one <wall>.
  std::size_t walls = 0;
  for (std::size_t at = xml.find("<wall "); at != std::string::npos; at = xml.find("<wall ", at + 1)) ++walls;
  CHECK(walls == m.wall_segments().size());
  const maze::Maze from_num = maze::read_num(maze::write_num(m), "n");
  CHECK(same_walls(from_num, m));
  CHECK(from_num.goals().empty());
  // Through every format and back to the same canonical bytes.
  const std::string text = maze::write_text_map(m);
  CHECK(maze::write_text_map(maze::read_xml(maze::write_xml(maze::read_text_map(text, "t")), "x")) == text);
}

}  // namespace

TEST_CASE("formats: every world in worlds/ reads, and round-trips through text, num and XML") {
  const auto files = world_files();
  CHECK(files.size() >= 8);
  for (const auto &file : files) {
    CAPTURE(file);
    const maze::World world = maze::load_world(file);
    CHECK(world.warnings.empty());
    CHECK(world.maze().reachable_count() ==
          static_cast<std::size_t>(world.maze().width()) * static_cast<std::size_t>(world.maze().height()));
    check_round_trips(world.maze());
  }
}

TEST_CASE("formats: a canonical text map shows as the same bytes") {
  for (const auto &file : world_files()) {
    if (!file.ends_with(".txt")) continue;
    CAPTURE(file);
    const std::string text = maze::read_file(file);
    CHECK(maze::write_text_map(maze::read_text_map(text, file)) == text);
  }
}

TEST_CASE("formats: lab4x4 is the same maze as text, num and XML") {
  const std::string dir = WORLDS_DIR;
  const auto text = maze::load_world(dir + "/lab4x4.txt").maze();
  CHECK(heightless(maze::load_world(dir + "/lab4x4.xml").maze()) == text);
  CHECK(same_walls(maze::load_world(dir + "/lab4x4.num").maze(), text));
  CHECK(text.width() == 4);
  CHECK(text.start() == maze::Cell{0, 0});
  CHECK(text.start_heading() == maze::Side::north);
  CHECK(text.goals() == std::vector<maze::Cell>{{3, 3}});
}

TEST_CASE("formats: generated mazes round-trip, loops and all three algorithms") {
  for (const auto algorithm : {maze::Algorithm::dfs, maze::Algorithm::kruskal, maze::Algorithm::prim}) {
    for (const double loops : {0.0, 0.3, 1.0}) {
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        check_round_trips(maze::generate_maze({7, 5, seed, loops, algorithm}));
      }
    }
  }
  check_round_trips(maze::generate_maze({1, 1, 1, 0.0, maze::Algorithm::dfs}));
  check_round_trips(maze::generate_maze({1, 9, 1, 0.0, maze::Algorithm::prim}));
}

TEST_CASE("formats: the text map reads '+' posts, S and G anywhere in a cell, and CRLF") {
  const maze::Maze m = maze::read_text_map("+---+---+\r\n|G      |\r\n+   +---+\r\n|  S|   |\r\n+---+---+\r\n", "f");
  CHECK(m.width() == 2);
  CHECK(m.height() == 2);
  CHECK(m.start() == maze::Cell{0, 0});
  CHECK(m.goals() == std::vector<maze::Cell>{{0, 1}});
  CHECK(m.has_wall({0, 0}, maze::Side::east));
  CHECK(!m.has_wall({0, 0}, maze::Side::north));
  CHECK(m.has_wall({1, 0}, maze::Side::north));
  CHECK(maze::write_text_map(m) == "o---o---o\n| G     |\no   o---o\n| S |   |\no---o---o\n");
}

// Regression (the CI fuzz run, 2026-11-22): 0.02 m cells 200 to a side. Written walls end at
// x * 0.02 computed in doubles, so the shortest wall read back measured 0.019999999999999574
// m, not the cell size: the reread maze differed. The writer now states cellSize.
TEST_CASE("formats: XML written and read back is the same maze, small cells far from the origin") {
  std::string xml = "<world>";
  const auto wall = [&xml](double x1, double y1, double x2, double y2) {
    xml += fmt::format("<wall x1='{}' y1='{}' x2='{}' y2='{}' width='0.004'/>", x1, y1, x2, y2);
  };
  wall(0, 0, 4, 0);
  wall(0, 0.02, 4, 0.02);
  wall(0, 0, 0, 0.02);
  wall(4, 0, 4, 0.02);
  wall(2, 0, 2, 0.02);  // one cell long: the cell size, 0.02 m
  xml += "</world>";
  const maze::Maze m = maze::read_xml(xml, "f");
  REQUIRE(m.width() == 200);
  const std::string written = maze::write_xml_keeping_origin(m);
  const maze::Maze again = maze::read_xml(written, "g");
  CHECK(again.cell_size_m() == m.cell_size_m());
  CHECK(again == m);
  CHECK(maze::write_xml_keeping_origin(again) == written);
}

TEST_CASE("formats: without an S the start is the south-west cell facing north") {
  const maze::Maze m = maze::read_text_map("o---o---o\n|       |\no---o---o\n", "f");
  CHECK(m.start() == maze::Cell{0, 0});
  CHECK(m.start_heading() == maze::Side::north);
}

TEST_CASE("formats: XML infers cell size and origin, reads runs, start heading and goals") {
  const char *xml = R"(<world>
  <wall x1="-0.5" y1="1" x2="0.1" y2="1" width="0.01"/>
  <wall x1="-0.5" y1="1.6" x2="0.1" y2="1.6" width="0.01"/>
  <wall x1="-0.5" y1="1" x2="-0.5" y2="1.6" width="0.01"/>
  <wall x1="0.1" y1="1" x2="0.1" y2="1.6" width="0.01"/>
  <wall x1="-0.2" y1="1.3" x2="-0.2" y2="1.6" width="0.01"/>
  <startPositions><pos x="-0.35" y="1.15" theta="3.14159"/><pos x="0" y="1.5"/></startPositions>
  <goal id="0" x="0.0" y="1.45"/>
</world>)";
  const maze::Maze m = maze::read_xml(xml, "f");
  CHECK(m.width() == 2);
  CHECK(m.height() == 2);
  CHECK(m.cell_size_m() == doctest::Approx(0.3));
  CHECK(m.origin_x_m() == doctest::Approx(-0.5));
  CHECK(m.origin_y_m() == doctest::Approx(1.0));
  CHECK(m.wall_thickness_m() == doctest::Approx(0.01));
  CHECK(m.has_wall({0, 1}, maze::Side::east));
  CHECK(!m.has_wall({0, 0}, maze::Side::east));
  CHECK(!m.has_wall({0, 0}, maze::Side::north));
  CHECK(m.start() == maze::Cell{0, 0});
  CHECK(m.start_heading() == maze::Side::west);
  CHECK(m.goals() == std::vector<maze::Cell>{{1, 1}});
  // Written back, it reads as the same maze (physical set-up to rounding).
  const maze::Maze again = maze::read_xml(maze::write_xml_keeping_origin(m), "g");
  CHECK(maze::write_text_map(again) == maze::write_text_map(m));
  CHECK(again.start_heading() == maze::Side::west);
  CHECK(again.cell_size_m() == doctest::Approx(0.3));
  CHECK(again.origin_x_m() == doctest::Approx(-0.5));
}

TEST_CASE("formats: num lists every cell, X outer, Y inner") {
  const maze::Maze m = maze::read_text_map("o---o---o\n| S |   |\no---o---o\n", "f");
  CHECK(maze::write_num(m) == "0 0 1 1 1 1\n1 0 1 1 1 1\n");
  CHECK(maze::read_num("\n1 0 1 1 1 1\r\n0 0 1 1 1 1\n\n", "n") == m);
}

TEST_CASE("formats: the Webots world has the R2023b header, one Solid per wall run, and the start") {
  const maze::Maze m = maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.txt").maze();
  const std::string wbt = maze::write_wbt(m, "lab4x4");
  CHECK(wbt.starts_with("#VRML_SIM R2023b utf8\n"));
  auto count = [&wbt](std::string_view what) {
    std::size_t n = 0;
    for (std::size_t at = wbt.find(what); at != std::string::npos; at = wbt.find(what, at + 1)) ++n;
    return n;
  };
  const std::size_t runs = m.wall_segments().size();
  CHECK(count("\nSolid {") == runs + 1);  // the walls and the floor
  CHECK(count("boundingObject USE WALL_BOX_") == runs);
  CHECK(count("EXTERNPROTO \"https://raw.githubusercontent.com/cyberbotics/webots/R2023b/") == 2);
  CHECK(count("\nTexturedBackground {") == 1);
  CHECK(count("\nTexturedBackgroundLight {") == 1);
  CHECK(count("# start: cell (0,0) facing north, x 0.5 m, y 0.5 m, yaw 1.570796 rad\n") == 1);
  CHECK(count("DEF START Pose {") == 1);
  CHECK(count("{") == count("}"));
  CHECK(count("[") == count("]"));
  // The first wall run: the south edge, 4 cells plus the thickness, centred on it.
  CHECK(count("translation 2 0 0.25\n") == 1);
  CHECK(count("size 4.012 0.012 0.5\n") == 2);  // south and north edges
}

TEST_CASE("formats: writes are atomic; an unwritable path leaves nothing behind") {
  const auto dir = std::filesystem::temp_directory_path() / ("maze_mapper_test_write_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string target = (dir / "out.txt").string();
  maze::write_file_atomically(target, "first\n");
  maze::write_file_atomically(target, "second\n");
  CHECK(maze::read_file(target) == "second\n");
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);

  const std::string bad = (dir / "missing" / "out.txt").string();
  try {
    maze::write_file_atomically(bad, "x");
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == "error: cannot write " + bad + ": No such file or directory");
  }
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);
  std::filesystem::remove_all(dir);
}

TEST_CASE("formats: the output format comes from the extension") {
  CHECK(maze::format_for_output("a/b.wbt") == maze::Format::wbt);
  CHECK(maze::format_for_output("b.num") == maze::Format::num);
  try {
    maze::format_for_output("maze.png");
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() ==
          "error: cannot tell the output format of 'maze.png' from its extension: use .txt, .num, .xml, .wbt, .maz or .room");
  }
}

TEST_CASE("formats: the output extension is read in any case") {
  CHECK(maze::format_for_output("OUT.TXT") == maze::Format::text_map);
  CHECK(maze::format_for_output("a/Lab.Xml") == maze::Format::xml);
  CHECK(maze::format_for_output("b.NUM") == maze::Format::num);
  CHECK(maze::format_for_output("c.WBT") == maze::Format::wbt);
}

TEST_CASE("formats: dropped_by says what a format cannot hold, in one line") {
  const maze::Maze lab = maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.txt").maze();
  CHECK(maze::dropped_by(lab, maze::Format::num) == "dropped the goal (3,3): a num file holds only the walls");
  CHECK(!maze::dropped_by(lab, maze::Format::text_map));
  CHECK(!maze::dropped_by(lab, maze::Format::xml));
  CHECK(!maze::dropped_by(lab, maze::Format::wbt));
  const maze::Maze course = maze::load_world(std::string(TEST_DATA_DIR) + "/worlds/course_frame_1m.xml").maze();
  CHECK(maze::dropped_by(course, maze::Format::num) ==
        "dropped the start (5,3) facing west, the goal (1,6) and the size (cells of 0.5 m, walls 0.012 m thick, "
        "origin (0, 0)): a num file holds only the walls");
  CHECK(maze::dropped_by(course, maze::Format::text_map) ==
        "dropped the start's heading (west) and the size (cells of 0.5 m, walls 0.012 m thick, origin (0, 0)): a "
        "text map holds walls, start cell and goals; its start faces north");
  CHECK(!maze::dropped_by(course, maze::Format::xml));
  const maze::Maze num = maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.num").maze();
  CHECK(!maze::dropped_by(num, maze::Format::num));
}

TEST_CASE("formats: --cell-size, --start and --goal apply to the world loaded") {
  maze::WorldOverrides o;
  o.cell_size_m = 0.18;
  o.start = maze::Cell{3, 0};
  o.start_heading = maze::Side::west;
  o.goals = std::vector<maze::Cell>{{2, 2}, {1, 1}};
  const maze::World w = maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.num", o);
  CHECK(w.format == maze::Format::num);
  CHECK(w.maze().cell_size_m() == 0.18);
  CHECK(w.maze().wall_thickness_m() == maze::kDefaultWallThickness_m);
  CHECK(w.maze().start() == maze::Cell{3, 0});
  CHECK(w.maze().start_heading() == maze::Side::west);
  CHECK(w.maze().goals() == std::vector<maze::Cell>{{1, 1}, {2, 2}});
  // An XML world that states no cellSize reads on the lattice --cell-size chooses (its walls
  // on it); one written by convert states its own, and another is refused.
  maze::WorldOverrides same;
  same.cell_size_m = 0.5;
  CHECK(maze::load_world(std::string(TEST_DATA_DIR) + "/worlds/course_lattice.xml", same).maze().cell_size_m() == 0.5);
  CHECK(maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.xml", same).maze().width() == 8);
  const std::string stated = maze::read_file(std::string(WORLDS_DIR) + "/lab4x4.xml");
  try {
    (void)maze::read_xml(maze::write_xml(maze::read_xml(stated, "lab4x4.xml")), "w.xml", maze::XmlReadOptions{0.5});
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == "error: --cell-size 0.5 m disagrees with the cellSize 1 m that w.xml states; leave "
                            "--cell-size out");
  }
  maze::WorldOverrides outside;
  outside.goals = std::vector<maze::Cell>{{0, 0}, {4, 0}};
  try {
    (void)maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.txt", outside);
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == "error: --goal 4,0 is outside the 4x4 maze");
  }
}

TEST_CASE("convert to XML: centred on (0, 0), collinear walls merged, as the course writes its mazes") {
  const maze::Maze m = maze::read_text_map(maze::read_file(std::string(WORLDS_DIR) + "/lab4x4.txt"), "lab4x4.txt");
  const std::string xml = maze::write_xml(m);
  // The 4 x 4 m frame from -2 to 2: its south side one wall, not four.
  CHECK(xml.find("<wall x1=\"-2\" y1=\"-2\" x2=\"2\" y2=\"-2\" width=\"0.012\"/>") != std::string::npos);
  CHECK(xml.find("<wall x1=\"-2\" y1=\"-2\" x2=\"-1\" y2=\"-2\"") == std::string::npos);
  // The start (0,0) on its centre, facing north; the goal (3,3) on its centre.
  CHECK(xml.find("<pos x=\"-1.5\" y=\"-1.5\" theta=\"1.5707963267948966\"/>") != std::string::npos);
  CHECK(xml.find("<goal id=\"0\" x=\"1.5\" y=\"1.5\"/>") != std::string::npos);
  const maze::Maze back = maze::read_xml(xml, "lab4x4.xml");
  CHECK(back.origin_x_m() == -2.0);
  CHECK(back.origin_y_m() == -2.0);
  CHECK(maze::write_text_map(back) == maze::write_text_map(m));
  // --keep-origin: from (0, 0) as the world has it.
  CHECK(maze::write_xml_keeping_origin(m).find("<wall x1=\"0\" y1=\"0\" x2=\"4\" y2=\"0\"") != std::string::npos);
}
