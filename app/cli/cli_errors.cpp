#include "app/cli/cli_errors.hpp"

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

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

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbours cost one each.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

// The subcommand the command line chose, the deepest one (demo 1d: 1d), or the top level.
const CLI::App &chosen(const CLI::App &cli) {
  const CLI::App *app = &cli;
  while (!app->get_subcommands().empty()) app = app->get_subcommands().front();
  return *app;
}

std::vector<std::string> option_names(const CLI::App &app) {
  std::vector<std::string> names;
  for (const CLI::Option *o : app.get_options()) {
    if (o->get_group().empty()) continue;  // hidden: an old spelling, not one to suggest
    for (const std::string &l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string &s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

std::vector<std::string> command_names(const CLI::App &app) {
  std::vector<std::string> names;
  for (const CLI::App *sub : app.get_subcommands([](const CLI::App *) { return true; })) {
    if (sub->get_group().empty()) continue;  // hidden (the build's __reference)
    names.push_back(sub->get_name());
  }
  return names;
}

std::string either(const std::vector<std::string> &names) {
  return names.size() == 1 ? names[0] : fmt::format("{} or {}", names[0], names[1]);
}

// The options `typed` may have meant. A short option is one letter, and every other letter is
// one edit from it: -q means the long options starting with q (--quiet), or the same letter in
// the other case; a long name typed with one dash (-quiet) is read with two.
std::vector<std::string> close_option_names(const std::string &typed, const std::vector<std::string> &names) {
  if (typed.size() == 2 && typed[1] != '-') {
    std::vector<std::string> close;
    for (const std::string &name : names) {
      const bool long_with_letter = name.size() > 3 && name.starts_with("--") && name[2] == typed[1];
      const bool other_case = name.size() == 2 && name != typed &&
                              std::tolower(static_cast<unsigned char>(name[1])) == std::tolower(static_cast<unsigned char>(typed[1]));
      if (long_with_letter || other_case) close.push_back(name);
    }
    if (close.size() > 2) close.clear();  // -s: --seed, --strategy, --subcells... no guess
    return close;
  }
  if (typed.size() > 2 && typed[1] != '-') return close_names("-" + typed, names);
  return close_names(typed, names);
}

// The first word CLI11 did not expect, told with the names it may have meant.
std::string unexpected(const CLI::App &cli, const std::string &words) {
  // An unknown option first: the words after it may be its value (CLI11 lists them in no
  // set order).
  std::istringstream in(words);
  std::string first;
  for (std::string word; in >> word;) {
    if (first.empty() || (word.starts_with("-") && !first.starts_with("-"))) first = word;
  }
  if (first.starts_with("--")) first = first.substr(0, first.find('='));
  const CLI::App &app = chosen(cli);
  const std::string where = &app == &cli ? "maze_mapper" : app.get_name();
  if (first.starts_with("-")) {
    const std::vector<std::string> close = close_option_names(first, option_names(app));
    return close.empty() ? fmt::format("{} has no option {}", where, first)
                         : fmt::format("{} has no option {}; did you mean {}?", where, first, either(close));
  }
  const std::vector<std::string> commands = command_names(app);
  if (commands.empty()) return fmt::format("unexpected argument '{}'", first);
  const std::vector<std::string> close = close_names(first, commands);
  const std::string kind = &app == &cli ? "command" : fmt::format("{} command", where);
  return close.empty() ? fmt::format("unknown {} '{}' (choose {})", kind, first, fmt::join(commands, ", "))
                       : fmt::format("unknown {} '{}'; did you mean {}?", kind, first, either(close));
}

}  // namespace

std::vector<std::string> close_names(std::string_view typed, const std::vector<std::string> &names) {
  const std::size_t dashes = typed.find_first_not_of('-') == std::string_view::npos ? 0 : typed.find_first_not_of('-');
  const std::size_t letters = typed.size() - dashes;
  const std::size_t reach = letters <= 3 ? 1 : 2;
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const std::string &name : names) {
    const std::size_t d = edit_distance(typed, name);
    if (d <= reach) scored.emplace_back(d, name);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
  std::vector<std::string> close;
  for (const auto &[d, name] : scored) {
    if (d == scored.front().first) close.push_back(name);
  }
  if (close.empty() && letters >= 2) {
    for (const std::string &name : names) {
      if (name.starts_with(typed)) close.push_back(name);
    }
    if (close.size() != 1) close.clear();
  }
  return close;
}

std::string describe_usage_error(const CLI::App &cli, const CLI::ParseError &error) {
  const std::string text = error.what();
  static const std::regex conversion("Could not convert: (\\S+) = (.*)");
  static const std::regex missing("(\\S+): ([0-9]+) required \\S+ missing");
  static const std::regex too_few("(\\S+): At least ([0-9]+) required but received ([0-9]+)");
  static const std::regex invalid("(\\S+): (must .*)");
  static const std::regex extras("The following arguments? (?:was|were) not expected: (.*)");
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
  if (dynamic_cast<const CLI::ExtrasError *>(&error) != nullptr && std::regex_match(text, m, extras)) {
    return unexpected(cli, m[1].str());
  }
  return text;
}

}  // namespace app
