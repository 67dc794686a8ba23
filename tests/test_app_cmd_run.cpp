// `run`'s command line parsed without running (CommandContext::run_parse_only), as
// fuzz/fuzz_run_cli.cpp parses it. Regression (the CI fuzz run, issue 9): with no arguments
// at all the fuzz target aborted, its check comparing the unset --max-steps as if it were 0.

#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/run.hpp"
#include "common/error.hpp"

namespace {

// The options `maze_mapper run ARGS...` would run with.
app::RunOptions parse_run(std::vector<std::string> args) {
  args.insert(args.begin(), {"maze_mapper", "run"});
  std::vector<const char *> argv;
  for (const std::string &a : args) argv.push_back(a.c_str());
  return app::parse_run_options(static_cast<int>(argv.size()), argv.data());
}

}  // namespace

TEST_CASE("run command line: no arguments leave the step limit to the maze") {
  const app::RunOptions o = parse_run({});
  CHECK_FALSE(o.max_steps.has_value());
  CHECK(o.world.ends_with("lab4x4.txt"));
  CHECK(o.dropout == 0.0);
  CHECK(o.spikes == 0.0);
}

TEST_CASE("run command line: --max-steps and the fault options") {
  const app::RunOptions o = parse_run({"--max-steps", "1", "--dropout", "0.05", "--spikes", "0.01"});
  CHECK(o.max_steps == std::optional<std::int64_t>{1});
  CHECK(o.dropout == 0.05);
  CHECK(o.spikes == 0.01);
  try {
    parse_run({"--max-steps", "0"});
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == "error: --max-steps must be at least 1 (got 0)");
  }
}
