#pragma once
// The options of a run, each described once: the command-line option that sets it, its help
// (with its default, read from the options themselves), where it lives in RunOptions and its
// key in summary.json's "options" echo, and the Webots controllerArgs key that carries it to a
// controller. The command line registers options from here (app/cli/option_binding.hpp) and
// the echo writes every field from here (app/report/outputs.cpp); docs/output.md lists the
// echo's keys.
//
// A table a concern: option_fields<mapping::SensorModelOptions>() holds --p-free, --p-occ,
// --prior, --log-base and --clamp, and serves every command that takes a sensor model (run,
// plan, batch, room, explain, demo 1d). The run's own table, option_fields<RunOptions>(),
// holds its top-level fields and, as entries without an option, the concerns' objects.
//
// A field is one of three kinds:
// - plain: a bool, number or string that CLI11 reads as it is (`value` set): a bool is a
//   flag, and a flag named --no-X clears it;
// - parsed: text that `parse` turns into the field (names of enums, units converted), with
//   `echo` writing it back;
// - own code: `help` is null, the option is registered by its own function in app/cli
//   (--seed, --clamp, --start, --goal, --max-steps, --out and the other options whose arity,
//   checks or help vary with the command); the table still names its flag and key, and
//   tests/test_app_option_fields.cpp checks each flag is an option of `run` or `plan`.

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "app/run/run_options.hpp"

namespace app {

// A plain field, as CLI11 binds it.
using FieldRef = std::variant<bool *, int *, std::int64_t *, std::uint64_t *, double *, std::string *,
                              std::optional<int> *, std::optional<double> *, std::optional<std::int64_t> *>;

template <typename Concern>
struct OptionField {
  std::string_view key;   // summary.json: the key in the concern's object
  std::string_view flag;  // the option that sets it ("" when no option sets it alone)
  // The Webots controllerArgs key that carries it to a controller (robot/controller_args.hpp:
  // `maze_mapper convert` writes it, the controller reads it back); "" when the controller
  // does not take it.
  std::string_view controller_arg;
  // The help line given the options before parsing (their defaults); null: registered by its
  // own code (see above).
  std::string (*help)(const Concern &defaults) = nullptr;
  FieldRef (*value)(Concern &) = nullptr;                       // plain
  void (*parse)(Concern &, const std::string &text) = nullptr;  // parsed
  // A parsed field's value as CLI11's help names it and the command line checks it
  // (app/cli/cli_errors.hpp): "FLOAT" for a number, "" for text.
  std::string_view value_type;
  nlohmann::ordered_json (*echo)(const Concern &) = nullptr;  // its value in summary.json
};

template <typename Concern>
std::span<const OptionField<Concern>> option_fields();

template <>
std::span<const OptionField<RunOptions>> option_fields();
template <>
std::span<const OptionField<maze::WorldOverrides>> option_fields();
template <>
std::span<const OptionField<sensing::ModelOptions>> option_fields();
template <>
std::span<const OptionField<mapping::SensorModelOptions>> option_fields();
template <>
std::span<const OptionField<sensing::RangeModelOptions>> option_fields();
template <>
std::span<const OptionField<maze::sim::SimulationOptions>> option_fields();
template <>
std::span<const OptionField<PlanOptions>> option_fields();
template <>
std::span<const OptionField<OutputOptions>> option_fields();
template <>
std::span<const OptionField<LocalizationOptions>> option_fields();
// A run in metres' own options; their echo is the room report's own keys, so they have no `echo`.
template <>
std::span<const OptionField<MetresOptions>> option_fields();

// The help line of the run's option `flag` ("--robot", "--seed", "--max-steps", "--out", ...),
// the same words in every command that takes it and in the Python runner: a table field's
// help given the options' defaults, or the help of an option registered by its own code.
// std::logic_error when no run option is so named.
std::string option_help(std::string_view flag);

// The field the option `flag` sets in Concern's table; std::logic_error when it has none (a
// slip in the program, not in the input).
template <typename Concern>
const OptionField<Concern> &option_field(std::string_view flag) {
  for (const OptionField<Concern> &field : option_fields<Concern>()) {
    if (field.flag == flag) return field;
  }
  throw std::logic_error("no option field " + std::string(flag));
}

// The concern's fields as summary.json's "options" echoes them: {key: value, ...}.
template <typename Concern>
nlohmann::ordered_json echo_fields(const Concern &concern) {
  nlohmann::ordered_json object = nlohmann::ordered_json::object();
  for (const OptionField<Concern> &field : option_fields<Concern>())
    object[std::string(field.key)] = field.echo(concern);
  return object;
}

// "cell, ray (a lidar); bump (bumpers); depth, pie, cone (range sensors)": the set-ups by
// the devices they read, for --model's help.
std::string models_by_device();

// "hambot; bumper-depth for bump and depth, ir-ring for pie and cone": the set-ups' default
// robots, for --robot's help.
std::string default_robots();

// "hambot, hambot-2025, ...": the built-in robot profiles' names.
std::string robot_names();

}  // namespace app
