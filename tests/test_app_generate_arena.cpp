// `maze_mapper generate arena`: the library's generated arenas (maze::generate_arena) on the
// command line, as a room file on standard output or written as .room or .xml; sizes, lists
// and formats it cannot take refused in one line, nothing written.

#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "common/error.hpp"
#include "maze/formats/solids_format.hpp"
#include "maze/generate/solids_generator.hpp"
#include "maze/world/world.hpp"
#include "maze/world/world_files.hpp"

namespace {

// What `maze_mapper ARGS...` says when it refuses them.
std::string refusal(const std::vector<std::string> &args) {
  try {
    (void)test_cli::run(args);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "";
}

}  // namespace

TEST_CASE("generate arena prints the library's arena for the seed, sides and count given, as a room file") {
  maze::ArenaGeneration g;
  g.seed = 6;
  g.width_m = 3.0;
  g.height_m = 3.0;
  g.obstacles = 4;
  g.min_side_m = 0.2;
  g.max_side_m = 0.8;
  const test_cli::Ran ran =
      test_cli::run({"generate", "arena", "3x3", "--obstacles", "4", "--sides", "0.2,0.8", "--seed", "6"});
  CHECK(ran.status == 0);
  CHECK(ran.out == maze::write_room(maze::generate_arena(g)));
  // The defaults are the library's: 10 rectangles of 0.3 to 1.5 m, seed 1.
  g = maze::ArenaGeneration{};
  g.width_m = 6.0;
  g.height_m = 4.5;
  CHECK(test_cli::run({"generate", "arena", "6x4.5"}).out == maze::write_room(maze::generate_arena(g)));
}

TEST_CASE("generate arena -o writes the room file it prints, or the course's .xml, each loading as the arena") {
  const test_cli::TempDir dir("generate_arena");
  std::filesystem::create_directories(dir.path);
  const std::vector<std::string> args{"generate", "arena", "3x3", "--obstacles", "4", "--seed", "2"};
  const std::string printed = test_cli::run(args).out;
  for (const char *name : {"a.room", "a.xml"}) {
    const std::string file = (dir.path / name).string();
    std::vector<std::string> to_file = args;
    to_file.insert(to_file.end(), {"-o", file});
    CHECK(test_cli::run(to_file).out.empty());
    const maze::World world = maze::load_world(file);
    REQUIRE(!world.on_lattice());
    CHECK(world.arena().obstacles.size() == 4);
    CHECK(world.arena().width_m() == doctest::Approx(3.0));
  }
  CHECK(maze::read_file((dir.path / "a.room").string()) == printed);
}

TEST_CASE("generate arena refuses a size, a list or a file format it cannot take, in one line, writing nothing") {
  const test_cli::TempDir dir("generate_arena_refusals");
  std::filesystem::create_directories(dir.path);
  CHECK(refusal({"generate", "arena", "3"}) == "error: an arena's size is WxH in metres, e.g. 3x3 (got '3')");
  CHECK(refusal({"generate", "arena", "3xfour"}) == "error: an arena's size is WxH in metres, e.g. 3x3 (got '3xfour')");
  CHECK(refusal({"generate", "arena", "0.5x3"}) == "error: a generated arena is 1 to 1000 m a side (got 0.5 x 3 m)");
  CHECK(refusal({"generate", "arena", "3x3", "--sides", "0.8"}) == "error: --sides needs 2 numbers (got 1)");
  CHECK(refusal({"generate", "arena", "3x3", "--sides", "0.8,0.2"}) ==
        "error: obstacle sides need 0 < min <= max (got 0.8 and 0.2 m)");
  CHECK(refusal({"generate", "arena", "3x3", "--sides", "0.2,inf"}) ==
        "error: obstacle sides need 0 < min <= max (got 0.2 and inf m)");
  const std::string text_map = (dir.path / "a.txt").string();
  CHECK(refusal({"generate", "arena", "3x3", "-o", text_map}) ==
        "error: a text map file holds a grid maze; an arena is written as .room or .xml");
  CHECK(!std::filesystem::exists(text_map));
  // A maze still needs its size; the arena's options are not the maze's.
  CHECK(refusal({"generate"}) == "error: generate needs the maze's size WxH, e.g. 16x16 (or `generate arena WxH`)");
  CHECK_THROWS(test_cli::run({"generate", "4x4", "--obstacles", "3"}));
  CHECK_THROWS(test_cli::run({"generate", "arena", "3x3", "--loops", "0.1"}));
  const std::string before = (dir.path / "before.room").string();
  CHECK(refusal({"generate", "--loops", "0.1", "arena", "3x3", "-o", before}) ==
        "error: --loops is the maze's, given before `arena`; an arena's options follow `arena`");
  CHECK(refusal({"generate", "4x4", "arena", "3x3", "-o", before}) ==
        "error: WxH is the maze's, given before `arena`; an arena's options follow `arena`");
  CHECK(!std::filesystem::exists(before));
}
