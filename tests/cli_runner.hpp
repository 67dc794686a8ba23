#pragma once
// `maze_mapper ARGS...` run in the test's process through the real command line (CLI11 and
// every subcommand), its standard output captured.
// CLI11 stays in cli_runner.cpp (see app/cli/commands.hpp for why).
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

namespace test_cli {

struct Ran {
  int status = 0;
  std::string out;
};

// Throws what the command line throws (CLI::Error, common::InputError); std::cout is
// restored either way.
Ran run(std::vector<std::string> args);

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
