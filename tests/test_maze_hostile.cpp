// Hostile input never crashes or hangs: it is an error with a place, quickly.
#include <doctest/doctest.h>

#include <string>

#include "common/error.hpp"
#include "common/random.hpp"
#include "maze/world/world.hpp"

namespace {

// The diagnostic, or "(no error)".
std::string read(const std::string &text) {
  try {
    maze::read_world(text, "h");
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("hostile: empty, blank and binary input") {
  CHECK(read("") == "h: error: the file is empty; expected a maze");
  CHECK(read("\n\n  \n").starts_with("h:1:1: error: cannot tell the format"));
  common::Rng rng(11);
  for (int round = 0; round < 300; ++round) {
    std::string noise(static_cast<std::size_t>(rng.below(400)), '\0');
    for (char &c : noise) c = static_cast<char>(rng.below(256));
    // Each format's reader on noise that starts the way that format does.
    for (const char *prefix : {"", "o", "o---o\n|", "<world>", "0 0 "}) {
      const std::string text = prefix + noise;
      CAPTURE(round);
      const std::string d = read(text);
      CHECK((d.starts_with("h") || d == "(no error)"));
    }
  }
}

TEST_CASE("hostile: a 100 MB single line") {
  std::string line(100u << 20, '-');
  line[0] = 'o';
  CHECK(read(line) == "h:1:16386: error: the maze is wider than 4096 cells (lines longer than 16385 characters)");
  line[0] = '<';
  CHECK(read(line) == "h:1:2: error: not well-formed XML: invalid token");
  line[0] = '7';
  CHECK(read(line) == "h:1:1: error: X is not an integer: '7-------------------...'");
}

TEST_CASE("hostile: a million lines") {
  std::string text = "o---o\n";
  for (int i = 0; i < 500000; ++i) text += "|   |\no---o\n";
  CHECK(read(text) == "h:8194:1: error: the maze is taller than 4096 cells (more than 8193 lines)");
  std::string num;
  for (int i = 0; i < 1000000; ++i) num += "0 0 1 1 1 1\n";
  CHECK(read(num) == "h:2:1: error: cell (0,0) listed twice; the first is on line 1");
}

TEST_CASE("hostile: ragged lines, tabs and UTF-8 arrows") {
  CHECK(read("o---o\n|   |   |\no---o\n") == "h:2:6: error: line 2 is 9 characters long, expected 5 like the first line");
  CHECK(read("o---o\n|\t|\no---o\n") == "h:2:2: error: unexpected tab in cell (0,0); expected a blank, 'S' or 'G'");
  CHECK(read("o---o\n| \xE2\x86\x91 |\no---o\n") ==
        "h:2:3: error: unexpected byte 0xe2 in cell (0,0); expected a blank, 'S' or 'G'");
  CHECK(read("o---o\n|\no---o\n") == "h:2:2: error: line 2 is 1 characters long, expected 5 like the first line");
  CHECK(read("0\t0 1 1 1 1\n") == "(no error)");
}

TEST_CASE("hostile: XML with unknown elements, NaN, infinities, deep nesting") {
  const std::string walls =
      "<wall x1='0' y1='0' x2='1' y2='0'/><wall x1='0' y1='1' x2='1' y2='1'/>"
      "<wall x1='0' y1='0' x2='0' y2='1'/><wall x1='1' y1='0' x2='1' y2='1'/>";
  CHECK(read("<world>" + walls + "<robot><arm/></robot><x y='nan'/></world>") == "(no error)");
  CHECK(read("<world cellSize='0.5'>" + walls + "</world>") == "(no error)");
  CHECK(read("<world cellSize='0'>" + walls + "</world>") == "h:1:8: error: cellSize must be positive, got 0");
  CHECK(read("<world cellSize='nan'>" + walls + "</world>") == "h:1:8: error: cellSize is not a finite number of metres: 'nan'");
  CHECK(read("<world>" + walls + "<wall x1='inf' y1='0' x2='1' y2='0'/></world>") ==
        "h:1:154: error: x1 is not a finite number of metres: 'inf'");
  CHECK(read("<world>" + walls + "<goal x='NaN' y='0.5'/></world>") ==
        "h:1:154: error: x is not a finite number of metres: 'NaN'");
  CHECK(read("<world>" + walls + "<wall x1='0' y1='0' x2='1e300' y2='0'/></world>") ==
        "h:1:168: error: x2 is not a finite number of metres: '1e300'");
  CHECK(read("<world><wall x1='0' y1='0' x2='4097' y2='0'/><wall x1='0' y1='1' x2='0' y2='0'/></world>") ==
        "h:1:1: error: the walls span 4097x1 cells of 1 m; each side must be 1 to 4096");
  std::string deep;
  for (int i = 0; i < 100000; ++i) deep += "<a>";
  CHECK(read("<world>" + deep) == "h:1:300008: error: not well-formed XML: the file ends inside <a> of line 1");
  CHECK(read("<world/>") == "h:1:1: error: no <wall> elements: an open arena, not a grid maze; a maze needs walls");
}

TEST_CASE("hostile: XML places are the parser's, across lines, marks and entities") {
  const std::string walls =
      "<wall x1='0' y1='0' x2='1' y2='0'/><wall x1='0' y1='1' x2='1' y2='1'/>"
      "<wall x1='0' y1='0' x2='0' y2='1'/><wall x1='1' y1='0' x2='1' y2='1'/>";
  // An attribute on a later line of its tag is found there.
  CHECK(read("<world>\n<wall x1='0' y1='0'\n     x2='q' y2='0'/></world>") == "h:3:6: error: x2 is not a number: 'q'");
  // A byte-order mark is no column; a two-byte character is one.
  CHECK(read("\xEF\xBB\xBF<world cellSize='0'>" + walls + "</world>") == "h:1:8: error: cellSize must be positive, got 0");
  CHECK(read("<world name='\xC3\xA9'><wall x1='0' y1='0' x2='q' y2='0'/></world>") ==
        "h:1:37: error: x2 is not a number: 'q'");
  // Entities are replaced before a number is read; walls below the world's children are not walls.
  CHECK(read("<world><wall x1='0' y1='0' x2='&#49;' y2='0'/>" + walls.substr(35) +
             "<robot><wall x1='q'/></robot></world>") == "(no error)");
  CHECK(read("<world>" + walls + "<startPositions>\n</world>") ==
        "h:2:3: error: not well-formed XML: mismatched tag: </world> where <startPositions> of line 1 is open");
  CHECK(read("<world>" + walls) == "h:1:148: error: not well-formed XML: the file ends inside <world> of line 1");
  CHECK(read("<?xml version='1.0'?><!-- only a comment -->") == "h: error: no XML element: expected <world>");
}
