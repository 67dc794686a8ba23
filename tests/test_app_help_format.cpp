// --help as it reads (app/cli/help_format.hpp): every visible command's help, found by walking the
// command tree (so commands added later are checked too), fits 80 columns with COLUMNS=80,
// breaks no word, keeps no CLI11 leftovers, and its examples name options the command has.

#include <doctest/doctest.h>

#include <cctype>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/cli_reference.hpp"
#include "app/cli/commands.hpp"
#include "app/cli/help_format.hpp"

namespace {

struct HelpProgram {
  CLI::App cli{"maze_mapper: explore a grid maze with a simulated robot and map it into a 4D log-odds occupancy grid",
               "maze_mapper"};
  app::CommandContext context;
  HelpProgram() { app::add_commands(cli, context); }
};

std::size_t code_points(const std::string &line) {
  std::size_t n = 0;
  for (const char c : line) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1 : 0;
  return n;
}

std::vector<std::string> words_of(const std::string &text) {
  std::vector<std::string> words;
  std::istringstream in(text);
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

// The help `maze_mapper PATH --help` prints (CLI11's help() appends the command's own name).
std::string help_of(const app::CommandNode &node) {
  const std::size_t last = node.path.rfind(' ');
  return node.app->help(node.path.empty() ? "" : "maze_mapper" + (last == std::string::npos ? "" : " " + node.path.substr(0, last)));
}

// The command an example line runs: the program's, descended through the subcommands named.
const CLI::App *command_of(const CLI::App &root, const std::string &line) {
  const CLI::App *command = &root;
  std::istringstream words(line);
  std::string word;
  words >> word;  // maze_mapper
  while (words >> word) {
    const CLI::App *sub = nullptr;
    for (const CLI::App *candidate : command->get_subcommands([](const CLI::App *) { return true; })) {
      if (candidate->get_name() == word) sub = candidate;
    }
    if (sub == nullptr) break;
    command = sub;
  }
  return command;
}

// Sets COLUMNS for the test's life.
struct Columns {
  explicit Columns(const char *value) { ::setenv("COLUMNS", value, 1); }
  ~Columns() { ::unsetenv("COLUMNS"); }
  Columns(const Columns &) = delete;
  Columns &operator=(const Columns &) = delete;
};

}  // namespace

TEST_CASE("every command's help fits 80 columns, breaks no word and keeps no library leftovers") {
  const Columns columns("80");
  const HelpProgram program;
  for (const app::CommandNode &node : app::visible_commands(program.cli)) {
    const std::string help = help_of(node);
    INFO("maze_mapper ", node.path, " --help:\n", help);
    std::istringstream lines(help);
    for (std::string line; std::getline(lines, line);) {
      CHECK(code_points(line) <= 80);
      CHECK(!line.ends_with(" "));
    }
    for (const char *leftover : {"{false}", "{true}", "Excludes", "Needs:", "REQUIRED", "TEXT:", "SUBCOMMAND"}) {
      CHECK(help.find(leftover) == std::string::npos);
    }
    // Every word of every description is whole in the help: wrapping broke none.
    const std::vector<std::string> help_words = words_of(help);
    const std::set<std::string> present(help_words.begin(), help_words.end());
    for (const CLI::Option *option : node.app->get_options()) {
      if (option->get_group().empty()) continue;  // hidden: an old spelling
      for (const std::string &word : words_of(option->get_description())) {
        if (word.ends_with(":")) continue;  // the value name's colon is dropped ("X,Y: ...")
        INFO("word: ", word);
        CHECK(present.count(word) == 1);
      }
    }
    CHECK(help.starts_with("Usage: maze_mapper"));
  }
}

TEST_CASE("at 60 columns too (but the examples), and the usage line shows what is required") {
  const Columns columns("60");
  const HelpProgram program;
  for (const app::CommandNode &node : app::visible_commands(program.cli)) {
    // The examples are command lines, kept whole (they fit 80 columns, checked above).
    const std::string help = help_of(node);
    std::istringstream lines(help.substr(0, help.find("\nExamples:\n")));
    for (std::string line; std::getline(lines, line);) {
      // A single word longer than the width stands alone (demo 1d's default list).
      INFO("maze_mapper ", node.path, ": ", line);
      const std::size_t text_start = line.find_first_not_of(' ');
      const bool one_word = text_start != std::string::npos && line.find(' ', text_start) == std::string::npos;
      CHECK((code_points(line) <= 60 || one_word));
    }
  }
  const std::string scan = program.cli.get_subcommand("scan")->help("maze_mapper");
  const std::string usage = scan.substr(0, scan.find("\n\n"));
  CHECK(usage.find("maze_mapper scan WORLD --pose X,Y,YAW") != std::string::npos);
  const std::string show = program.cli.get_subcommand("show")->help("maze_mapper");
  CHECK(show.starts_with("Usage: maze_mapper show WORLD [OPTIONS]"));
  const std::string run = program.cli.get_subcommand("run")->help("maze_mapper");
  CHECK(run.starts_with("Usage: maze_mapper run [WORLD] [OPTIONS]"));
  // Wrapped at 60 columns: read as one line.
  std::string map_log = program.cli.get_subcommand("map-log")->help("maze_mapper");
  map_log.replace(map_log.find("\n    "), 5, " ");
  CHECK(map_log.starts_with("Usage: maze_mapper map-log LOG --boundary XS,XE,YS,YE [OPTIONS]"));
}

TEST_CASE("run's options are grouped: world, robot and model, exploration, faults, output") {
  const Columns columns("80");
  const HelpProgram program;
  const std::string help = program.cli.get_subcommand("run")->help("maze_mapper");
  std::size_t at = 0;
  for (const char *heading : {"\nWorld:\n", "\nRobot and model:\n", "\nExploration:\n", "\nFaults:\n", "\nOutput:\n",
                              "\nExamples:\n"}) {
    INFO(heading);
    const std::size_t found = help.find(heading, at);
    REQUIRE(found != std::string::npos);
    at = found;
  }
  CHECK(help.find("--robot NAME or FILE.json") != std::string::npos);
  CHECK(help.find("--wheel-slip", help.find("\nFaults:\n")) < help.find("\nOutput:\n"));
}

TEST_CASE("the examples are commands of the program with options their command has") {
  const Columns columns("80");
  const HelpProgram program;
  std::size_t commands_with_examples = 0;
  for (const app::CommandNode &node : app::visible_commands(program.cli)) {
    const std::string footer = node.app->get_footer();
    if (footer.empty()) continue;
    ++commands_with_examples;
    INFO("maze_mapper ", node.path);
    REQUIRE(footer.starts_with("Examples:\n"));
    std::istringstream lines(footer.substr(footer.find('\n') + 1));
    std::size_t examples = 0;
    for (std::string line; std::getline(lines, line);) {
      ++examples;
      const std::string command = node.path.empty() ? "  maze_mapper" : "  maze_mapper " + node.path;
      INFO(line);
      CHECK(line.starts_with(command));
      const std::string command_line = line.substr(0, line.find(" #"));
      const CLI::App *target = command_of(program.cli, command_line.substr(2));
      for (const std::string &word : words_of(command_line)) {
        // An option, not a value such as -2,2,-2,2.
        if (word.size() > 1 && word[0] == '-' && !std::isdigit(static_cast<unsigned char>(word[1]))) {
          INFO("option: ", word);
          CHECK(target->get_option_no_throw(word) != nullptr);
        }
      }
    }
    CHECK(examples >= 1);
    CHECK(examples <= 3);
  }
  CHECK(commands_with_examples >= 17);
}
