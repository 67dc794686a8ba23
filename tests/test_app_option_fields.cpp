// The options described once (app/run/option_fields.hpp): each field that CLI11 binds from
// the table sets what the summary.json echo shows under its key, and every option of `run`
// and `plan` is a field of a table, so an option added to the command line and not to the
// echo fails here.

#include <doctest/doctest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/commands.hpp"
#include "app/cli/option_binding.hpp"

namespace {

// A value each kind of field reads that differs from every default.
std::vector<std::string> sample_words(std::string_view flag, const app::FieldRef *value) {
  static const std::map<std::string_view, std::string> parsed{
      {"--strategy", "frontier"}, {"--model", "pie"}, {"--log-base", "10"}, {"--pie-beta", "12"}};
  std::vector<std::string> words{"prog", std::string(flag)};
  if (value == nullptr) {
    REQUIRE(parsed.contains(flag));
    words.push_back(parsed.at(flag));
  } else if (!std::holds_alternative<bool *>(*value)) {
    words.push_back(std::holds_alternative<std::string *>(*value) ? "left" : "7");
  }
  return words;
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
    CLI::App command;
    app::add_field_option(command, concern, field.flag);
    const app::FieldRef probe = field.value ? field.value(concern) : app::FieldRef{};
    std::vector<std::string> words = sample_words(field.flag, field.value ? &probe : nullptr);
    std::vector<const char *> argv;
    for (const std::string &w : words) argv.push_back(w.c_str());
    command.parse(static_cast<int>(argv.size()), argv.data());
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

}  // namespace

TEST_CASE("option fields: each bound field sets what the echo shows under its key") {
  check_bound_fields_echo<app::RunOptions>();
  check_bound_fields_echo<sensing::ModelOptions>();
  check_bound_fields_echo<mapping::SensorModelOptions>();
  check_bound_fields_echo<sensing::RangeModelOptions>();
  check_bound_fields_echo<maze::sim::SimulationOptions>();
  check_bound_fields_echo<app::PlanOptions>();
  check_bound_fields_echo<app::OutputOptions>();
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
