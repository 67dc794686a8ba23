#include "app/cli/cli_errors.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <system_error>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/run/shipped_worlds.hpp"
#include "common/error.hpp"
#include "common/parse_number.hpp"

namespace app {
namespace {

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

std::vector<std::string> suggestable_option_names(const CLI::App &app) {
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

// The subcommand of `command` called `word`, or null.
const CLI::App *subcommand_named(const CLI::App &command, const std::string &word) {
  if (word.starts_with("-")) return nullptr;
  for (const CLI::App *sub : command.get_subcommands([](const CLI::App *) { return true; })) {
    if (sub->get_name() == word) return sub;
  }
  return nullptr;
}

// Whether `word`, in the command's place, is a world to map: a file that is there, or a
// shipped world's name (`maze_mapper maze8x8.txt` meant `maze_mapper run maze8x8.txt`).
bool names_a_world(const std::string &word) {
  if (word.starts_with("-")) return false;
  std::error_code error;
  return std::filesystem::is_regular_file(word, error) || shipped_world(word).has_value();
}

// The first word the command line did not expect, told with the names it may have meant.
std::string unexpected(const CLI::App &cli, const std::vector<std::string> &extras) {
  // An unknown option first: the words after it may be its value.
  std::string first;
  for (const std::string &word : extras) {
    if (first.empty() || (word.starts_with("-") && !first.starts_with("-"))) first = word;
  }
  if (first.starts_with("--")) first = first.substr(0, first.find('='));
  const CLI::App &app = chosen(cli);
  const std::string where = &app == &cli ? "maze_mapper" : app.get_name();
  if (&app == &cli && names_a_world(extras.front())) {
    return fmt::format("unknown command '{}'; to map that world: maze_mapper run {}", extras.front(), extras.front());
  }
  if (first.starts_with("-")) {
    const std::vector<std::string> close = close_option_names(first, suggestable_option_names(app));
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

// Whether `word` names `option` ("--clamp", "--clamp=1", "-o").
bool names(const std::string &word, const CLI::Option &option) {
  if (word.starts_with("--")) return option.check_lname(word.substr(2, word.find('=') - 2));
  return word.size() == 2 && word[0] == '-' && option.check_sname(word.substr(1));
}

// The option of the chosen command that got fewer values than it takes: one holding some
// values but too few, else the last one named on the command line (CLI11 stops at the end
// of the words, so the option short of values is the last one given).
const CLI::Option *short_of_values(const CLI::App &cli, const std::vector<std::string> &words) {
  const CLI::App &app = chosen(cli);
  for (const CLI::Option *o : app.get_options()) {
    const std::size_t got = o->results().size();
    if (got > 0 && got < static_cast<std::size_t>(o->get_items_expected_min())) return o;
  }
  for (auto word = words.rbegin(); word != words.rend(); ++word) {
    for (const CLI::Option *o : app.get_options()) {
      if (o->get_items_expected_max() > 0 && names(*word, *o)) return o;
    }
  }
  return nullptr;
}

// An option of the chosen command given more values than it takes (CLI11 hands it every
// word up to the next option), or none.
const CLI::Option *past_its_values(const CLI::App &cli) {
  for (const CLI::Option *o : chosen(cli).get_options()) {
    const int most = o->get_items_expected_max();
    if (most > 0 && o->results().size() > static_cast<std::size_t>(most)) return o;
  }
  return nullptr;
}

// The value a numeric option's type asks for, in words; "" for another type.
std::string wanted_number(const std::string &type_name) {
  if (type_name == "INT") return "a whole number";
  if (type_name == "UINT") return "a whole number from 0";
  if (type_name == "FLOAT") return "a number";
  return "";
}

// Whether `text` reads as the type asks (common/parse_number.hpp); a FLOAT may be inf or nan,
// which the option's own check refuses in its own words ("must be finite").
bool reads_as(const std::string &type_name, const std::string &text) {
  if (type_name == "INT") return common::parse_number<long long>(text).has_value();
  if (type_name == "UINT") return common::parse_number<unsigned long long>(text).has_value();
  return common::parse_real(text).has_value();
}

// ", out of range" when `text` is a number of the type's form past its range ("1e999" for a
// FLOAT: not a finite double; 2^63 for an INT), else "".
std::string_view range_note_of(const std::string &type_name, const std::string &text) {
  if (type_name == "INT") return common::range_note<long long>(text);
  if (type_name == "UINT") return common::range_note<unsigned long long>(text);
  return common::range_note<double>(text);
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

CLI::Validator usage_check(const std::string &option, std::function<std::string(const std::string &)> check) {
  return CLI::Validator(
      [option, check = std::move(check)](std::string &value) {
        const std::string wrong = check(value);
        if (!wrong.empty()) throw common::InputError(fmt::format("{} {}", option, wrong));
        return std::string();
      },
      "");
}

void check_values_ourselves(CLI::App &command) {
  for (CLI::Option *option : command.get_options()) {
    if (option->get_type_size_max() == 0) continue;  // a flag
    const std::string name = option->get_name();
    const std::string type = option->get_type_name();
    const std::string number = wanted_number(type);
    option->check(usage_check(name, [type, number](const std::string &value) {
      if (value.empty()) return std::string("must not be empty");
      if (!number.empty() && !reads_as(type, value)) {
        return fmt::format("needs {} (got '{}'{})", number, value, range_note_of(type, value));
      }
      return std::string();
    }));
  }
  for (CLI::App *sub : command.get_subcommands([](CLI::App *) { return true; })) check_values_ourselves(*sub);
}

std::string describe_usage_error(const CLI::App &cli, const CLI::ParseError &error,
                                 const std::vector<std::string> &words) {
  if (dynamic_cast<const CLI::ExtrasError *>(&error) != nullptr) {
    const std::vector<std::string> extras = cli.remaining(true);
    if (!extras.empty()) return unexpected(cli, extras);
  }
  if (dynamic_cast<const CLI::ArgumentMismatch *>(&error) != nullptr) {
    if (const CLI::Option *o = past_its_values(cli)) {
      const auto &values = o->results();
      return unexpected(cli, {values.begin() + o->get_items_expected_max(), values.end()});
    }
    if (const CLI::Option *o = short_of_values(cli, words)) {
      const int needed = o->get_items_expected_min();
      const std::size_t got = o->results().size();
      return needed <= 1 ? fmt::format("{} needs a value", o->get_name())
                         : fmt::format("{} needs {} values (got {})", o->get_name(), needed, got);
    }
  }
  if (dynamic_cast<const CLI::ConversionError *>(&error) != nullptr) {
    // Values are checked by check_values_ourselves; what is left is a flag given a value.
    for (auto word = words.rbegin(); word != words.rend(); ++word) {
      const std::size_t equals = word->find('=');
      if (!word->starts_with("--") || equals == std::string::npos) continue;
      for (const CLI::Option *o : chosen(cli).get_options()) {
        if (o->get_items_expected_max() == 0 && names(*word, *o)) {
          return fmt::format("{} is a flag: it takes no value, or true or false (got '{}')", o->get_name(),
                             word->substr(equals + 1));
        }
      }
    }
  }
  if (dynamic_cast<const CLI::RequiredError *>(&error) != nullptr) {
    const CLI::App &app = chosen(cli);
    for (const CLI::Option *o : app.get_options()) {
      if (o->get_required() && o->count() == 0) return fmt::format("{} needs {}", app.get_name(), o->get_name());
    }
  }
  return error.what();  // a case the program does not word itself (none known)
}

std::string one_dash_long_option(const CLI::App &cli, const std::vector<std::string> &words) {
  const CLI::App *command = &cli;
  for (const std::string &word : words) {
    if (word == "--") break;  // the rest are arguments, not options
    if (const CLI::App *sub = subcommand_named(*command, word)) {
      command = sub;
      continue;
    }
    if (word.size() < 3 || word[0] != '-' || word[1] == '-') continue;
    const std::string name = word.substr(1, word.find('=') - 1);
    for (const CLI::Option *o : command->get_options()) {
      if (!o->check_lname(name)) continue;
      const std::string where = command == &cli ? "maze_mapper" : command->get_name();
      return fmt::format("{} has no option {}; did you mean --{}?", where,
                         word.substr(0, word.find('=')), name);
    }
  }
  return "";
}

}  // namespace app
