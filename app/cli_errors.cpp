#include "cli_errors.hpp"

#include <regex>
#include <string_view>

#include <fmt/format.h>

namespace app {
namespace {

// The option called `name` in the command line's subcommand or the top level, or nullptr.
const CLI::Option *find_option(const CLI::App &cli, const std::string &name) {
  for (const CLI::App *sub : cli.get_subcommands()) {
    if (const CLI::Option *o = sub->get_option_no_throw(name)) return o;
  }
  return cli.get_option_no_throw(name);
}

// What CLI11's type name asks for, in words.
std::string wanted(std::string_view type_name) {
  if (type_name == "INT") return "a whole number";
  if (type_name == "UINT") return "a whole number from 0";
  if (type_name == "FLOAT") return "a number";
  return "a value of type " + std::string(type_name);
}

}  // namespace

std::string describe_usage_error(const CLI::App &cli, const CLI::ParseError &error) {
  const std::string text = error.what();
  static const std::regex conversion("Could not convert: (\\S+) = (.*)");
  static const std::regex missing("(\\S+): ([0-9]+) required \\S+ missing");
  static const std::regex too_few("(\\S+): At least ([0-9]+) required but received ([0-9]+)");
  static const std::regex invalid("(-\\S+): (must .*)");
  std::smatch m;
  if (std::regex_match(text, m, conversion)) {
    const CLI::Option *o = find_option(cli, m[1].str());
    const std::string type = o != nullptr ? o->get_type_name() : std::string("FLOAT");
    return fmt::format("{} needs {} (got '{}')", m[1].str(), wanted(type), m[2].str());
  }
  if (std::regex_match(text, m, missing)) {
    return m[2].str() == "1" ? fmt::format("{} needs a value", m[1].str())
                             : fmt::format("{} needs {} values", m[1].str(), m[2].str());
  }
  if (std::regex_match(text, m, too_few)) {
    return fmt::format("{} needs {} values (got {})", m[1].str(), m[2].str(), m[3].str());
  }
  if (dynamic_cast<const CLI::ValidationError *>(&error) != nullptr && std::regex_match(text, m, invalid)) {
    return fmt::format("{} {}", m[1].str(), m[2].str());
  }
  return text;
}

}  // namespace app
