// maze_mapper batch WORLD... [--jobs N] [--csv FILE] [run options] (see app/batch.hpp).

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/batch.hpp"
#include "app/run_cli.hpp"
#include "app/terminal.hpp"
#include "commands.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace app {
namespace {

struct BatchInput {
  std::vector<std::string> worlds;
  int jobs = 0;
  std::string csv;
};

// "[#########           ] 9/20" on one line of stderr, redrawn in place.
void draw_progress(std::size_t done, std::size_t total) {
  constexpr std::size_t kWidth = 30;
  const std::size_t filled = total == 0 ? kWidth : done * kWidth / total;
  fmt::print(stderr, "\r[{}{}] {}/{}", std::string(filled, '#'), std::string(kWidth - filled, ' '),
             done, total);
  if (done == total) fmt::print(stderr, "\r\x1b[K");
  std::fflush(stderr);
}

}  // namespace

void add_batch_command(CLI::App &cli, CommandContext &context) {
  auto parsed = std::make_shared<RunOptions>();
  auto batch = std::make_shared<BatchInput>();
  CLI::App *command = cli.add_subcommand(
      "batch", "run many worlds (files, or folders of them) in parallel; print a table and totals");
  command->add_option("WORLD", batch->worlds, "maze files or folders")->required();
  command->add_option("--jobs", batch->jobs, "N: parallel runs (default all cores)");
  command->add_option("--csv", batch->csv, "FILE: also write the table as CSV");
  add_mapping_run_options(*command, *parsed);
  command->callback([command, parsed, batch, &context] {
    RunOptions options = checked_run_options(*command, *parsed, false);
    options.output.quiet = true;
    print_warnings(options_not_applying(*command, options));
    if (batch->jobs < 0) throw common::InputError(fmt::format("--jobs must be at least 1 (got {})", batch->jobs));
    const int jobs = batch->jobs > 0 ? batch->jobs
                                     : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const WorldList list = expand_worlds(batch->worlds);
    if (list.worlds.empty()) {
      throw common::InputError(fmt::format("no world to run: the folders hold no maze file ({} other file{} skipped)",
                                           list.skipped.size(), list.skipped.size() == 1 ? "" : "s"));
    }
    const auto started = std::chrono::steady_clock::now();
    std::function<void(std::size_t, std::size_t)> progress;
    if (is_terminal(STDERR_FILENO)) progress = draw_progress;
    const SigintGuard sigint;
    const std::vector<BatchItem> items = run_batch(options, list.worlds, jobs, progress, &SigintGuard::interrupted);
    if (progress) fmt::print(stderr, "\r\x1b[K");
    const double elapsed_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    for (const BatchItem &item : items) {
      if (!item.ran && !item.interrupted) fmt::print(stderr, "{}\n", item.error);
    }
    std::cout << format_batch_table(items, elapsed_ms, list.skipped);
    if (!batch->csv.empty()) common::write_file_atomically(batch->csv, format_batch_csv(items));
    context.status = batch_exit_status(items);
  });
}

}  // namespace app
