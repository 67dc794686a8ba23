#include "common/parse_number.hpp"
#include "app/cli/help_format.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <map>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "app/cli/cli_reference.hpp"
#include "app/run/terminal.hpp"

namespace app {
namespace {

constexpr const char *kRequiredMark = "required";
constexpr std::size_t kNameColumn = 28;  // where an option's description starts

// Which group each option is listed in, by its first long name.
const std::map<std::string, std::string, std::less<>> &group_of_option() {
  static const std::map<std::string, std::string, std::less<>> groups = [] {
    std::map<std::string, std::string, std::less<>> table;
    for (const char *name : {"--cell-size", "--start", "--goal", "--boundary", "--cells", "--resolution"}) table[name] = kWorldGroup;
    for (const char *name : {"--robot", "--model", "--subcells", "--threshold", "--pie-beta", "--pie-alpha",
                             "--hit-depth", "--ignore-no-return", "--noise", "--seed", "--p-free", "--p-occ",
                             "--prior", "--log-base", "--clamp", "--sensor", "--bump-radius", "--depth-angles", "--depth-max",
                             "--depth-reading", "--depth-origin"}) {
      table[name] = kRobotGroup;
    }
    for (const char *name : {"--strategy", "--max-steps", "--time-limit", "--dilate", "--speed-run", "--plan-to", "--from", "--to",
                             "--step", "--waypoints", "--laps"}) {
      table[name] = kExplorationGroup;
    }
    for (const char *name : {"--dropout", "--spikes", "--stuck-bumper", "--wheel-slip"}) table[name] = kFaultsGroup;
    for (const char *name : {"--quiet", "--out", "--output", "--snapshots", "--no-trace", "--no-replay", "--no-color",
                             "--color", "--animate", "--fps", "--speed", "--wide", "--narrow", "--ascii",
                             "--unknown", "--csv", "--svg", "--png"}) {
      table[name] = kOutputGroup;
    }
    return table;
  }();
  return groups;
}

std::size_t columns(std::string_view text) {
  std::size_t n = 0;
  for (const char c : text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1 : 0;
  return n;
}

// `text` wrapped to `width`, lines after the first indented by `indent`; the first line starts
// at column `first_column` (its indent written when `indent_first`, else already on the line).
std::string wrap_paragraph(std::string_view text, std::size_t width, std::size_t indent, bool indent_first,
                           std::size_t first_column) {
  std::string out = indent_first ? std::string(indent, ' ') : std::string();
  std::size_t used = indent_first ? indent : first_column;
  bool line_empty = true;
  std::istringstream words{std::string(text)};
  for (std::string word; words >> word;) {
    if (!line_empty && used + 1 + columns(word) > width) {
      out += "\n" + std::string(indent, ' ');
      used = indent;
      line_empty = true;
    }
    if (!line_empty) {
      out += ' ';
      ++used;
    }
    out += word;
    used += columns(word);
    line_empty = false;
  }
  return out;
}

std::string option_names_text(const CLI::Option &option) {
  std::vector<std::string> names;
  for (const std::string &s : option.get_snames()) names.push_back("-" + s);
  for (const std::string &l : option.get_lnames()) names.push_back("--" + l);
  std::string text;
  for (const std::string &name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

bool shown_as_required(const CLI::Option &option) {
  return option.get_required() || option.get_option_text() == kRequiredMark;
}

class ReadableFormatter : public CLI::Formatter {
 public:
  std::string make_help(const CLI::App *app, std::string name, CLI::AppFormatMode mode) const override {
    if (mode == CLI::AppFormatMode::Sub) return make_expanded(app);
    return make_usage(app, std::move(name)) + make_description(app) + make_positionals(app) + make_option_groups(app) +
           make_subcommands(app, mode) + make_footer(app);
  }

  std::string make_positionals(const CLI::App *app) const override {
    const std::vector<const CLI::Option *> positionals =
        app->get_options([](const CLI::Option *candidate) { return candidate->get_positional() && !candidate->get_group().empty(); });
    return positionals.empty() ? std::string() : make_group("Arguments", true, positionals);
  }

  std::string make_usage(const CLI::App *app, std::string name) const override {
    std::string usage = "Usage: " + name;
    for (const CLI::Option *p : app->get_options([](const CLI::Option *candidate) { return candidate->get_positional(); })) {
      const std::string word = p->get_name() + (p->get_items_expected_max() > 1 ? "..." : "");
      usage += shown_as_required(*p) ? " " + word : " [" + word + "]";
    }
    for (const CLI::Option *o : app->get_options([](const CLI::Option *candidate) { return candidate->nonpositional(); })) {
      if (shown_as_required(*o)) usage += " " + o->get_name() + " " + value_name(*o);
    }
    if (!app->get_subcommands([](const CLI::App *s) { return !s->get_group().empty(); }).empty()) {
      usage += app->get_require_subcommand_min() > 0 ? " COMMAND" : " [COMMAND]";
    }
    if (!app->get_options([](const CLI::Option *candidate) { return candidate->nonpositional(); }).empty()) usage += " [OPTIONS]";
    return wrap_paragraph(usage, help_width(), 4, false, 0) + "\n\n";
  }

  std::string make_description(const CLI::App *app) const override {
    const std::string description = app->get_description();
    if (description.empty()) return "";
    return wrap_paragraph(description, help_width(), 0, false, 0) + "\n";
  }

  std::string make_footer(const CLI::App *app) const override {
    const std::string footer = app->get_footer();
    return footer.empty() ? std::string() : "\n" + footer + (footer.ends_with('\n') ? "" : "\n");
  }

  std::string make_subcommand(const CLI::App *sub) const override {
    return option_line("  " + sub->get_name(), sub->get_description());
  }

  std::string make_subcommands(const CLI::App *app, CLI::AppFormatMode mode) const override {
    std::string out;
    for (const CLI::App *sub : app->get_subcommands([](const CLI::App *s) { return !s->get_group().empty(); })) {
      out += mode == CLI::AppFormatMode::All ? make_expanded(sub) : make_subcommand(sub);
    }
    return out.empty() ? out : "\nCommands:\n" + out;
  }

  std::string make_group(std::string group, bool is_positional, std::vector<const CLI::Option *> opts) const override {
    std::string out = "\n" + group + ":\n";
    for (const CLI::Option *o : opts) out += make_option(o, is_positional);
    return out;
  }

  std::string make_option(const CLI::Option *opt, bool is_positional) const override {
    return option_line(make_option_name(opt, is_positional) + make_option_opts(opt), make_option_desc(opt));
  }

  std::string make_option_name(const CLI::Option *opt, bool is_positional) const override {
    return "  " + (is_positional ? opt->get_name() : option_names_text(*opt));
  }

  std::string make_option_opts(const CLI::Option *opt) const override {
    if (opt->get_positional()) return "";
    const std::string value = value_name(*opt);
    return value.empty() ? "" : " " + value;
  }

  std::string make_option_desc(const CLI::Option *opt) const override {
    if (opt->get_positional()) return opt->get_description();  // its value's name is not shown
    const std::string value = value_name(*opt);
    std::string text = opt->get_description();
    if (!value.empty() && text.starts_with(value + ": ")) text = text.substr(value.size() + 2);
    return text;
  }

 private:
  // "  --name VALUE" then its description from kNameColumn, on the same line when the name
  // leaves room, else on the next.
  static std::string option_line(const std::string &name, const std::string &description) {
    const std::size_t width = help_width();
    std::string out = name;
    if (columns(name) + 2 <= kNameColumn) {
      out += std::string(kNameColumn - columns(name), ' ');
      out += wrap_paragraph(description, width, kNameColumn, false, kNameColumn);
    } else {
      out += "\n" + wrap_paragraph(description, width, kNameColumn, true, kNameColumn);
    }
    return out + "\n";
  }

  std::string make_option_groups(const CLI::App *app) const {
    std::vector<std::string> order{"Options"};
    for (const char *group : {kWorldGroup, kRobotGroup, kExplorationGroup, kFaultsGroup, kOutputGroup}) {
      order.emplace_back(group);
    }
    for (const std::string &group : app->get_groups()) {
      if (!group.empty() && std::find(order.begin(), order.end(), group) == order.end()) order.push_back(group);
    }
    std::string out;
    for (const std::string &group : order) {
      std::vector<const CLI::Option *> options = app->get_options([&group](const CLI::Option *candidate) {
        return candidate->nonpositional() && candidate->get_group() == group;
      });
      if (!options.empty()) out += make_group(group, false, options);
    }
    return out;
  }
};

// Each command's examples, the end of its --help: real command lines, each with what it does.
// A maze of one's own comes from `generate`; a command line without WORLD maps the default.
const std::map<std::string, std::string, std::less<>> &examples() {
  static const std::map<std::string, std::string, std::less<>> table{
      {"", "  maze_mapper                          # map the default world, lab4x4.txt\n"
           "  maze_mapper run --help               # a command's options\n"
           "  maze_mapper generate 8x8 -o maze.txt # a maze of one's own"},
      {"run", "  maze_mapper run --quiet                 # the default world, map and summary\n"
              "  maze_mapper run maze.txt --model ray --subcells 5 --out results\n"
              "  maze_mapper run maze.txt --strategy floodfill --speed-run --goal 3,3"},
      {"compare", "  maze_mapper compare --subcells 3,5,7\n"
                  "  maze_mapper compare maze.txt --subcells 3,5 --model ray --quiet"},
      {"plan", "  maze_mapper plan                        # the default world, start to goal\n"
               "  maze_mapper plan maze.txt --from 0,0 --to 3,3 --dilate 1"},
      {"batch", "  maze_mapper batch mazes/ --jobs 2 --csv results.csv\n"
                "  maze_mapper batch mazes/ --shard 1/4 --csv part1.csv\n"
                "  maze_mapper batch arenas/ --kind room --model pie --csv rooms.csv"},
      {"batch merge", "  maze_mapper batch merge part1.csv part2.csv -o all.csv"},
      {"demo", "  maze_mapper demo 1d\n"
               "  maze_mapper demo pie --pose 1.5,2.5,270"},
      {"demo 1d", "  maze_mapper demo 1d\n"
                  "  maze_mapper demo 1d --order shuffle --svg plot.svg"},
      {"demo pie", "  maze_mapper demo pie\n"
                   "  maze_mapper demo pie --pose 1.5,2.5,270 --png pie.png"},
      {"demo cone", "  maze_mapper demo cone\n"
                    "  maze_mapper demo cone --sensor sonar --pose 0,0,90"},
      {"demo trilaterate", "  maze_mapper demo trilaterate --distances 3.2,4.1,2.9\n"
                           "  maze_mapper demo trilaterate --pose 0.7,-1.3 --noise 0.1 --seed 4"},
      {"demo localize", "  maze_mapper demo localize\n"
                        "  maze_mapper demo localize --start 13 --explain\n"
                        "  maze_mapper demo localize --particles --seed 7"},
      {"explain", "  maze_mapper explain\n"
                  "  maze_mapper explain --p-free 0.2 --p-occ 0.7 --log-base 10"},
      {"map-log", "  maze_mapper map-log log.csv --boundary -2,2,-2,2\n"
                  "  maze_mapper map-log results/trace.csv --boundary 0,4,0,4 --cells 40,40"},
      {"worlds", "  maze_mapper worlds     # then, from any folder: maze_mapper run maze8x8"},
      {"show", "  maze_mapper show maze.txt\n"
               "  maze_mapper show course.xml"},
      {"convert", "  maze_mapper convert maze.txt maze.num\n"
                  "  maze_mapper convert maze.txt maze.wbt      # a Webots world"},
      {"generate", "  maze_mapper generate 8x8 --seed 3 -o maze.txt\n"
                   "  maze_mapper generate 16x16 --loops 0.1 --algorithm kruskal\n"
                   "  maze_mapper generate arena 3x3 --obstacles 4 --sides 0.2,0.8 -o arena.room"},
      {"generate arena", "  maze_mapper generate arena 3x3 --obstacles 4 --sides 0.2,0.8 -o arena.room\n"
                         "  maze_mapper generate arena 10x10 --rotated --seed 7 -o course.xml"},
      {"scan", "  maze_mapper scan maze.txt --pose 0.5,0.5,90\n"
               "  maze_mapper scan maze.txt --pose 1.5,0.5,0 --noise 0"},
      {"robot", "  maze_mapper robot                        # the profiles\n"
                "  maze_mapper robot hambot > my.json       # one to edit, for --robot my.json"},
  };
  return table;
}

void add_examples(CLI::App &command, const std::string &path) {
  const auto found = examples().find(path);
  if (found != examples().end() && command.get_footer().empty()) command.footer("Examples:\n" + found->second);
  for (CLI::App *sub : command.get_subcommands([](CLI::App *) { return true; })) {
    if (!sub->get_group().empty()) add_examples(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name());
  }
}

void assign_groups(CLI::App &command, const std::shared_ptr<ReadableFormatter> &formatter) {
  command.formatter(formatter);
  for (CLI::Option *option : command.get_options()) {
    if (!option->nonpositional() || option->get_group().empty()) continue;
    const std::vector<std::string> &names = option->get_lnames();
    if (names.empty()) continue;
    const auto found = group_of_option().find("--" + names.front());
    if (found != group_of_option().end()) option->group(found->second);
  }
  for (CLI::App *sub : command.get_subcommands([](CLI::App *) { return true; })) assign_groups(*sub, formatter);
}

}  // namespace

std::size_t help_width() {
  if (const char *text = std::getenv("COLUMNS")) {
    const std::optional<int> n = common::parse_number<int>(text);
    if (n && *n >= 40 && *n <= 500) return static_cast<std::size_t>(*n);
  }
  if (is_terminal(STDOUT_FILENO)) return static_cast<std::size_t>(std::clamp(terminal_size(STDOUT_FILENO).columns, 40, 500));
  return 80;
}

std::string wrap_words(std::string_view text, std::size_t width, std::size_t indent, bool indent_first) {
  std::string out;
  std::size_t start = 0;
  bool first = true;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (!first) out += '\n';
    out += wrap_paragraph(text.substr(start, end - start), width, indent, indent_first || !first, 0);
    first = false;
    start = end + 1;
  }
  return out;
}

void show_as_required(CLI::Option &option) { option.option_text(kRequiredMark); }

void use_readable_help(CLI::App &root) {
  assign_groups(root, std::make_shared<ReadableFormatter>());
  add_examples(root, "");
}

}  // namespace app
