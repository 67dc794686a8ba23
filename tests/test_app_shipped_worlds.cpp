// Where the program finds its shipped worlds (app/run/shipped_worlds.hpp): the environment
// variable, a checkout's worlds/, else beside the program (the build tree links its
// share/maze_mapper/worlds to the source's worlds/, as an installed tree has it).

#include <doctest/doctest.h>

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
