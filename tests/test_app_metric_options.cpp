// A run in metres' options: described once in the run's table (app/run/option_fields.hpp), an
// option that does nothing for the room run asked warned about as `run` warns, and the run
// going on; the options every run takes read the same in run, room and mms.

#include <doctest/doctest.h>

#include <algorithm>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/commands.hpp"
#include "app/run/metric/run.hpp"
#include "app/run/option_fields.hpp"
#include "app/run/run_options.hpp"
#include "cli_runner.hpp"
#include "common/error.hpp"

namespace {

std::vector<std::string> room_warnings(std::set<std::string> typed, const app::RunOptions &o) {
  const app::GivenOptions given{"room", [&typed](std::string_view option) { return typed.count(std::string(option)) > 0; }};
  return app::check_metres_options_apply(given, o);
}

app::RunOptions with(explore::StrategyKind strategy, sensing::ModelKind model = sensing::ModelKind::ray) {
  app::RunOptions o = app::metres_run_options();
  o.strategy = strategy;
  o.model.kind = model;
  return o;
}

}  // namespace

TEST_CASE("room options: one that does nothing for the strategy or model asked is warned about as run warns") {
  using explore::StrategyKind;
  CHECK(room_warnings({"--goal", "--dilate"}, with(StrategyKind::frontier)) ==
        std::vector<std::string>{"warning: --goal has no effect without --strategy wavefront",
                                 "warning: --dilate has no effect without --strategy wavefront (frontier keeps the "
                                 "body's radius clear)"});
  CHECK(room_warnings({"--goal", "--dilate"}, with(StrategyKind::wavefront)).empty());
  CHECK(room_warnings({"--verbose"}, with(StrategyKind::wander)) ==
        std::vector<std::string>{"warning: --verbose has no effect without --strategy frontier (its frontier left and "
                                 "set aside are the details)"});
  CHECK(room_warnings({"--verbose"}, with(StrategyKind::frontier)).empty());
  CHECK(room_warnings({"--waypoints", "--laps"}, with(StrategyKind::wander)) ==
        std::vector<std::string>{"warning: --waypoints has no effect without --strategy waypoints",
                                 "warning: --laps has no effect without --strategy waypoints"});
  CHECK(room_warnings({"--waypoints", "--laps"}, with(StrategyKind::waypoints)).empty());
  CHECK(room_warnings({"--depth-reading", "--depth-origin"}, with(StrategyKind::frontier, sensing::ModelKind::pie)) ==
        std::vector<std::string>{"warning: --depth-reading has no effect with the pie model (read by depth)",
                                 "warning: --depth-origin has no effect with the pie model (read by depth)"});
  CHECK(room_warnings({"--depth-reading"}, with(StrategyKind::frontier, sensing::ModelKind::depth)).empty());
  CHECK(room_warnings({}, with(StrategyKind::frontier)).empty());
}

TEST_CASE("room options: an option that does not apply warns and the run goes on") {
  // --laps with wavefront: a warning on standard error, the run to the goal as without it.
  const test_cli::Ran ran = test_cli::run({"room", std::string(WORLDS_DIR) + "/ir_room.room", "--strategy", "wavefront",
                                           "--laps", "2", "--quiet"});
  CHECK(ran.status == 0);
  CHECK(ran.out.find("end: goal reached") != std::string::npos);
}

TEST_CASE("room options: every flag of the table is an option of room, and --resolution reads as in every command") {
  CLI::App cli{"maze_mapper", "maze_mapper"};
  app::CommandContext context;
  app::add_commands(cli, context);
  const CLI::App *room = cli.get_subcommand("room");
  for (const app::OptionField<app::MetresOptions> &field : app::option_fields<app::MetresOptions>()) {
    CAPTURE(field.flag);
    CHECK(room->get_option_no_throw(std::string(field.flag)) != nullptr);
  }
  const std::string resolution = room->get_option("--resolution")->get_description();
  CHECK(resolution == "LENGTH: a cell's side, m, or with its unit: 0.1m, 10cm (default 0.1)");
  // Every command that lays a grid declares it by the same function.
  const CLI::App *demo = cli.get_subcommand("demo");
  for (const CLI::App *command : {cli.get_subcommand("show"), cli.get_subcommand("batch"), demo->get_subcommand("1d"),
                                  demo->get_subcommand("pie"), demo->get_subcommand("cone")}) {
    CAPTURE(command->get_name());
    CHECK(command->get_option("--resolution")->get_description().starts_with(
        "LENGTH: a cell's side, m, or with its unit: 0.1m, 10cm (default "));
  }
  // CLI11 takes the words last first.
  std::vector<std::string> words{"0", "--resolution", "x.room", "room"};
  CHECK_THROWS_WITH_AS(cli.parse(words), "--resolution must be > 0 m (got 0)", common::InputError);
}

TEST_CASE("room options: --cells with --resolution, and a threshold not finite, are refused") {
  app::RunOptions o = app::metres_run_options();
  o.metres.cells_x = 10;
  o.metres.cells_y = 10;
  o.metres.resolution_m = 0.1;
  CHECK_THROWS_WITH_AS(app::validate_metres(o), "give --cells or --resolution, not both", common::InputError);
  app::RunOptions t = app::metres_run_options();
  t.threshold = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH_AS(app::validate_metres(t), doctest::Contains("--threshold must be a finite"), common::InputError);
}

TEST_CASE("room options: the options every run takes read the same, word for word, in run, room and mms") {
  CLI::App cli{"maze_mapper", "maze_mapper"};
  app::CommandContext context;
  app::add_commands(cli, context);
  for (const char *flag : {"--robot", "--model", "--seed", "--noise", "--clamp", "--time-limit", "--max-steps", "--quiet",
                           "--out", "--threshold", "--p-free", "--log-base"}) {
    CAPTURE(flag);
    const std::string help = app::option_help(flag);
    for (const char *name : {"run", "room", "mms"}) {
      CAPTURE(name);
      const CLI::Option *option = cli.get_subcommand(name)->get_option_no_throw(flag);
      REQUIRE(option != nullptr);
      CHECK(option->get_description() == help);
    }
  }
}

TEST_CASE("room options: a strategy is parsed from the one strategy table, cells or metres") {
  CHECK(explore::parse_strategy("frontier", explore::StrategySpace::cells) == explore::StrategyKind::frontier);
  CHECK(explore::parse_strategy("frontier", explore::StrategySpace::metres) == explore::StrategyKind::frontier);
  CHECK(explore::parse_strategy("wander", explore::StrategySpace::metres) == explore::StrategyKind::wander);
  CHECK(explore::strategy_names(explore::StrategySpace::cells) == "dfs, frontier, left-wall, right-wall or floodfill");
  CHECK(explore::strategy_names(explore::StrategySpace::metres) == "waypoints, wavefront, frontier or wander");
  CHECK_THROWS_WITH_AS(explore::parse_strategy("wander"),
                       "unknown --strategy 'wander' (choose dfs, frontier, left-wall, right-wall or floodfill)",
                       common::InputError);
  CHECK_THROWS_WITH_AS(test_cli::run({"room", std::string(WORLDS_DIR) + "/ir_room.room", "--strategy", "dfs"}),
                       "--strategy must be waypoints, wavefront, frontier or wander in a room (got 'dfs')",
                       common::InputError);
}
