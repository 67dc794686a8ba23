// Generator properties over many seeds: perfect mazes, loops, determinism, goals.
#include <doctest/doctest.h>

#include <chrono>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "maze/generate/generator.hpp"
#include "maze/formats/text_map.hpp"

namespace {

constexpr maze::Algorithm kAlgorithms[] = {maze::Algorithm::dfs, maze::Algorithm::kruskal, maze::Algorithm::prim};

std::size_t cells(const maze::Maze &m) {
  return static_cast<std::size_t>(m.width()) * static_cast<std::size_t>(m.height());
}

}  // namespace

TEST_CASE("generator: a perfect maze has cells - 1 passages and every cell reachable") {
  for (const auto algorithm : kAlgorithms) {
    for (std::uint64_t seed = 0; seed < 60; ++seed) {
      const int w = 1 + static_cast<int>(seed % 13);
      const int h = 1 + static_cast<int>((seed * 7) % 11);
      const maze::Maze m = maze::generate_maze({w, h, seed, 0.0, algorithm});
      CAPTURE(seed);
      CHECK(m.passage_count() == cells(m) - 1);
      CHECK(m.reachable_count() == cells(m));
    }
  }
}

TEST_CASE("generator: loops remove round(F * walls left) interior walls") {
  for (const auto algorithm : kAlgorithms) {
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
      for (const double loops : {0.05, 0.25, 0.5, 1.0}) {
        const maze::GeneratorOptions options{12, 9, seed, loops, algorithm};
        const maze::Maze m = maze::generate_maze(options);
        const std::size_t walls_left = m.interior_side_count() - (cells(m) - 1);
        const auto expected = static_cast<std::size_t>(std::llround(loops * static_cast<double>(walls_left)));
        CHECK(maze::loop_walls_removed(options) == expected);
        CHECK(m.passage_count() == cells(m) - 1 + expected);
        CHECK(m.reachable_count() == cells(m));
      }
    }
  }
  // All of them: an open room.
  CHECK(maze::generate_maze({6, 6, 1, 1.0, maze::Algorithm::dfs}).passage_count() == 60);
}

TEST_CASE("generator: the same seed gives the same bytes, another seed another maze") {
  for (const auto algorithm : kAlgorithms) {
    const auto a = maze::write_text_map(maze::generate_maze({16, 16, 5, 0.1, algorithm}));
    CHECK(a == maze::write_text_map(maze::generate_maze({16, 16, 5, 0.1, algorithm})));
    CHECK(a != maze::write_text_map(maze::generate_maze({16, 16, 6, 0.1, algorithm})));
  }
}

TEST_CASE("generator: a fixed seed gives this maze on every platform") {
  CHECK(maze::write_text_map(maze::generate_maze({4, 3, 1, 0.0, maze::Algorithm::dfs})) ==
        "o---o---o---o---o\n"
        "|               |\n"
        "o   o---o---o   o\n"
        "|     G | G     |\n"
        "o---o   o   o---o\n"
        "| S     |       |\n"
        "o---o---o---o---o\n");
}

TEST_CASE("generator: start south-west facing north, goal the centre (2x2 when even)") {
  const maze::Maze even = maze::generate_maze({16, 16, 3, 0.0, maze::Algorithm::dfs});
  CHECK(even.start() == maze::Cell{0, 0});
  CHECK(even.start_heading() == maze::Side::north);
  CHECK(even.goals() == std::vector<maze::Cell>{{7, 7}, {7, 8}, {8, 7}, {8, 8}});
  CHECK(maze::generate_maze({5, 5, 3, 0.0, maze::Algorithm::dfs}).goals() == std::vector<maze::Cell>{{2, 2}});
  CHECK(maze::generate_maze({4, 5, 3, 0.0, maze::Algorithm::dfs}).goals() == std::vector<maze::Cell>{{1, 2}, {2, 2}});
  CHECK(maze::generate_maze({1, 1, 3, 0.0, maze::Algorithm::dfs}).goals() == std::vector<maze::Cell>{{0, 0}});
}

TEST_CASE("generator: large mazes without recursion (dfs 1024 x 1024, the others 512 x 512)") {
  for (const auto algorithm : kAlgorithms) {
    const int side = algorithm == maze::Algorithm::dfs ? 1024 : 512;
    const auto begin = std::chrono::steady_clock::now();
    const maze::Maze m = maze::generate_maze({side, side, 9, 0.0, algorithm});
    const auto ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
    MESSAGE(side << "x" << side << " algorithm " << static_cast<int>(algorithm) << ": " << ms << " ms");
    // A perfect maze: a spanning tree of the cells, each side seen from both cells alike,
    // the outer boundary closed.
    CHECK(m.passage_count() == cells(m) - 1);
    CHECK(m.reachable_count() == cells(m));
    std::size_t openings = 0;
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) {
        if (x + 1 < side && !m.has_wall({x, y}, maze::Side::east)) ++openings;
        if (y + 1 < side && !m.has_wall({x, y}, maze::Side::north)) ++openings;
      }
      REQUIRE(m.has_wall({0, y}, maze::Side::west));
      REQUIRE(m.has_wall({side - 1, y}, maze::Side::east));
      REQUIRE(m.has_wall({y, 0}, maze::Side::south));
      REQUIRE(m.has_wall({y, side - 1}, maze::Side::north));
    }
    CHECK(openings == cells(m) - 1);
  }
}

TEST_CASE("generator: options and sizes are checked") {
  auto message = [](auto &&f) -> std::string {
    try {
      f();
    } catch (const common::InputError &e) {
      return e.diagnostic();
    }
    return "(no error)";
  };
  CHECK(maze::parse_size("16x8").x == 16);
  CHECK(maze::parse_size("16x8").y == 8);
  CHECK(message([] { maze::parse_size("0x3"); }) ==
        "error: size must be WxH with W and H from 1 to 4096 (e.g. 16x16), got '0x3'");
  CHECK(message([] { maze::parse_size("4097x3"); }) ==
        "error: size must be WxH with W and H from 1 to 4096 (e.g. 16x16), got '4097x3'");
  CHECK(message([] { maze::parse_size("16"); }) ==
        "error: size must be WxH with W and H from 1 to 4096 (e.g. 16x16), got '16'");
  CHECK(message([] { maze::parse_size("8x8x8"); }) ==
        "error: size must be WxH with W and H from 1 to 4096 (e.g. 16x16), got '8x8x8'");
  CHECK(message([] { maze::parse_algorithm("bfs"); }) == "error: --algorithm must be dfs, kruskal or prim, got 'bfs'");
  CHECK(message([] { maze::GeneratorOptions{4, 4, 1, 1.5, maze::Algorithm::dfs}.validate(); }) ==
        "error: --loops must be a fraction from 0 to 1, got 1.5");
  CHECK(message([] { maze::GeneratorOptions{4, 4, 1, std::nan(""), maze::Algorithm::dfs}.validate(); }) ==
        "error: --loops must be a fraction from 0 to 1, got nan");
}
