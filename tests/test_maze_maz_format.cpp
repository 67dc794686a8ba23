// The binary .maz format of micromouseonline's maze collection: byte x * 16 + y is cell
// (x, y), bits 0x01 N, 0x02 E, 0x04 S, 0x08 W; read by content, written by convert.

#include <doctest/doctest.h>

#include <string>

#include "common/error.hpp"
#include "maze/formats/maz_format.hpp"
#include "maze/world/world.hpp"

namespace {

maze::Maze classic() { return maze::load_world(std::string(WORLDS_DIR) + "/classic16x16.txt").maze(); }

std::string diagnostic_of(const std::string &bytes) {
  try {
    (void)maze::read_maz(bytes, "m.maz");
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "no error";
}

}  // namespace

TEST_CASE("maz: the layout of micromouseonline's mazetool, and a round trip") {
  const maze::Maze m = classic();
  const std::string bytes = maze::write_maz(m);
  REQUIRE(bytes.size() == 256);
  CHECK(bytes[0] == '\x0E');  // the start cell (0,0): walls east, south and west, open north
  // Byte 1 is the cell north of the start, byte 16 the cell east of it.
  const auto bits = [&m](maze::Cell c) {
    int v = 0;
    for (const maze::Side s : maze::kSides) v |= m.has_wall(c, s) ? 1 << static_cast<int>(s) : 0;
    return v;
  };
  CHECK(static_cast<unsigned char>(bytes[1]) == bits({0, 1}));
  CHECK(static_cast<unsigned char>(bytes[16]) == bits({1, 0}));
  CHECK(static_cast<unsigned char>(bytes[15]) == bits({0, 15}));  // the north-west corner
  CHECK(maze::detect_format(bytes, "m.maz") == maze::Format::maz);
  const maze::Maze back = maze::read_maz(bytes, "m.maz");
  CHECK(maze::write_maz(back) == bytes);
  for (int x = 0; x < 16; ++x) {
    for (int y = 0; y < 16; ++y) {
      for (const maze::Side s : maze::kSides) CHECK(back.has_wall({x, y}, s) == m.has_wall({x, y}, s));
    }
  }
  CHECK(back.start() == maze::Cell{0, 0});
  CHECK(back.goals() == std::vector<maze::Cell>{{7, 7}, {7, 8}, {8, 7}, {8, 8}});
}

TEST_CASE("maz: a broken file says where") {
  const std::string bytes = maze::write_maz(classic());
  CHECK(diagnostic_of(bytes.substr(0, 255)) ==
        "m.maz: error: a binary maze (.maz) is 256 bytes, one a cell of a 16 x 16 maze; this file has 255");
  std::string bad = bytes;
  bad[37] = '\x41';
  CHECK(diagnostic_of(bad) ==
        "m.maz:1:38: error: byte 38 (cell (2,5)) is 0x41: a cell's byte holds only the wall bits 0x01 N, 0x02 E, "
        "0x04 S, 0x08 W");
  std::string open_edge = bytes;
  open_edge[0] = '\x06';  // the start cell without its west wall, on the maze's edge
  CHECK(diagnostic_of(open_edge).starts_with("m.maz:1:1: error: "));
  CHECK_THROWS_WITH_AS(maze::write_maz(maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.txt").maze()),
                       "a binary maze (.maz) holds a 16 x 16 maze; this one is 4x4", common::InputError);
}
