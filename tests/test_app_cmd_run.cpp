// `run`'s command line parsed without running (CommandContext::run_parse_only), as
// fuzz/fuzz_run_cli.cpp parses it. Regression (the CI fuzz run): with no arguments
// at all the fuzz target aborted, its check comparing the unset --max-steps as if it were 0.

#include <doctest/doctest.h>

#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "app/cli/commands.hpp"
#include "app/run/run.hpp"
#include "app/run/step_limit.hpp"
#include "common/error.hpp"
#include "maze/world/world.hpp"
#include "cli_runner.hpp"
#include "test_values.hpp"

namespace {

// The options `maze_mapper run ARGS...` would run with.
app::RunOptions parse_run(std::vector<std::string> args) {
  args.insert(args.begin(), {"maze_mapper", "run"});
  std::vector<const char *> argv;
  for (const std::string &a : args) argv.push_back(a.c_str());
  return app::parse_run_options(static_cast<int>(argv.size()), argv.data());
}

}  // namespace

TEST_CASE("run command line: no arguments leave the step limit to the maze") {
  const app::RunOptions o = parse_run({});
  CHECK_FALSE(o.max_steps.has_value());
  CHECK(o.world.ends_with("lab4x4.txt"));
  CHECK(o.simulation.dropout == 0.0);
  CHECK(o.simulation.spikes == 0.0);
}

TEST_CASE("run command line: --max-steps and the fault options") {
  const app::RunOptions o = parse_run({"--max-steps", "1", "--dropout", "0.05", "--spikes", "0.01"});
  CHECK(o.max_steps == std::optional<std::int64_t>{1});
  CHECK(o.simulation.dropout == 0.05);
  CHECK(o.simulation.spikes == 0.01);
  try {
    parse_run({"--max-steps", "0"});
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == "error: --max-steps must be at least 1 (got 0)");
  }
}

TEST_CASE("run command line: --cell-size, --start X,Y[,HEADING] and --goal X,Y;X,Y") {
  const app::RunOptions o = parse_run({"--cell-size", "0.5", "--start", "2, 1,e", "--goal", "3,3;0,3"});
  CHECK(o.world_overrides.cell_size_m == std::optional<double>{0.5});
  CHECK(o.world_overrides.start == std::optional<maze::Cell>{maze::Cell{2, 1}});
  CHECK(o.world_overrides.start_heading == maze::Side::east);
  CHECK(o.world_overrides.goals == std::optional<std::vector<maze::Cell>>{{{3, 3}, {0, 3}}});
  const app::RunOptions plain = parse_run({"--start", "1,0"});
  CHECK(plain.world_overrides.start_heading == maze::Side::north);
  CHECK_FALSE(plain.world_overrides.goals.has_value());
  CHECK_FALSE(plain.world_overrides.cell_size_m.has_value());
  for (const char *bad : {"1,", ",1", "1,1,", "1,1,NE", "a,b", "1;1"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(parse_run({"--start", bad}), common::InputError);
  }
  for (const char *bad : {"1,1;", ";1,1", "1,1,N", "1"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(parse_run({"--goal", bad}), common::InputError);
  }
}

TEST_CASE("run command line: each model's default robot, and a profile file names a path") {
  CHECK(parse_run({}).robot == "hambot");
  CHECK(parse_run({"--model", "ray"}).robot == "hambot");
  CHECK(parse_run({"--model", "bump"}).robot == "bumper-depth");
  CHECK(parse_run({"--model", "depth"}).robot == "bumper-depth");
  CHECK(parse_run({"--model", "pie"}).robot == "ir-ring");
  CHECK(parse_run({"--model", "cone"}).robot == "ir-ring");
  CHECK(parse_run({"--model", "cone", "--robot", "sonar-ring"}).robot == "sonar-ring");
  CHECK_THROWS_WITH_AS(parse_run({"--robot", "missing.json"}),
                       "cannot read missing.json: No such file or directory", common::InputError);
}

TEST_CASE("micromouse maps lab4x4 at 0.18 m cells with 12 mm walls (cell and ray models)") {
  maze::Maze m = maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.txt").maze();
  m.set_physical(0.18, 0.012, 0.0, 0.0);
  for (const sensing::ModelKind model : {sensing::ModelKind::cell, sensing::ModelKind::ray}) {
    app::RunOptions options;
    options.robot = "micromouse";
    options.model.kind = model;
    options.output.quiet = true;
    std::ostringstream sink;
    const app::RunSummary s = app::run_maze(options, m, sink);
    CAPTURE(sensing::to_string(model));
    CHECK(s.reason == robot::EndReason::done);
    CHECK(s.score.coverage_percent() == 100.0);
    CHECK(s.score.wall_accuracy_percent() == 100.0);
  }
}

TEST_CASE("run command line: --start pos:N and --start random, the latter by --seed") {
  const app::RunOptions third = parse_run({"--start", "pos:3"});
  CHECK(third.world_overrides.start_position == std::optional<int>{3});
  CHECK_FALSE(third.world_overrides.start.has_value());
  CHECK_FALSE(third.world_overrides.random_start);
  const app::RunOptions random = parse_run({"--start", "random", "--seed", "9"});
  CHECK(random.world_overrides.random_start);
  CHECK(random.world_overrides.random_start_seed == 9);
  CHECK_FALSE(random.world_overrides.start_position.has_value());
  for (const char *bad : {"pos:0", "pos:", "pos:x", "pos:-1"}) {
    CAPTURE(bad);
    try {
      parse_run({"--start", bad});
      FAIL("no error");
    } catch (const common::InputError &e) {
      CHECK(e.diagnostic() == std::string("error: --start pos:N needs N = 1, 2, ... (got '") + bad + "')");
    }
  }
}

TEST_CASE("run command line: --time-limit is simulated seconds, more than 0; inf is no limit") {
  CHECK(parse_run({"--time-limit", "2.5"}).time_limit_s == std::optional<double>{2.5});
  CHECK(parse_run({"--time-limit", "inf"}).time_limit_s == std::optional<double>{kInf});
  for (const char *bad : {"0", "-1"}) {
    try {
      parse_run({"--time-limit", bad});
      FAIL("no error for ", bad);
    } catch (const common::InputError &e) {
      CHECK(e.diagnostic() == fmt::format("error: --time-limit must be more than 0 simulated seconds (got {})", bad));
    }
  }
}

TEST_CASE("steps_to_reach: the control steps until simulated time reaches a time limit, at least one, saturating") {
  CHECK(app::steps_to_reach(2.0, 32) == 63);   // 1.984 s is short of 2 s, 2.016 s reaches it
  CHECK(app::steps_to_reach(3.2, 32) == 100);  // exactly 3.2 s, though 3.2 * 1000 / 32 is a hair above 100 in doubles
  CHECK(app::steps_to_reach(0.001, 32) == 1);
  CHECK(app::steps_to_reach(9.3e9, 32) == 290625000000);
  CHECK(app::steps_to_reach(1e300, 32) == std::numeric_limits<std::int64_t>::max());
  CHECK(app::steps_to_reach(kInf, 32) == std::numeric_limits<std::int64_t>::max());
}

TEST_CASE("--time-limit ends a maze run and a room run at the same step: the first at or past the limit") {
  for (const char *kind : {"run", "room"}) {
    CAPTURE(kind);
    const char *world = std::string_view(kind) == "run" ? "/lab4x4.txt" : "/ir_room.room";
    const test_cli::Ran timed = test_cli::run({kind, std::string(WORLDS_DIR) + world, "--quiet", "--time-limit", "2"});
    CHECK(timed.out.find("end: time limit (2 s of simulated time)\n") != std::string::npos);
    CHECK(timed.out.find("\nsim_time_s: 2.016\n") != std::string::npos);
  }
}

TEST_CASE("a run stopped by --time-limit ends as planned and says so; a huge limit changes nothing") {
  const test_cli::Ran timed = test_cli::run({"run", std::string(WORLDS_DIR) + "/lab4x4.txt", "--quiet", "--time-limit", "2"});
  CHECK(timed.status == 0);
  CHECK(timed.out.find("end: time limit (2 s of simulated time)\nsteps: 63\n") != std::string::npos);
  const test_cli::Ran whole = test_cli::run({"run", std::string(WORLDS_DIR) + "/lab4x4.txt", "--quiet", "--time-limit", "inf"});
  CHECK(whole.status == 0);
  CHECK(whole.out.find("end: done\n") != std::string::npos);
}

TEST_CASE("a landmark standing inside a cell: the truth walls it in where it stands on the robot's path, and the run ends done") {
  const maze::World world = maze::load_world(std::string(TEST_DATA_DIR) + "/worlds/course_landmark_in_cell.xml");
  const maze::Maze &m = world.maze();
  REQUIRE(m.width() == 11);  // cells of 1 m; the landmark (radius 0.25 m) at the centre of (0, 10)
  REQUIRE(m.landmarks().size() == 1);
  CHECK_FALSE(m.has_wall({0, 10}, maze::Side::east));
  for (const int k : {3, 5, 7, 9}) {
    CAPTURE(k);
    const maze::Maze truth = maze::with_solid_sides(m, k);
    for (const maze::Side s : maze::kSides) CHECK(truth.has_wall({0, 10}, s));
    CHECK_FALSE(truth.has_wall({1, 10}, maze::Side::east));
    CHECK_FALSE(truth.has_wall({0, 9}, maze::Side::south));
  }
  struct Case {
    sensing::ModelKind model;
    int k;
  };
  using sensing::ModelKind;
  for (const Case c : {Case{ModelKind::cell, 3}, Case{ModelKind::cell, 5}, Case{ModelKind::cell, 7},
                       Case{ModelKind::ray, 3}, Case{ModelKind::ray, 5}}) {
    CAPTURE(c.model == ModelKind::ray);
    CAPTURE(c.k);
    app::RunOptions options;
    options.output.quiet = true;
    options.model.kind = c.model;
    options.subcells = c.k;
    std::ostringstream sink;
    const app::RunSummary s = app::run_maze(options, m, sink);
    CHECK(s.reason == robot::EndReason::done);
    CHECK(s.message == "");
    CHECK(s.score.reachable_cells == 120);
  }
}

TEST_CASE("a solid standing in a cell far from its sides leaves them open in the truth") {
  maze::Maze m(3, 3);
  m.set_physical(2.0, m.wall_thickness_m(), 0.0, 0.0);  // the 0.25 m landmark at a 2 m cell's centre
  m.set_landmarks({maze::Landmark{3.0, 3.0, 1.5, 1.0, 1.0, 0.0}});
  const maze::Maze truth = maze::with_solid_sides(m, 3);  // reaches no sub-cell past the centre's
  for (const maze::Side s : maze::kSides) CHECK_FALSE(truth.has_wall({1, 1}, s));
  const maze::Maze k9 = maze::with_solid_sides(m, 9);  // sub-cells of 0.22 m: the one after the centre's holds it
  for (const maze::Side s : maze::kSides) CHECK(k9.has_wall({1, 1}, s));
}
