// The options described once (app/run/option_fields.hpp): each field that CLI11 binds from
// the table sets what the summary.json echo shows under its key; every option of `run` and
// `plan` is a field of a table, so an option added to the command line and not to the echo
// fails here; and each field the table says a Webots controller takes reaches the
// controllerArgs under its key and reads back unchanged.

#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/cli/commands.hpp"
#include "app/cli/option_binding.hpp"
#include "app/run/run.hpp"
#include "common/error.hpp"
#include "maze/world/world.hpp"
#include "robot/controller_args.hpp"

namespace {

// A value each kind of field reads that differs from every default (and that the controller
// accepts: --p-occ above the prior).
std::vector<std::string> sample_words(std::string_view flag, const app::FieldRef *value) {
  static const std::map<std::string_view, std::string> own_samples{
      {"--strategy", "frontier"}, {"--model", "ray"},          {"--log-base", "10"},
      {"--pie-beta", "12"},       {"--p-occ", "0.75"},         {"--unknown", "?"},
      {"--snapshots", "7"},       {"--picture-format", "svg"}, {"--cell-size", "0.45"}};
  std::vector<std::string> words{"prog", std::string(flag)};
  if (own_samples.contains(flag)) {
    words.push_back(own_samples.at(flag));
  } else if (value == nullptr) {
    FAIL("no sample for a parsed field");
  } else if (!std::holds_alternative<bool *>(*value)) {
    const bool whole = std::holds_alternative<int *>(*value) || std::holds_alternative<std::optional<int> *>(*value);
    words.push_back(std::holds_alternative<std::string *>(*value) ? "left" : whole ? "7" : "0.45");
  }
  return words;
}

// The field bound to `concern` on a command line of its own, given its sample value.
template <typename Concern>
void give_sample(const app::OptionField<Concern> &field, Concern &concern) {
  CLI::App command;
  app::add_field_option(command, concern, field.flag);
  const app::FieldRef probe = field.value ? field.value(concern) : app::FieldRef{};
  const std::vector<std::string> words = sample_words(field.flag, field.value ? &probe : nullptr);
  std::vector<const char *> argv;
  for (const std::string &w : words) argv.push_back(w.c_str());
  command.parse(static_cast<int>(argv.size()), argv.data());
}

// Each field of Concern's table that the command line binds: given on a command line of its
// own, it changes the echo under its key and nothing else.
template <typename Concern>
void check_bound_fields_echo() {
  const nlohmann::ordered_json defaults = app::echo_fields(Concern{});
  for (const app::OptionField<Concern> &field : app::option_fields<Concern>()) {
    if (field.help == nullptr) continue;
    CAPTURE(field.flag);
    Concern concern{};
    give_sample(field, concern);
    const nlohmann::ordered_json echoed = app::echo_fields(concern);
    for (const auto &item : defaults.items()) {
      CAPTURE(item.key());
      if (item.key() == field.key) {
        CHECK(echoed.at(item.key()) != item.value());
      } else {
        CHECK(echoed.at(item.key()) == item.value());
      }
    }
  }
}

// Each field of Concern's table that parses its own text: words that are not what it reads,
// given straight to the parse (no command line's check before it, as parse_run_options
// once had), end in common::InputError naming the flag, never in another exception.
template <typename Concern>
void check_parses_refuse_wrong_words() {
  for (const app::OptionField<Concern> &field : app::option_fields<Concern>()) {
    if (field.parse == nullptr) continue;
    CAPTURE(field.flag);
    for (const std::string word : {"", "abc", "--snapshots", "1e999x", "\xeb"}) {
      CAPTURE(word);
      Concern concern{};
      try {
        field.parse(concern, word);
        FAIL("read a word that is not its type");
      } catch (const common::InputError &e) {
        CHECK(e.diagnostic().find(field.flag) != std::string::npos);
      }
    }
  }
}

template <typename Concern>
void collect_flags(std::set<std::string> &flags) {
  for (const app::OptionField<Concern> &field : app::option_fields<Concern>()) flags.insert(std::string(field.flag));
}

std::set<std::string> table_flags() {
  std::set<std::string> flags;
  collect_flags<app::RunOptions>(flags);
  collect_flags<maze::WorldOverrides>(flags);
  collect_flags<sensing::ModelOptions>(flags);
  collect_flags<mapping::SensorModelOptions>(flags);
  collect_flags<sensing::RangeModelOptions>(flags);
  collect_flags<maze::sim::SimulationOptions>(flags);
  collect_flags<app::PlanOptions>(flags);
  collect_flags<app::OutputOptions>(flags);
  collect_flags<app::LocalizationOptions>(flags);
  flags.erase("");
  return flags;
}

// The options of `name` by their long names ("--quiet"; a positional by its name).
std::set<std::string> command_options(std::string_view name) {
  CLI::App cli;
  app::CommandContext context;
  app::add_commands(cli, context, name);
  std::set<std::string> names;
  for (const CLI::Option *o : cli.get_subcommand(std::string(name))->get_options()) {
    names.insert(o->get_lnames().empty() ? o->get_name() : "--" + o->get_lnames().front());
  }
  return names;
}

// The controllerArgs run gives a Webots controller for lab4x4.txt with these options (the
// world's overrides applied as the world is read).
std::vector<std::string> controller_args(const app::RunOptions &options) {
  const maze::Maze lab4x4 = maze::load_world(std::string(WORLDS_DIR) + "/lab4x4.txt", options.world_overrides).maze();
  return robot::format_controller_args(app::controller_options(options, lab4x4, app::robot_profile(options)));
}

// Each bound field of Concern's table with a controllerArgs key: given on the command line,
// it changes that argument (and reads back into the same arguments).
template <typename Concern>
void check_fields_reach_controller(Concern &(*concern_of)(app::RunOptions &)) {
  const std::vector<std::string> defaults = controller_args(app::RunOptions{});
  for (const app::OptionField<Concern> &field : app::option_fields<Concern>()) {
    if (field.help == nullptr || field.controller_arg.empty()) continue;
    CAPTURE(field.flag);
    app::RunOptions options;
    Concern &concern = concern_of(options);
    give_sample(field, concern);
    const std::vector<std::string> args = controller_args(options);
    const std::string prefix = fmt::format("--{}=", field.controller_arg);
    std::vector<std::string> changed;
    for (const std::string &arg : args) {
      if (std::find(defaults.begin(), defaults.end(), arg) == defaults.end()) changed.push_back(arg);
    }
    CAPTURE(fmt::format("{}", fmt::join(changed, " ")));
    REQUIRE(changed.size() == 1);
    CHECK(changed.front().starts_with(prefix));
    CHECK(robot::format_controller_args(robot::parse_controller_args(args)) == args);
  }
}

}  // namespace

TEST_CASE("option fields: each bound field sets what the echo shows under its key") {
  check_bound_fields_echo<app::RunOptions>();
  check_bound_fields_echo<maze::WorldOverrides>();
  check_bound_fields_echo<sensing::ModelOptions>();
  check_bound_fields_echo<mapping::SensorModelOptions>();
  check_bound_fields_echo<sensing::RangeModelOptions>();
  check_bound_fields_echo<maze::sim::SimulationOptions>();
  check_bound_fields_echo<app::PlanOptions>();
  check_bound_fields_echo<app::OutputOptions>();
  check_bound_fields_echo<app::LocalizationOptions>();
}

TEST_CASE("option fields: a table's own parse refuses what it does not read, in an InputError") {
  check_parses_refuse_wrong_words<app::RunOptions>();
  check_parses_refuse_wrong_words<maze::WorldOverrides>();
  check_parses_refuse_wrong_words<sensing::ModelOptions>();
  check_parses_refuse_wrong_words<mapping::SensorModelOptions>();
  check_parses_refuse_wrong_words<sensing::RangeModelOptions>();
  check_parses_refuse_wrong_words<maze::sim::SimulationOptions>();
  check_parses_refuse_wrong_words<app::PlanOptions>();
  check_parses_refuse_wrong_words<app::OutputOptions>();
  check_parses_refuse_wrong_words<app::LocalizationOptions>();
}

TEST_CASE("run's parse-only command line checks values as the program does") {
  // The fuzz target's crash (fuzz_run_cli): `run WORLD --snapshots --snapshots` reached the
  // field's parse unchecked and escaped as std::bad_optional_access.
  const std::vector<const char *> argv{"maze_mapper", "run", "worln-ubc", "--snapshots", "--snapshots"};
  CHECK_THROWS_WITH_AS(app::parse_run_options(static_cast<int>(argv.size()), argv.data()),
                       "--snapshots needs a whole number (got '--snapshots')", common::InputError);
}

TEST_CASE("option fields: every option of run and plan is echoed, every field's option exists") {
  // What the echo shows under another option's name, or never: --narrow and --wide set one
  // field (subcell_columns, listed as --wide), --plan-to is plan's --to, --no-color the old
  // spelling of --color never, and --help.
  const std::set<std::string> elsewhere{"--help", "--narrow", "--plan-to", "--no-color"};
  const std::set<std::string> fields = table_flags();
  std::set<std::string> taken;
  for (const std::string_view command : {"run", "plan"}) {
    for (const std::string &option : command_options(command)) {
      CAPTURE(command);
      CAPTURE(option);
      CHECK((fields.contains(option) || elsewhere.contains(option)));
      taken.insert(option);
    }
  }
  for (const std::string &flag : fields) {
    CAPTURE(flag);
    CHECK(taken.contains(flag));
  }
}

TEST_CASE("option fields: a flag names one field of its table") {
  CHECK(app::option_field<mapping::SensorModelOptions>("--p-occ").key == "p_occ");
  CHECK(app::option_field<app::OutputOptions>("--no-trace").key == "trace");
  CHECK_THROWS_AS(app::option_field<app::OutputOptions>("--no-such"), std::logic_error);
  CLI::App command;
  maze::sim::SimulationOptions simulation;
  CHECK_THROWS_AS(app::add_field_option(command, simulation, "--seed"), std::logic_error);
}

TEST_CASE("option fields: each field a controller takes reaches its controllerArgs key") {
  check_fields_reach_controller<app::RunOptions>([](app::RunOptions &o) -> app::RunOptions & { return o; });
  check_fields_reach_controller<maze::WorldOverrides>([](app::RunOptions &o) -> auto & { return o.world_overrides; });
  check_fields_reach_controller<sensing::ModelOptions>([](app::RunOptions & o) -> auto & { return o.model; });
  check_fields_reach_controller<mapping::SensorModelOptions>([](app::RunOptions & o) -> auto & { return o.sensor; });
  check_fields_reach_controller<sensing::RangeModelOptions>(
      [](app::RunOptions & o) -> auto & { return o.range_model; });
  check_fields_reach_controller<maze::sim::SimulationOptions>(
      [](app::RunOptions & o) -> auto & { return o.simulation; });
  check_fields_reach_controller<app::PlanOptions>([](app::RunOptions & o) -> auto & { return o.plan; });
}

TEST_CASE("option fields: every controllerArgs key is an option's or the maze's or the robot's") {
  // What the controller learns from the maze (its size, origin, start heading) and from the
  // robot's profile (wheels, device names, mounts), not from an option.
  const std::set<std::string_view> from_maze_or_robot{
      "size",         "origin",        "heading", "wheel-radius", "axle",  "left-motor", "right-motor",
      "left-encoder", "right-encoder", "imu",     "gps",          "lidar", "bumper",     "range"};
  std::set<std::string_view> carried;
  const auto collect = [&carried](const auto &fields) {
    for (const auto &field : fields) carried.insert(field.controller_arg);
  };
  collect(app::option_fields<app::RunOptions>());
  collect(app::option_fields<maze::WorldOverrides>());
  collect(app::option_fields<sensing::ModelOptions>());
  collect(app::option_fields<mapping::SensorModelOptions>());
  collect(app::option_fields<sensing::RangeModelOptions>());
  collect(app::option_fields<maze::sim::SimulationOptions>());
  collect(app::option_fields<app::PlanOptions>());
  collect(app::option_fields<app::OutputOptions>());
  carried.erase("");
  for (const std::string_view key : robot::controller_arg_keys()) {
    CAPTURE(key);
    CHECK((carried.contains(key) != from_maze_or_robot.contains(key)));
    carried.erase(key);
  }
  CHECK(carried.empty());  // no field names a key the controller does not read
}
