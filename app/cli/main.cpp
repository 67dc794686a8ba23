// maze_mapper: map a maze cell by cell into a 4D log-odds occupancy grid (see README.md).
// This is the composition root: the only place that wires the world side to the controller.

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli/cli_errors.hpp"
#include "app/cli/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "common/standard_streams.hpp"

namespace {

constexpr int kExitUsage = 2;
constexpr int kExitFailure = 1;

// Standard output could not take the program's output (`error_number`: the failed write's
// errno): exit status 4 when the disk is full (as for a file), 1 otherwise.
int stdout_failed(int error_number) {
  if (error_number == ENOSPC || error_number == EDQUOT) {
    common::print_stderr("error: cannot write standard output: {}\n", std::strerror(error_number));
    return common::kExitNoSpace;
  }
  common::print_stderr("error: could not write to standard output\n");
  return kExitFailure;
}

// A stop signal recorded while the command still worked (after its last poll, while it
// printed or wrote its files) is its exit status too: 128 + the signal, said on one line
// unless the command's own status already says it.
int status_after_signal(int status) {
  if (!common::interrupted() || status == common::interrupted_exit_status()) return status;
  common::print_stderr("error: interrupted by {}\n", common::interrupt_name());
  return common::interrupted_exit_status();
}

}  // namespace

int main(int argc, char **argv) {
  common::secure_standard_streams();  // a closed stream is /dev/null, never a file opened later
  CLI::App cli{"maze_mapper: explore a grid maze with a simulated robot and map it into a "
               "4D log-odds occupancy grid",
               "maze_mapper"};
  app::CommandContext context;
  app::add_commands(cli, context, argc <= 1 ? std::string_view("run") : std::string_view(argv[1]));
  common::install_signal_handlers();
  const common::StandardStreamsThroughBuffers streams;  // a write a full pipe holds still ends on a signal

  std::vector<std::string> words;  // the command line as parsed, for a usage error
  try {
    if (argc <= 1) {
      // No arguments: the main job, mapping the default world.
      const std::vector<std::string> as_if{argc == 1 ? argv[0] : "maze_mapper", "run"};
      words.assign(as_if.begin() + 1, as_if.end());
      std::vector<const char *> as_if_argv;
      for (const std::string &word : as_if) as_if_argv.push_back(word.c_str());
      cli.parse(static_cast<int>(as_if_argv.size()), as_if_argv.data());
    } else {
      const std::vector<std::string> args = app::split_child_command(std::vector<std::string>(argv, argv + argc), context);
      words.assign(args.begin() + 1, args.end());
      if (const std::string one_dash = app::one_dash_long_option(cli, words); !one_dash.empty()) {
        common::print_stderr("error: {}\n", common::printable(one_dash));
        return kExitUsage;
      }
      std::vector<const char *> parsed;
      for (const std::string &word : args) parsed.push_back(word.c_str());
      cli.parse(static_cast<int>(parsed.size()), parsed.data());
    }
    std::cout.flush();
    if (!std::cout) return stdout_failed(errno);
    return status_after_signal(context.status);
  } catch (const CLI::CallForHelp &e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp &e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion &e) {
    return cli.exit(e);
  } catch (const CLI::ParseError &e) {
    common::print_stderr("error: {}\n", common::printable(app::describe_usage_error(cli, e, words)));
    return kExitUsage;
  } catch (const common::InputError &e) {
    std::cout.flush();
    common::print_stderr("{}\n", e.diagnostic());
    return kExitUsage;
  } catch (const common::Interrupted &e) {
    std::cout.flush();
    common::print_stderr("error: {}\n", common::printable(e.what()));
    return common::interrupted_exit_status();
  } catch (const common::NoSpaceError &e) {
    std::cout.flush();
    common::print_stderr("error: {}\n", common::printable(e.what()));
    return common::kExitNoSpace;
  } catch (const common::RuntimeFailure &e) {
    std::cout.flush();
    common::print_stderr("error: {}\n", common::printable(e.what()));
    return kExitFailure;
  } catch (const std::bad_alloc &) {
    common::print_stderr("error: out of memory\n");
    return kExitFailure;
  } catch (const std::exception &e) {
    common::print_stderr("error: internal failure: {}\n", common::printable(e.what()));
    return kExitFailure;
  }
}
