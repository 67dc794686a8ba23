// One spelling per idea on the command line: the pose X,Y,YAW (degrees, or with a unit), a
// goal list by repeating --goal, -o always --out, map-log's --snapshots-at, --color; the old
// spellings still work, each with a warning (the exact lines: tests/bad_inputs/cases.txt).

#include <doctest/doctest.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli/cli_options.hpp"
#include "app/cli/commands.hpp"
#include "app/run/run_options.hpp"
#include "app/run/terminal.hpp"
#include "cli_runner.hpp"
#include "common/error.hpp"

namespace {

app::RunOptions parsed_run(std::vector<std::string> args) {
  args.insert(args.begin(), {"maze_mapper", "run"});
  std::vector<const char *> argv;
  for (const std::string &a : args) argv.push_back(a.c_str());
  return app::parse_run_options(static_cast<int>(argv.size()), argv.data());
}

}  // namespace

TEST_CASE("scan --pose X,Y,YAW prints what the old --pose X Y YAW (radians) printed") {
  const std::string world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  const test_cli::Ran now = test_cli::run({"scan", world, "--pose", "0.5,0.5,90", "--noise", "0"});
  const test_cli::Ran old = test_cli::run({"scan", world, "--pose", "0.5", "0.5", "1.5707963267948966", "--noise", "0"});
  const test_cli::Ran world_after = test_cli::run({"scan", "--pose", "0.5,0.5,90", world, "--noise", "0"});
  CHECK(now.out == old.out);
  CHECK(world_after.out == now.out);
  CHECK(now.out.starts_with("0 3.132866 0.490019\n"));  // the fixed lidar: beam 0 half a beam in, 1 cm rounding
  CHECK_THROWS_WITH_AS(test_cli::run({"scan", world, "--pose", "0.5,0.5,90", "other.txt"}),
                       "scan: unexpected argument 'other.txt'", common::InputError);
}

TEST_CASE("--resolution is one option in every command: metres, or with its unit m or cm") {
  const std::string one_d = test_cli::run({"demo", "1d"}).out;
  CHECK(test_cli::run({"demo", "1d", "--resolution", "10cm"}).out == one_d);
  CHECK(test_cli::run({"demo", "1d", "--resolution", "0.1m"}).out == one_d);
  CHECK(test_cli::run({"demo", "1d", "--resolution", "10"}).out == one_d);  // the old cm, with a warning
  const std::string pie = test_cli::run({"demo", "pie", "--resolution", "0.2"}).out;
  CHECK(pie.find("resolution 0.2 m\n") != std::string::npos);
  CHECK(test_cli::run({"demo", "pie", "--resolution", "20cm"}).out == pie);
  CHECK(test_cli::run({"demo", "cone", "--resolution", "2cm"}).out == test_cli::run({"demo", "cone", "--resolution", "0.02m"}).out);
  CHECK_THROWS_WITH_AS(test_cli::run({"demo", "cone", "--resolution", "0cm"}), "--resolution must be > 0 m (got 0cm)",
                       common::InputError);
}

TEST_CASE("a pose in metres is Xm,Ym[,YAW] in every command; X,Y without the unit is the old spelling") {
  CHECK(test_cli::run({"demo", "pie", "--pose", "1.5m,2.5m,270"}).out == test_cli::run({"demo", "pie"}).out);
  CHECK(test_cli::run({"demo", "cone", "--pose", "50cm,0m,90"}).out ==
        test_cli::run({"demo", "cone", "--pose", "0.5,0,90"}).out);
  const std::string world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  CHECK(test_cli::run({"scan", world, "--pose", "0.5m,0.5m,90", "--noise", "0"}).out ==
        test_cli::run({"scan", world, "--pose", "0.5,0.5,90", "--noise", "0"}).out);
  // run: a place in metres faces a side: a letter, or degrees on a quarter turn.
  const app::RunOptions degrees = parsed_run({"--start", "0.5m,1.5m,270"});
  REQUIRE(degrees.world_overrides.start_m.has_value());
  CHECK(degrees.world_overrides.start_heading == maze::Side::south);
  CHECK(parsed_run({"--start", "0.5m,1.5m,W"}).world_overrides.start_heading == maze::Side::west);
  CHECK(parsed_run({"--start", "50cm,150cm,-90deg"}).world_overrides.start_heading == maze::Side::south);
  CHECK(parsed_run({"--start", "1,2,E"}).world_overrides.start_heading == maze::Side::east);
  CHECK_THROWS_AS(parsed_run({"--start", "0.5m,1.5m,45"}), common::InputError);
  CHECK_THROWS_AS(parsed_run({"--start", "1,2,90"}), common::InputError);  // a cell's heading is a letter
}

TEST_CASE("goals: --goal repeated, the old X,Y;X,Y list the same, centre alone") {
  const app::RunOptions repeated = parsed_run({"--goal", "3,3", "--goal", "0,3"});
  const app::RunOptions old = parsed_run({"--goal", "3,3;0,3"});
  REQUIRE(repeated.world_overrides.goals.has_value());
  CHECK(repeated.world_overrides.goals->size() == 2);
  CHECK(old.world_overrides.goals == repeated.world_overrides.goals);
  CHECK(parsed_run({"--goal", "centre"}).world_overrides.centre_goals);
  CHECK_THROWS_AS(parsed_run({"--goal", "centre", "--goal", "1,1"}), common::InputError);
  // The goal does not swallow the world after it.
  const app::RunOptions with_world = parsed_run({"--goal", "3,3", std::string(WORLDS_DIR) + "/lab4x4.txt"});
  CHECK(with_world.world == std::string(WORLDS_DIR) + "/lab4x4.txt");
}

TEST_CASE("-o is --out in every command that writes files") {
  const test_cli::TempDir dir("spellings_out");
  const app::RunOptions run = parsed_run({"-o", dir.path.string()});
  CHECK(run.output.out_dir == dir.path.string());
  std::filesystem::create_directories(dir.path);
  const std::string maze = (dir.path / "maze.txt").string();
  (void)test_cli::run({"generate", "4x4", "-o", maze});
  CHECK(std::filesystem::exists(maze));
  const std::string old_maze = (dir.path / "old.txt").string();
  (void)test_cli::run({"generate", "4x4", "--output", old_maze});
  CHECK(std::filesystem::exists(old_maze));
}

TEST_CASE("--color: never and always as said; auto follows the terminal and NO_COLOR") {
  CHECK(app::parse_color_choice("auto") == app::ColorChoice::automatic);
  CHECK_THROWS_WITH_AS(app::parse_color_choice("yes"), "--color must be auto, always or never (got 'yes')",
                       common::InputError);
  const int pipe_fd = ::open("/dev/null", O_WRONLY);
  REQUIRE(pipe_fd >= 0);
  CHECK(app::use_color(app::ColorChoice::always, pipe_fd));
  CHECK(!app::use_color(app::ColorChoice::automatic, pipe_fd));
  ::close(pipe_fd);
  // A terminal: a pseudo-terminal's follower side.
  const int leader = ::posix_openpt(O_RDWR | O_NOCTTY);
  REQUIRE(leader >= 0);
  REQUIRE(::grantpt(leader) == 0);
  REQUIRE(::unlockpt(leader) == 0);
  const int terminal = ::open(::ptsname(leader), O_RDWR | O_NOCTTY);
  REQUIRE(terminal >= 0);
  ::unsetenv("NO_COLOR");
  CHECK(app::use_color(app::ColorChoice::automatic, terminal));
  ::setenv("NO_COLOR", "1", 1);
  CHECK(!app::use_color(app::ColorChoice::automatic, terminal));
  CHECK(app::use_color(app::ColorChoice::always, terminal));
  ::setenv("NO_COLOR", "", 1);  // set but empty: no effect (no-color.org)
  CHECK(app::use_color(app::ColorChoice::automatic, terminal));
  CHECK(!app::use_color(app::ColorChoice::never, terminal));
  ::unsetenv("NO_COLOR");
  ::close(terminal);
  ::close(leader);
}
