// libFuzzer target: the command line of `maze_mapper run`, built as app/cli/main.cpp builds it and
// parsed without running (CommandContext::run_parse_only). The input is the argument list,
// one argument a line. A bad command line must end in CLI::Error (CLI11's usage errors, help)
// or common::InputError; anything else escapes and libFuzzer reports it.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/commands.hpp"
#include "app/run/run.hpp"
#include "common/error.hpp"

namespace {

constexpr std::size_t kMaxArguments = 64;

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> words{"maze_mapper", "run"};
  while (!text.empty() && words.size() < kMaxArguments) {
    const std::size_t end = text.find('\n');
    words.emplace_back(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return words;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const std::vector<std::string> words =
      split_lines(std::string_view(reinterpret_cast<const char *>(data), size));
  // --robot FILE.json reads the file while parsing: device files (/dev/zero, a terminal)
  // would block or never end; they are not what this target tests.
  for (const std::string &word : words) {
    if (word.find("/dev") != std::string::npos || word.find("/proc") != std::string::npos) return 0;
  }
  std::vector<const char *> argv;
  for (const std::string &word : words) argv.push_back(word.c_str());

  app::RunOptions options;
  try {
    options = app::parse_run_options(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::Error &) {
    return 0;
  } catch (const common::InputError &e) {
    if (e.diagnostic().empty()) std::abort();
    return 0;
  }
  // parse_run_options() validates the options once (app::validate). Without --max-steps the limit is left to the
  // maze (max_steps_for); the first version of this check compared the empty optional and
  // aborted on every command line without it (tests/test_app_cmd_run.cpp).
  if (options.max_steps && *options.max_steps < 1) std::abort();
  return 0;
}
