#pragma once
// Registers options with CLI11 from their one description (app/run/option_fields.hpp): the
// flag, the help with its default, and the field it sets or the parse that sets it.
// Commands list the flags they take, in the order their help shows them:
//
//   add_field_options(command, o.sensor, {"--p-free", "--p-occ", "--prior", "--log-base"});

#include <initializer_list>
#include <string>
#include <string_view>
#include <variant>

#include <CLI/CLI.hpp>

#include "app/run/option_fields.hpp"

namespace app {

// The option `flag` of Concern's table, bound to `concern` (which must outlive the parse);
// its help shows the default `concern` holds now. A field without a help line is registered
// by its own code: std::logic_error.
template <typename Concern>
CLI::Option *add_field_option(CLI::App &command, Concern &concern, std::string_view flag) {
  const OptionField<Concern> &field = option_field<Concern>(flag);
  if (field.help == nullptr) throw std::logic_error("option " + std::string(flag) + " has its own registration");
  const std::string name(flag);
  const std::string help = field.help(concern);
  if (field.value == nullptr) {
    CLI::Option *option = command.add_option_function<std::string>(
        name, [&concern, parse = field.parse](const std::string &text) { parse(concern, text); }, help);
    if (!field.value_type.empty()) option->type_name(std::string(field.value_type));
    return option;
  }
  return std::visit(
      [&](auto *value) -> CLI::Option * {
        if constexpr (std::is_same_v<decltype(value), bool *>) {
          // --no-X clears the field; every other flag sets it.
          return command.add_flag(name.starts_with("--no-") ? name + "{false}" : name, *value, help);
        } else {
          return command.add_option(name, *value, help);
        }
      },
      field.value(concern));
}

template <typename Concern>
void add_field_options(CLI::App &command, Concern &concern, std::initializer_list<std::string_view> flags) {
  for (const std::string_view flag : flags) add_field_option(command, concern, flag);
}

}  // namespace app
