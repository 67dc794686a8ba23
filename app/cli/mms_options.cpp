#include "app/cli/mms_options.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "app/batch/mms_batch.hpp"
#include "app/run/progress_line.hpp"
#include "app/run/terminal.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "common/standard_streams.hpp"

namespace app {

void add_mms_options(CLI::App &command, MmsOptions &o) {
  command.add_option_function<std::string>(
      "--walls",
      [&o](const std::string &text) {
        if (text != "truth" && text != "sensed") {
          throw common::InputError(fmt::format("--walls must be truth or sensed (got '{}')", text));
        }
        o.walls = text == "truth" ? MmsWalls::truth : MmsWalls::sensed;
      },
      "truth|sensed: answer wallFront/Left/Right from the maze, as mms does, or from what the robot's sensors "
      "mapped (default sensed)");
  command.add_option_function<std::string>(
      "--until",
      [&o](const std::string &text) {
        const std::map<std::string, MmsUntil> words{{"exit", MmsUntil::exit}, {"goal", MmsUntil::goal}, {"start", MmsUntil::start}};
        const auto found = words.find(text);
        if (found == words.end()) throw common::InputError(fmt::format("--until must be exit, goal or start (got '{}')", text));
        o.until = found->second;
      },
      "exit|goal|start: end when the algorithm exits, when the robot first reaches the goal, or when it is back "
      "at the start after the goal (default exit)");
  command.add_option("--wall-limit", o.wall_limit_s,
                     fmt::format("S: wall-clock seconds the algorithm has, the whole run: the guard against a hung "
                                 "program; inf for no limit (default {:g}; --time-limit is simulated seconds)",
                                 o.wall_limit_s));
  command.add_option("--max-line", o.max_line_bytes,
                     fmt::format("BYTES: a longer line from the algorithm ends the run (default {})", o.max_line_bytes));
  command.add_flag("--ignore-invalid", o.ignore_invalid,
                   "skip a line that is no command with a warning, as mms does; without it such a line ends the "
                   "run, naming the line");
}

bool mms_options_given(const CLI::App &command) {
  for (const char *name : {"--walls", "--until", "--wall-limit", "--max-line", "--ignore-invalid"}) {
    const CLI::Option *option = command.get_option_no_throw(name);
    if (option != nullptr && option->count() > 0) return true;
  }
  return false;
}

void check_mms_command_line(const CLI::App &command) {
  const auto given = [&command](const char *name) {
    const CLI::Option *option = command.get_option_no_throw(name);
    return option != nullptr && option->count() > 0;
  };
  for (const char *name : {"--strategy", "--speed-run"}) {
    if (given(name)) {
      throw common::InputError(fmt::format("{} does not apply to an mms algorithm: it decides where the robot goes", name));
    }
  }
  if (given("--time-limit") && !given("--wall-limit")) {
    common::print_stderr("warning: --time-limit is simulated seconds; the guard against a hung program is --wall-limit "
                       "(wall-clock seconds, default {:g})\n",
                         MmsOptions{}.wall_limit_s);
  }
}

int run_mms_batch_command(const CLI::App &command, const RunOptions &options, MmsOptions mms,
                          const std::vector<std::string> &child_command, const WorldList &list, int jobs,
                          const std::string &csv) {
  if (child_command.empty()) {
    throw common::InputError("the mms options need the algorithm: batch WORLD... [options] -- COMMAND [ARGS...]");
  }
  check_mms_command_line(command);
  mms.command = child_command;
  validate(mms);
  std::optional<BatchProgressLine> progress_line;
  std::function<void(std::size_t, std::size_t)> progress;
  if (is_terminal(STDERR_FILENO)) {
    progress_line.emplace(STDERR_FILENO);
    progress = [&progress_line](std::size_t done, std::size_t total) { progress_line->update(done, total); };
  }
  const auto started = std::chrono::steady_clock::now();
  const common::SignalsStopWork stop_signals;  // the children are ended and reaped first
  const std::vector<MmsBatchItem> items =
      run_mms_batch(options, mms, list.worlds, jobs, progress, &common::interrupted);
  progress_line.reset();  // cleared before the table
  const double elapsed_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  for (const MmsBatchItem &item : items) {
    if (!item.ran && !item.interrupted) common::print_stderr("{}\n", item.error);
  }
  std::cout << format_mms_batch_table(items, elapsed_ms, list.skipped);
  if (!csv.empty()) common::write_file_atomically(csv, format_mms_batch_csv(items));
  return mms_batch_exit_status(items);
}

}  // namespace app
