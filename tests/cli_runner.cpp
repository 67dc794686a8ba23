#include "cli_runner.hpp"

#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "app/cli/commands.hpp"

namespace test_cli {

Ran run(std::vector<std::string> args) {
  const std::string first = args.empty() ? "run" : args.front();  // as main() builds the command line
  args.insert(args.begin(), "maze_mapper");
  app::CommandContext context;
  args = app::split_child_command(args, context);  // mms and batch: the algorithm after "--"
  std::vector<const char *> argv;
  for (const std::string &a : args) argv.push_back(a.c_str());
  CLI::App cli{"maze_mapper", "maze_mapper"};
  app::add_commands(cli, context, first);
  std::ostringstream out;
  std::streambuf *saved = std::cout.rdbuf(out.rdbuf());
  try {
    cli.parse(static_cast<int>(argv.size()), argv.data());
  } catch (...) {
    std::cout.rdbuf(saved);
    throw;
  }
  std::cout.rdbuf(saved);
  return {context.status, out.str()};
}

}  // namespace test_cli
