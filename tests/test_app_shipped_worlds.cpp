// Where the program finds its shipped worlds (app/run/shipped_worlds.hpp): the environment
// variable, a checkout's worlds/, else beside the program (the build tree links its
// share/maze_mapper/worlds to the source's worlds/, as an installed tree has it).

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "app/run/shipped_worlds.hpp"
#include "cli_runner.hpp"
#include "common/error.hpp"

namespace {

void touch(const std::filesystem::path &file) {
  std::filesystem::create_directories(file.parent_path());
  std::FILE *f = std::fopen(file.c_str(), "w");
  REQUIRE(f != nullptr);
  std::fclose(f);
}

// Runs in `dir` as the working directory, with MAZE_MAPPER_WORLDS set to `worlds` (unset when
// empty), and restores both.
struct Surroundings {
  std::filesystem::path old_dir = std::filesystem::current_path();
  Surroundings(const std::filesystem::path &dir, const std::string &worlds) {
    std::filesystem::create_directories(dir);
    std::filesystem::current_path(dir);
    if (worlds.empty()) {
      ::unsetenv(app::kWorldsEnvironmentVariable);
    } else {
      ::setenv(app::kWorldsEnvironmentVariable, worlds.c_str(), 1);
    }
  }
  ~Surroundings() {
    std::filesystem::current_path(old_dir);
    ::unsetenv(app::kWorldsEnvironmentVariable);
  }
  Surroundings(const Surroundings &) = delete;
  Surroundings &operator=(const Surroundings &) = delete;
};

}  // namespace

TEST_CASE("the default world comes from beside the program when the working directory has none") {
  const test_cli::TempDir elsewhere("shipped_worlds_elsewhere");
  const Surroundings here(elsewhere.path, "");
  const std::filesystem::path world = app::default_world();
  CHECK(world.is_absolute());
  CHECK(world.filename() == "lab4x4.txt");
  CHECK(world.parent_path().filename() == "worlds");
  CHECK(world.string().find("share/maze_mapper/worlds") != std::string::npos);
  CHECK(world.string().find("/../") == std::string::npos);
  CHECK(std::filesystem::is_regular_file(world));
}

TEST_CASE("a checkout's worlds/ in the working directory is taken as it is, relative") {
  const test_cli::TempDir checkout("shipped_worlds_checkout");
  touch(checkout.path / "worlds" / "lab4x4.txt");
  const Surroundings here(checkout.path, "");
  CHECK(app::default_world() == "worlds/lab4x4.txt");
}

TEST_CASE("MAZE_MAPPER_WORLDS names the worlds' folder, over the working directory's and the program's") {
  const test_cli::TempDir checkout("shipped_worlds_env");
  touch(checkout.path / "worlds" / "lab4x4.txt");
  const Surroundings here(checkout.path, "/srv/course/worlds");
  CHECK(app::default_world() == "/srv/course/worlds/lab4x4.txt");
  REQUIRE(app::shipped_worlds_dir().has_value());
  CHECK(*app::shipped_worlds_dir() == "/srv/course/worlds");
}

TEST_CASE("a shipped world is found by its name, with or without its extension, from any folder") {
  const test_cli::TempDir elsewhere("shipped_worlds_by_name");
  const Surroundings here(elsewhere.path, "");
  for (const char *name : {"maze8x8", "maze8x8.txt"}) {
    CAPTURE(name);
    const std::filesystem::path world = app::world_argument(name);
    CHECK(world.is_absolute());
    CHECK(world.filename() == "maze8x8.txt");
    CHECK(std::filesystem::is_regular_file(world));
  }
  CHECK(std::filesystem::path(app::world_argument("lab4x4")).filename() == "lab4x4.txt");  // over .num and .xml
  CHECK(std::filesystem::path(app::world_argument("lab4x4.xml")).filename() == "lab4x4.xml");
  CHECK(std::filesystem::path(app::world_argument("ir_room")).filename() == "ir_room.room");
  CHECK(app::world_argument("no_such_world") == "no_such_world");  // the reader's own error
  CHECK(app::world_argument("").empty());
  CHECK_FALSE(app::shipped_world("README").has_value());
}

TEST_CASE("a file in the working directory comes before a shipped world of its name") {
  const test_cli::TempDir elsewhere("shipped_worlds_own_file");
  touch(elsewhere.path / "maze8x8");
  const Surroundings here(elsewhere.path, "");
  CHECK(app::world_argument("maze8x8") == "maze8x8");
}

TEST_CASE("a missing path whose last part names a shipped world says how to name it") {
  const test_cli::TempDir elsewhere("shipped_worlds_missing_path");
  const Surroundings here(elsewhere.path, "");
  try {
    app::world_argument("worlds/maze8x8.txt");
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(std::string(e.what()) ==
          "cannot read worlds/maze8x8.txt: no such file; maze8x8.txt is a shipped world, found from any folder by its "
          "name: maze8x8");
  }
  CHECK(app::world_argument("worlds/not_shipped.txt") == "worlds/not_shipped.txt");
}

TEST_CASE("run, room and show take a shipped world's name from a folder without it") {
  const test_cli::TempDir elsewhere("shipped_worlds_run");
  const Surroundings here(elsewhere.path, "");
  const test_cli::Ran run = test_cli::run({"run", "maze8x8", "--quiet", "--noise", "0"});
  CHECK(run.status == 0);
  CHECK(run.out.find("/maze8x8.txt\n") != std::string::npos);
  CHECK(run.out.find("end: done") != std::string::npos);
  const test_cli::Ran show = test_cli::run({"show", "open_room6x6"});
  CHECK(show.status == 0);
  CHECK(show.out.starts_with("o---o"));
}

TEST_CASE("worlds lists every shipped world with its kind and size") {
  const test_cli::Ran ran = test_cli::run({"worlds"});
  CHECK(ran.status == 0);
  CHECK(ran.out.starts_with("world                  kind   size\n"));
  CHECK(ran.out.find("\nmaze8x8.txt            maze   8 x 8 cells\n") != std::string::npos);
  CHECK(ran.out.find("\nclassic16x16.txt       maze   16 x 16 cells\n") != std::string::npos);
  CHECK(ran.out.find("\nir_room.room           arena  ") != std::string::npos);
  CHECK(ran.out.find("README") == std::string::npos);
  CHECK(ran.out.find("does not load") == std::string::npos);
  const std::size_t lines = static_cast<std::size_t>(std::count(ran.out.begin(), ran.out.end(), '\n'));
  CHECK(lines == app::shipped_world_files().size() + 2);  // the heading and the folder's line
}
