#include "common/parse_number.hpp"
#include "app/cli/cli_errors.hpp"
#include "app/cli/cli_options.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "app/cli/option_binding.hpp"
#include "app/run/shipped_worlds.hpp"
#include "common/standard_streams.hpp"

namespace app {

std::optional<std::array<double, 2>> metres_point(std::string_view text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string_view::npos) return std::nullopt;
  std::array<double, 2> point{};
  const std::string_view parts[2] = {text.substr(0, comma), text.substr(comma + 1)};
  for (std::size_t k = 0; k < 2; ++k) {
    const std::optional<Length> length = length_of(common::trim_blanks(parts[k]));
    if (!length || length->unit == LengthUnit::none || !std::isfinite(length->value)) return std::nullopt;
    point[k] = metres(*length);
  }
  return point;
}

namespace {

bool whole_number(std::string_view text, int &value) {
  const std::optional<int> number = common::parse_number_trimmed<int>(text);
  if (number) value = *number;
  return number.has_value();
}

// "X,Y", or nothing.
std::optional<maze::Cell> cell_of(std::string_view text) {
  const std::size_t comma = text.find(',');
  maze::Cell c;
  if (comma == std::string_view::npos || !whole_number(text.substr(0, comma), c.x) ||
      !whole_number(text.substr(comma + 1), c.y)) {
    return std::nullopt;
  }
  return c;
}

std::optional<maze::Side> heading_of(std::string_view text) {
  constexpr std::pair<char, maze::Side> kHeadings[] = {
      {'N', maze::Side::north}, {'E', maze::Side::east}, {'S', maze::Side::south}, {'W', maze::Side::west}};
  for (const auto &[letter, side] : kHeadings) {
    if (text.size() == 1 && std::toupper(static_cast<unsigned char>(text[0])) == letter) return side;
  }
  return std::nullopt;
}

// A metres start's YAW in a maze, where the robot faces a side: a heading letter, or degrees
// from east (with or without deg) on a quarter turn.
std::optional<maze::Side> side_of_yaw(std::string_view text) {
  if (const std::optional<maze::Side> letter = heading_of(text)) return letter;
  if (text.ends_with("deg")) text.remove_suffix(3);
  const std::optional<double> degrees = common::parse_number<double>(text);
  if (!degrees || std::fmod(*degrees, 90.0) != 0.0) return std::nullopt;
  constexpr maze::Side kQuarters[] = {maze::Side::east, maze::Side::north, maze::Side::west, maze::Side::south};
  const double quarter = std::fmod(*degrees / 90.0, 4.0);
  return kQuarters[static_cast<int>(quarter < 0 ? quarter + 4.0 : quarter)];
}

// --start X,Y[,HEADING]: the cell, and the heading (north unless given); Xm,Ym[,YAW]: the
// place in metres (app/run/option_values.hpp's lengths); pos:N, random: the world's N-th
// start position, or one of them.
void parse_start(const std::string &text, maze::WorldOverrides &o) {
  o.start.reset();
  o.start_position.reset();
  o.random_start = text == "random";
  if (o.random_start) return;
  if (text.starts_with("pos:")) {
    int n = 0;
    if (!whole_number(std::string_view(text).substr(4), n) || n < 1) {
      throw common::InputError(fmt::format("--start pos:N needs N = 1, 2, ... (got '{}')", text));
    }
    o.start_position = n;
    return;
  }
  o.start_m.reset();
  const std::size_t second = text.find(',', text.find(',') + 1);
  const std::string_view where = std::string_view(text).substr(0, second);
  o.start = cell_of(where);
  if (!o.start) o.start_m = metres_point(where);
  o.start_heading = maze::Side::north;
  if (second != std::string::npos) {
    const std::string_view after = std::string_view(text).substr(second + 1);
    const std::optional<maze::Side> heading = o.start ? heading_of(after) : side_of_yaw(after);
    if (heading) {
      o.start_heading = *heading;
    } else {
      o.start.reset();
      o.start_m.reset();
    }
  }
  if (!o.start && !o.start_m) {
    throw common::InputError(fmt::format(
        "--start must be X,Y[,HEADING] (a cell, HEADING N, E, S or W) or Xm,Ym[,YAW] (metres, YAW N, E, S or W, or "
        "degrees 0, 90, 180 or 270) (got '{}')",
        text));
  }
}

// --goal X,Y[;X,Y...]
std::vector<maze::Cell> parse_goals(const std::string &text) {
  std::vector<maze::Cell> goals;
  std::string_view rest(text);
  for (;;) {
    const std::size_t semicolon = rest.find(';');
    const std::optional<maze::Cell> goal = cell_of(rest.substr(0, semicolon));
    if (!goal) {
      throw common::InputError(fmt::format("--goal must be X,Y, a list X,Y;X,Y;... or centre (got '{}')", text));
    }
    goals.push_back(*goal);
    if (semicolon == std::string_view::npos) return goals;
    rest.remove_prefix(semicolon + 1);
  }
}

}  // namespace

void add_color_option(CLI::App &command, ColorChoice &color) {
  command.add_option_function<std::string>(
      "--color", [&color](const std::string &text) { color = parse_color_choice(text); },
      "WHEN: ANSI colours auto (when standard output is a terminal and NO_COLOR is not set), always or never "
      "(default auto)");
  command
      .add_flag_callback("--no-color",
                         [&color] {
                           common::print_stderr("{}\n", old_spelling_warning("--no-color", "--color never"));
                           color = ColorChoice::never;
                         },
                         "the old spelling of --color never")
      ->group("");
}

CLI::Option *accept_shipped_world_names(CLI::Option *world) {
  return world->transform([](const std::string &given) { return world_argument(given); });
}

namespace {

CLI::Option *add_seed_option_helped(CLI::App &command, std::uint64_t &seed, const std::string &help) {
  const CLI::Validator whole_from_zero = usage_check("--seed", [](const std::string &text) {
    return common::parse_number<std::uint64_t>(text) ? std::string()
                                                       : fmt::format("must be a whole number from 0 to {} (got '{}')",
                                                                     std::numeric_limits<std::uint64_t>::max(), text);
  });
  return command.add_option("--seed", seed, help)->check(whole_from_zero);
}

}  // namespace

CLI::Option *add_seed_option(CLI::App &command, std::uint64_t &seed, const std::string &what) {
  return add_seed_option_helped(command, seed, fmt::format("N: seed of {} (default {})", what, seed));
}

CLI::Option *add_run_seed_option(CLI::App &command, std::uint64_t &seed) {
  return add_seed_option_helped(command, seed, option_help("--seed"));
}

CLI::Option *add_out_option(CLI::App &command, std::string &out_dir) {
  return command.add_option("-o,--out", out_dir, option_help("--out"));
}

mapping::Cell parse_cell(const std::string &text, const std::string &option) {
  const std::optional<maze::Cell> c = cell_of(text);
  if (!c) throw common::InputError(fmt::format("{} must be X,Y (got '{}')", option, text));
  return mapping::Cell{c->x, c->y};
}

void add_cell_size_option(CLI::App &command, maze::WorldOverrides &overrides) {
  add_field_option(command, overrides, "--cell-size");
}

void add_world_options(CLI::App &command, maze::WorldOverrides &overrides) {
  add_cell_size_option(command, overrides);
  command.add_option_function<std::string>(
      "--start", [&overrides](const std::string &text) { parse_start(text, overrides); },
      "X,Y[,HEADING], Xm,Ym[,YAW], pos:N or random: start cell, facing N, E, S or W (default N); a place in "
      "metres, YAW N, E, S, W or degrees from east; the world's N-th start position; or one of them picked by --seed "
      "(default the world's start)");
  command
      .add_option_function<std::vector<std::string>>(
          "--goal",
          [&overrides](const std::vector<std::string> &texts) {
            overrides.goals.reset();
            overrides.centre_goals = false;
            std::vector<maze::Cell> all;
            for (const std::string &text : texts) {
              if (text == "centre" || text == "center") {
                if (texts.size() > 1) throw common::InputError("--goal centre stands alone (it names the centre cells)");
                overrides.centre_goals = true;
                continue;
              }
              const std::vector<maze::Cell> goals = parse_goals(text);
              if (goals.size() > 1) {
                std::string repeated;
                for (const maze::Cell &g : goals) repeated += fmt::format("{}--goal {},{}", repeated.empty() ? "" : " ", g.x, g.y);
                common::print_stderr("{}\n", old_spelling_warning("--goal " + text, repeated));
              }
              all.insert(all.end(), goals.begin(), goals.end());
            }
            if (!all.empty()) overrides.goals = all;
          },
          "X,Y|centre: a goal cell, in place of the world's; repeat it for more (--goal 7,7 --goal 7,8); "
          "centre: the maze's centre cells (2x2 on an even size, the micromouse convention) (default the world's)")
      ->expected(1)
      ->allow_extra_args(false)  // --goal 3,3 WORLD: the world is not a goal
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

CLI::Option *add_old_spelling(CLI::App &command, const std::string &old_name, const std::string &new_name,
                              std::function<void(const std::string &)> take) {
  return command
      .add_option_function<std::string>(
          old_name,
          [old_name, new_name, take](const std::string &value) {
            common::print_stderr("{}\n", old_spelling_warning(old_name, new_name));
            take(value);
          },
          fmt::format("VALUE: the old spelling of {}", new_name))
      ->group("");
}

}  // namespace app
