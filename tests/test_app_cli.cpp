// The command line as a whole (app::add_commands): one language for every subcommand - the
// descriptions' form, "did you mean", one --seed, errors naming the option typed, and the
// options given that do nothing for what was asked.

#include <doctest/doctest.h>

#include <cctype>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/cli_errors.hpp"
#include "app/cli/commands.hpp"
#include "app/run/run.hpp"
#include "app/run/run_options.hpp"
#include "common/error.hpp"
#include "mapping/sensor_model.hpp"
#include "maze/sim/profile.hpp"

namespace {

// What `maze_mapper ARGS...` reports on stderr when parsing fails ("" when it parses: the
// command then ran, so only pass command lines that fail while parsing).
std::string usage_error(std::vector<std::string> args) {
  CLI::App cli{"maze_mapper", "maze_mapper"};
  app::CommandContext context;
  app::add_commands(cli, context, args.empty() ? "run" : args.front());  // as main() builds it
  const std::vector<std::string> words = args;
  args.insert(args.begin(), "maze_mapper");
  std::vector<const char *> argv;
  for (const std::string &a : args) argv.push_back(a.c_str());
  try {
    cli.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError &e) {
    return "error: " + app::describe_usage_error(cli, e, words);
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "";
}

void collect(const CLI::App &app, std::vector<const CLI::App *> &all) {
  all.push_back(&app);
  for (const CLI::App *sub : app.get_subcommands([](const CLI::App *) { return true; })) collect(*sub, all);
}

// Every "default" in a description is written "(default ...".
bool defaults_alike(const std::string &text) {
  for (std::size_t at = text.find("default"); at != std::string::npos; at = text.find("default", at + 1)) {
    if (at == 0 || text[at - 1] != '(' || text.compare(at, 8, "default ") != 0) return false;
  }
  return true;
}

app::RunOptions options_with(bool animate) {
  app::RunOptions o;
  o.output.animate = animate;
  return o;
}

std::vector<std::string> warnings(std::string_view command, std::vector<std::string> given, const app::RunOptions &o) {
  const app::GivenOptions g{command, [given](std::string_view option) {
                              for (const std::string &name : given) {
                                if (name == option) return true;
                              }
                              return false;
                            }};
  return app::check_options_apply(g, o);
}

}  // namespace

TEST_CASE("cli: every description is lowercase and says (default X) the same way") {
  CLI::App cli{"maze_mapper", "maze_mapper"};
  app::CommandContext context;
  app::add_commands(cli, context);
  std::vector<const CLI::App *> all;
  collect(cli, all);
  CHECK(all.size() >= 13);
  int options = 0;
  for (const CLI::App *command : all) {
    CAPTURE(command->get_name());
    const std::string about = command->get_description();
    if (command != &cli) CHECK_FALSE(std::isupper(static_cast<unsigned char>(about.at(0))));
    for (const CLI::Option *o : command->get_options()) {
      const std::string text = o->get_description();
      CAPTURE(o->get_name());
      CAPTURE(text);
      REQUIRE_FALSE(text.empty());
      // "X,Y: ...", "NAME or FILE.json", "K: ..." name their value in capitals; words are lowercase.
      const bool capital_word = std::isupper(static_cast<unsigned char>(text[0])) != 0 &&
                                std::islower(static_cast<unsigned char>(text[1])) != 0;
      CHECK_FALSE(capital_word);
      CHECK(defaults_alike(text));
      ++options;
    }
  }
  CHECK(options > 100);
}

TEST_CASE("cli: a command line that names a command builds only that one; --version none") {
  const auto built = [](std::string_view first_word) {
    CLI::App cli{"maze_mapper", "maze_mapper"};
    app::CommandContext context;
    app::add_commands(cli, context, first_word);
    std::vector<std::string> names;
    for (const CLI::App *command : cli.get_subcommands({})) names.push_back(command->get_name());
    return names;
  };
  CHECK(built("robot") == std::vector<std::string>{"robot"});
  CHECK(built("map-log") == std::vector<std::string>{"map-log"});
  CHECK(built("--version").empty());
  const std::vector<std::string> all = built("");
  CHECK(all.size() == 16);
  CHECK(built("--help") == all);
  CHECK(built("rnu") == all);        // a misspelt command: the error names the nearest of all
  CHECK(built("reference") == all);  // the reference describes every command
  CHECK(usage_error({"rnu"}) == "error: unknown command 'rnu'; did you mean run?");
}

TEST_CASE("cli: --robot's help names every built-in robot") {
  CLI::App cli{"maze_mapper", "maze_mapper"};
  app::CommandContext context;
  app::add_commands(cli, context);
  for (const char *command : {"run", "batch", "compare", "plan", "scan", "convert"}) {
    CAPTURE(command);
    const std::string text = cli.get_subcommand(command)->get_option("--robot")->get_description();
    for (const maze::sim::RobotProfile &p : maze::sim::profiles()) CHECK(text.find(p.name) != std::string::npos);
  }
}

TEST_CASE("cli: a misspelt option or command gets the name it was close to") {
  CHECK(usage_error({"run", "--sede", "3"}) == "error: run has no option --sede; did you mean --seed?");
  CHECK(usage_error({"run", "--subcels=5"}) == "error: run has no option --subcels; did you mean --subcells?");
  CHECK(usage_error({"run", "--frobnicate"}) == "error: run has no option --frobnicate");
  CHECK(usage_error({"rnu"}) == "error: unknown command 'rnu'; did you mean run?");
  CHECK(usage_error({"demo", "id"}) == "error: unknown demo command 'id'; did you mean 1d?");
  CHECK(usage_error({"generate", "4x4", "--sed", "1"}) == "error: generate has no option --sed; did you mean --seed?");
  CHECK(usage_error({"run", "a.txt", "b.txt"}) == "error: unexpected argument 'b.txt'");
  CHECK(app::close_names("--max", {"--max-steps", "--model"}) == std::vector<std::string>{"--max-steps"});
  CHECK(app::close_names("--p-fre", {"--p-free", "--p-occ", "--prior"}) == std::vector<std::string>{"--p-free"});
  CHECK(app::close_names("--xyz", {"--seed", "--speed"}).empty());
}

TEST_CASE("cli: every --seed is checked by one rule") {
  const std::string negative = "error: --seed must be a whole number from 0 to 18446744073709551615 (got '-4')";
  const std::string word = "error: --seed must be a whole number from 0 to 18446744073709551615 (got 'abc')";
  const std::vector<std::vector<std::string>> commands{
      {"run"}, {"batch", "worlds"}, {"compare"}, {"plan"}, {"scan", "w.txt", "--pose", "0.5", "0.5", "0"},
      {"generate", "4x4"}, {"demo", "1d"}};
  for (std::vector<std::string> command : commands) {
    CAPTURE(command.front());
    std::vector<std::string> bad = command;
    bad.insert(bad.end(), {"--seed", "-4"});
    CHECK(usage_error(bad) == negative);
    command.insert(command.end(), {"--seed", "abc"});
    CHECK(usage_error(command) == word);
  }
  CHECK(usage_error({"run", "--seed", "18446744073709551616"}) ==
        "error: --seed must be a whole number from 0 to 18446744073709551615 (got '18446744073709551616')");
}

TEST_CASE("cli: errors name the option as the user typed it") {
  CHECK(usage_error({"plan", "--to", "1"}) == "error: --to must be X,Y (got '1')");
  CHECK(usage_error({"plan", "--from", "1;2"}) == "error: --from must be X,Y (got '1;2')");
  CHECK(usage_error({"run", "--plan-to", "x"}) == "error: --plan-to must be X,Y (got 'x')");
  CHECK(usage_error({"scan", "w.txt", "--pose", "0.5", "0.5", "north"}) ==
        "error: --pose YAW must be a finite number of radians, or of degrees with a deg suffix like 90deg (got "
        "'north')");
  CHECK(usage_error({"scan", "w.txt", "--pose", "0.5m", "0.5", "0"}) ==
        "error: --pose X must be a finite number of metres (got '0.5m')");
}

TEST_CASE("cli: options given that do nothing for what was asked are warned about, once each") {
  CHECK(warnings("run", {"--fps", "--speed"}, options_with(false)) ==
        std::vector<std::string>{"warning: --fps has no effect without --animate",
                                 "warning: --speed has no effect without --animate"});
  CHECK(warnings("run", {"--fps", "--speed", "--animate"}, options_with(true)).empty());
  CHECK(warnings("run", {"--quiet", "--animate"}, options_with(true)) ==
        std::vector<std::string>{"warning: --quiet has no effect with --animate"});
  CHECK(warnings("run", {"--dilate"}, options_with(false)) ==
        std::vector<std::string>{"warning: --dilate has no effect without --plan-to"});
  app::RunOptions planned = options_with(false);
  planned.plan.to = mapping::Cell{1, 1};
  CHECK(warnings("run", {"--dilate", "--plan-to"}, planned).empty());
  app::RunOptions plan_command = options_with(false);
  plan_command.plan.only = true;
  CHECK(warnings("plan", {"--dilate"}, plan_command).empty());
  CHECK(warnings("batch", {"--dilate"}, options_with(false)) ==
        std::vector<std::string>{"warning: --dilate has no effect: batch plans no path"});
  CHECK(warnings("run", {}, options_with(false)).empty());
  // Then the model's rules, from the set-up table (app/run/model_rules.hpp).
  CHECK(warnings("run", {"--hit-depth", "--fps"}, options_with(false)) ==
        std::vector<std::string>{"warning: --fps has no effect without --animate",
                                 "warning: --hit-depth has no effect with the cell model (read by ray)"});
  app::RunOptions pie = options_with(false);
  pie.model.kind = sensing::ModelKind::pie;
  CHECK_THROWS_WITH_AS(warnings("run", {"--p-occ"}, pie),
                       doctest::Contains("--p-free and --p-occ do not apply to the pie model"), common::InputError);
  CHECK(usage_error({"run", "--model", "pie", "--p-free", "0.2"}).starts_with(
      "error: --p-free and --p-occ do not apply to the pie model"));
}

TEST_CASE("cli: --clamp must hold the prior's log-odds") {
  CHECK(usage_error({"run", "--clamp", "0.1", "0.5"}) ==
        "error: --clamp must hold the prior's log-odds 0 (--prior 0.5) between MIN and MAX (got 0.1 0.5)");
  CHECK(usage_error({"run", "--clamp", "-0.5", "0", "--prior", "0.5"}) ==
        "error: --clamp must hold the prior's log-odds 0 (--prior 0.5) between MIN and MAX (got -0.5 0)");
  mapping::SensorModelOptions around_0_405;  // l(0.6) = 0.405
  around_0_405.prior = 0.55;
  around_0_405.p_occ = 0.7;
  around_0_405.clamp = mapping::Clamp{0.1, 2.0};
  CHECK_NOTHROW(mapping::validate(around_0_405));
  around_0_405.clamp = mapping::Clamp{0.25, 2.0};
  CHECK_THROWS_WITH_AS(mapping::validate(around_0_405),
                       "--clamp must hold the prior's log-odds 0.2007 (--prior 0.55) between MIN and MAX (got 0.25 2)",
                       common::InputError);
}

TEST_CASE("cli: a long option typed with one dash is pointed to its two-dash spelling") {
  const auto one_dash = [](const std::vector<std::string> &words) {
    CLI::App cli{"maze_mapper", "maze_mapper"};
    app::CommandContext context;
    app::add_commands(cli, context, words.front());
    return app::one_dash_long_option(cli, words);
  };
  // CLI11 alone reads -out as -o with the value "ut".
  CHECK(one_dash({"run", "-out", "results"}) ==
        "run has no option -out; did you mean --out?");
  CHECK(one_dash({"run", "-seed=3"}) == "run has no option -seed; did you mean --seed?");
  CHECK(one_dash({"batch", "merge", "-out", "all.csv"}) ==
        "merge has no option -out; did you mean --out?");
  CHECK(one_dash({"mms", "-color", "never"}) ==
        "mms has no option -color; did you mean --color?");
  CHECK(one_dash({"run", "-o", "results", "--prior", "-0.5"}).empty());  // short options and numbers
  CHECK(one_dash({"run", "--out", "results"}).empty());
  CHECK(one_dash({"batch", "a.txt", "--", "-out"}).empty());  // after --: an argument
}

TEST_CASE("cli: a world file in the command's place suggests run") {
  const std::string file = WORLDS_DIR "/maze8x8.txt";
  CHECK(usage_error({file}) == "error: unknown command '" + file + "'; to map that world: maze_mapper run " + file);
  CHECK(usage_error({"maze8x8"}) == "error: unknown command 'maze8x8'; to map that world: maze_mapper run maze8x8");
  CHECK(usage_error({"nothing_here.txt"}).starts_with("error: unknown command 'nothing_here.txt' (choose run, "));
}

TEST_CASE("cli: mms takes --color as run does; --no-color is its old spelling") {
  CLI::App cli{"maze_mapper", "maze_mapper"};
  app::CommandContext context;
  app::add_commands(cli, context);
  for (const char *command : {"run", "mms"}) {
    CAPTURE(command);
    const CLI::App *sub = cli.get_subcommand(command);
    REQUIRE(sub->get_option_no_throw("--color") != nullptr);
    CHECK(sub->get_option("--color")->get_description().find("NO_COLOR") != std::string::npos);
    CHECK(sub->get_option("--no-color")->get_group().empty());  // hidden
  }
  CHECK(usage_error({"mms", "--color", "sometimes"}).find("--color") != std::string::npos);
}
