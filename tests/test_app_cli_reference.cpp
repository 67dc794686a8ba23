// The man page and the shell completions (app/cli/cli_reference.hpp): generated from the command
// tree, so every visible command and every option of each must be in each of them, in the
// form each reads; these walk the tree, so a command or option added later is covered too.

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string_view>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/cli/cli_reference.hpp"
#include "app/cli/completion_values.hpp"
#include "app/cli/commands.hpp"
#include "cli_runner.hpp"
#include "common/error.hpp"

namespace {

struct ReferenceProgram {
  CLI::App cli{"maze_mapper: explore a grid maze with a simulated robot", "maze_mapper"};
  app::CommandContext context;
  ReferenceProgram() { app::add_commands(cli, context); }
};

std::string roff_name(std::string name) {
  std::string out;
  for (const char c : name) out += c == '-' ? std::string("\\-") : std::string(1, c);
  return out;
}

// The man page's section of one command: from its ".SS" heading to the next heading.
std::string man_section(const std::string &page, const std::string &path) {
  const std::string heading = ".SS \"" + roff_name(path) + "\"\n";
  const std::size_t start = page.find(heading);
  if (start == std::string::npos) return "";
  std::size_t end = page.find("\n.S", start + heading.size());
  return page.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The line of a completion script's case branch for one command ("/run", "" for the program).
std::string case_line(const std::string &script, const std::string &path) {
  std::string slashed = path.empty() ? "" : "/" + path;
  for (char &c : slashed) c = c == ' ' ? '/' : c;
  std::istringstream lines(script);
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("    \"" + slashed + "\")")) return line;
  }
  return "";
}

}  // namespace

TEST_CASE("the man page has a section for every command, with every option of each") {
  const ReferenceProgram program;
  const std::string page = app::man_page(program.cli, "0.0.0");
  const std::vector<app::CommandNode> nodes = app::visible_commands(program.cli);
  CHECK(nodes.size() > 10);
  for (const app::CommandNode &node : nodes) {
    const std::string section = node.path.empty() ? page.substr(page.find(".SH OPTIONS")) : man_section(page, node.path);
    INFO("command: ", node.path);
    REQUIRE(!section.empty());
    for (const CLI::Option *option : node.app->get_options()) {
      if (option->get_group().empty()) continue;  // hidden: an old spelling
      if (!option->nonpositional()) {
        CHECK(section.find("\\fI" + roff_name(option->get_name()) + "\\fR") != std::string::npos);
        continue;
      }
      for (const std::string &name : app::option_names(*option)) {
        INFO("option: ", name);
        CHECK(section.find("\\fB" + roff_name(name) + "\\fR") != std::string::npos);
      }
    }
  }
  // The hidden command that prints it stays out of it; no line starts a roff request by accident.
  CHECK(page.find(app::kReferenceCommand) == std::string::npos);
  CHECK(page.find("\n.\n") == std::string::npos);
}

TEST_CASE("the bash and zsh completions offer every command and option, and say which take a value") {
  const ReferenceProgram program;
  const std::string bash = app::bash_completion(program.cli);
  const std::string zsh = app::zsh_completion(program.cli);
  for (const app::CommandNode &node : app::visible_commands(program.cli)) {
    INFO("command: ", node.path);
    const std::string bash_line = case_line(bash, node.path);
    const std::string zsh_line = case_line(zsh, node.path);
    REQUIRE(!bash_line.empty());
    REQUIRE(!zsh_line.empty());
    const std::string bash_options = bash_line.substr(0, bash_line.find("taking_value="));
    const std::string bash_taking = bash_line.substr(bash_line.find("taking_value="));
    for (const CLI::Option *option : node.app->get_options()) {
      if (option->get_group().empty()) continue;  // hidden: an old spelling
      if (!option->nonpositional()) continue;
      for (const std::string &name : app::option_names(*option)) {
        INFO("option: ", name);
        CHECK(bash_options.find(" " + name + " ") != std::string::npos);
        CHECK(zsh_line.find("'" + name + ":") != std::string::npos);
        CHECK((bash_taking.find(" " + name + " ") != std::string::npos) == app::takes_value(*option));
      }
    }
    for (const CLI::App *sub : node.app->get_subcommands([](const CLI::App *) { return true; })) {
      if (sub->get_group().empty()) {
        CHECK(bash_line.find(app::kReferenceCommand) == std::string::npos);
        continue;
      }
      CHECK(bash_line.find(sub->get_name()) != std::string::npos);
      CHECK(zsh_line.find("'" + sub->get_name() + ":") != std::string::npos);
    }
  }
}

TEST_CASE("the completions offer the words of --strategy, --model, --robot and --color, and the shipped worlds") {
  const ReferenceProgram program;
  const std::string bash = app::bash_completion(program.cli);
  const std::string zsh = app::zsh_completion(program.cli);
  const std::string fish = app::fish_completion(program.cli);
  for (const std::string_view flag : app::kWordValuedFlags) {
    INFO("option: ", flag);
    const std::vector<std::string> words = app::option_value_words(flag);
    REQUIRE(words.size() >= 3);
    const std::string joined = fmt::format("{}", fmt::join(words, " "));
    CHECK(bash.find(fmt::format("{}) COMPREPLY=($(compgen -W \"{}\" -- \"$cur\")) ;;", flag, joined)) != std::string::npos);
    CHECK(zsh.find(fmt::format("{}) compadd -- {} ;;", flag, joined)) != std::string::npos);
    CHECK(fish.find(fmt::format("-l {} -x -a '{}'", flag.substr(2), joined)) != std::string::npos);
  }
  CHECK(app::option_value_words("--color") == std::vector<std::string>{"auto", "always", "never"});
  const std::vector<std::string> strategies = app::option_value_words("--strategy");
  for (const char *name : {"dfs", "floodfill", "left-wall"}) {
    CHECK(std::find(strategies.begin(), strategies.end(), name) != strategies.end());
  }
  CHECK(app::option_value_words("--out").empty());
  const std::vector<std::string> worlds = app::shipped_world_names();
  REQUIRE(std::find(worlds.begin(), worlds.end(), "maze8x8") != worlds.end());
  CHECK(std::count(worlds.begin(), worlds.end(), "lab4x4") == 1);  // .txt, .num and .xml: one name
  const std::string shipped = fmt::format("{}", fmt::join(worlds, " "));
  CHECK(bash.find("shipped=\"" + shipped + "\"") != std::string::npos);
  CHECK(case_line(bash, "run").find("worlds=\"$shipped\"") != std::string::npos);
  CHECK(zsh.find("compadd -X 'shipped worlds' -- " + shipped) != std::string::npos);
  CHECK(fish.find("-a '" + shipped + "' -d 'shipped world'") != std::string::npos);
}

TEST_CASE("the fish completion has a line for every option of every command") {
  const ReferenceProgram program;
  const std::string fish = app::fish_completion(program.cli);
  for (const app::CommandNode &node : app::visible_commands(program.cli)) {
    INFO("command: ", node.path);
    // The condition names the command's last word ("demo cone": ... from cone).
    const std::string condition =
        node.path.empty() ? std::string("'__fish_use_subcommand'")
                          : "__fish_seen_subcommand_from " + node.path.substr(node.path.rfind(' ') + 1);
    for (const CLI::Option *option : node.app->get_options()) {
      if (option->get_group().empty()) continue;  // hidden: an old spelling
      if (!option->nonpositional()) continue;
      std::string flags;
      for (const std::string &l : option->get_lnames()) flags += " -l " + l;
      for (const std::string &s : option->get_snames()) flags += " -s " + s;
      INFO("option: ", flags);
      bool found = false;
      std::istringstream lines(fish);
      for (std::string line; std::getline(lines, line);) {
        found = found || (line.find(condition) != std::string::npos && line.find(flags + " ") != std::string::npos);
      }
      CHECK(found);
    }
  }
}

TEST_CASE("an option's value is named by its description's capitals, else by its type") {
  CLI::App command;
  std::string text;
  int number = 0;
  bool flag = false;
  const CLI::Option *robot = command.add_option("--robot", text, "NAME or FILE.json: robot profile");
  const CLI::Option *cell = command.add_option("--to", text, "X,Y: goal cell");
  const CLI::Option *plain = command.add_option("--count", number, "how many: at most 3");
  const CLI::Option *switch_ = command.add_flag("--quiet", flag, "say less");
  CHECK(app::value_name(*robot) == "NAME or FILE.json");
  CHECK(app::value_name(*cell) == "X,Y");
  CHECK(app::value_name(*plain) == "N");
  CHECK(app::value_name(*switch_).empty());
}

namespace {

// What a command needs besides the option under test to get as far as checking its options.
std::vector<std::string> needs(const std::string &path, const std::string &scratch) {
  const std::string lab = std::string(WORLDS_DIR) + "/lab4x4.txt";
  const std::string room = std::string(WORLDS_DIR) + "/ir_room.room";
  if (path == "run" || path == "compare" || path == "plan" || path == "batch" || path == "mms") return {lab};
  if (path == "room" || path == "show") return {room};
  if (path == "scan") return {lab, "--pose", "0.5,0.5,0"};
  if (path == "convert") return {lab, scratch + "/out.num"};
  if (path == "generate") return {"4x4"};
  if (path == "generate arena") return {"3x3"};
  if (path == "map-log") return {std::string(TEST_DATA_DIR) + "/logs/room_bump.csv", "--boundary", "0,6,0,6"};
  return {};
}

}  // namespace

TEST_CASE("cli: every number option of every command refuses nan and inf in a line naming the option") {
  const ReferenceProgram program;
  const test_cli::TempDir scratch("number_options");
  std::filesystem::create_directories(scratch.path);
  int checked = 0;
  for (const app::CommandNode &node : app::visible_commands(program.cli)) {
    for (const CLI::Option *option : node.app->get_options()) {
      if (option->get_type_name() != "FLOAT" || option->get_items_expected_max() != 1 || !option->nonpositional()) continue;
      for (const char *value : {"nan", "inf", "-inf"}) {
        std::vector<std::string> args;
        std::istringstream words(node.path);
        for (std::string word; words >> word;) args.push_back(word);
        for (const std::string &a : needs(node.path, scratch.path.string())) args.push_back(a);
        args.insert(args.end(), {option->get_name(), value});
        if (node.path == "mms" || node.path == "batch") args.insert(args.end(), {"--", "true"});
        INFO(node.path, " ", option->get_name(), " ", std::string(value));
        std::string message;
        try {
          test_cli::run(args);
        } catch (const common::InputError &e) {
          message = e.diagnostic();
        }
        // --time-limit and --wall-limit inf are no limit (as coreutils' timeout takes it); a run follows.
        const bool limit = option->get_name() == "--time-limit" || option->get_name() == "--wall-limit";
        if (limit && std::string_view(value) == "inf") continue;
        CHECK(message.find(option->get_name()) != std::string::npos);
        ++checked;
      }
    }
  }
  CHECK(checked > 30);
}

TEST_CASE("the man page's EXIT STATUS names every status the program ends with") {
  ReferenceProgram program;
  const std::string page = app::man_page(program.cli, "0.0.0");
  const std::size_t start = page.find(".SH EXIT STATUS\n");
  REQUIRE(start != std::string::npos);
  const std::string section = page.substr(start, page.find("\n.SH", start + 1) - start);
  for (const char *status : {"0", "1", "2", "4", "129", "130", "143"}) {
    CAPTURE(status);
    CHECK(section.find(std::string(".TP\n\\fB") + status + "\\fR\n") != std::string::npos);
  }
}
