#pragma once
// `maze_mapper ARGS...` run in the test's process through the real command line (CLI11 and
// every subcommand), its standard output captured.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands.hpp"

namespace test_cli {

struct Ran {
  int status = 0;
  std::string out;
};

inline Ran run(std::vector<std::string> args) {
  args.insert(args.begin(), "maze_mapper");
  std::vector<const char *> argv;
  for (const std::string &a : args) argv.push_back(a.c_str());
  CLI::App cli{"maze_mapper", "maze_mapper"};
  app::CommandContext context;
  app::add_commands(cli, context);
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

// A fresh directory under the system's temporary directory, removed at the end.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string &name)
      : path(std::filesystem::temp_directory_path() / ("maze_mapper_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

}  // namespace test_cli
