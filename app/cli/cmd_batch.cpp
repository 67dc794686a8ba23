// maze_mapper batch WORLD... [--jobs N] [--csv FILE] [run options] (see app/batch/batch.hpp).

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <string_view>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/batch/batch.hpp"
#include "app/cli/cli_options.hpp"
#include "app/cli/floor_options.hpp"
#include "app/cli/mms_options.hpp"
#include "app/cli/option_binding.hpp"
#include "app/cli/run_cli.hpp"
#include "app/run/progress_line.hpp"
#include "app/run/terminal.hpp"
#include "app/cli/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/interrupt.hpp"
#include "common/error.hpp"
#include "common/standard_streams.hpp"

namespace app {
namespace {

struct BatchInput {
  std::vector<std::string> worlds;
  int jobs = 0;
  std::string csv;
  std::string shard;                  // --shard K/N
  bool each_start = false;            // --each-start
  std::string kind = "auto";          // --kind auto|maze|room
  std::vector<std::string> merge_csvs;  // batch merge A.csv B.csv ...
  std::string merge_out;                // batch merge -o FILE
  std::string strategy;                 // --strategy: a maze run's, a room run's, or frontier for both
  RunOptions room = metres_run_options();  // the room runs' strategy and options in metres
};

// Whether a kind of run has the strategy `name` (the one strategy table's rows say where each
// explores); frontier is one of each.
bool names_strategy(const std::string &name, explore::StrategySpace space) {
  for (const explore::StrategyRow &row : explore::strategy_table()) {
    if (row.name == name) return explore::explores_in(row.kind, space);
  }
  return false;
}
bool maze_strategy(const std::string &name) { return names_strategy(name, explore::StrategySpace::cells); }
bool room_strategy(const std::string &name) { return names_strategy(name, explore::StrategySpace::metres); }

// --strategy NAME into the runs it names: a maze run's strategy, a room run's, or frontier, both.
void read_strategy(const std::string &name, RunOptions &maze, RunOptions &room) {
  if (!maze_strategy(name) && !room_strategy(name)) {
    throw common::InputError(fmt::format("unknown --strategy '{}' (a maze run's dfs, frontier, left-wall, right-wall or "
                                         "floodfill; a room run's waypoints, wavefront, frontier or wander)",
                                         name));
  }
  if (maze_strategy(name)) maze.strategy = explore::parse_strategy(name);
  if (room_strategy(name)) room.strategy = explore::parse_strategy(name, explore::StrategySpace::metres);
}

// The options of the room command a batch takes for its room runs, from room's one table.
void add_room_run_options(CLI::App &command, BatchInput &batch) {
  command.add_option("--strategy", batch.strategy,
                     "NAME: a maze run's dfs, frontier, left-wall, right-wall or floodfill (default dfs); a room run's "
                     "waypoints, wavefront, frontier or wander (default frontier); frontier is both");
  add_field_options(command, batch.room.metres, {"--waypoints", "--laps", "--cells"});
  add_resolution_option(command, batch.room.metres.resolution_m, "0.1");
  add_field_options(command, batch.room.metres, {"--depth-reading", "--depth-origin"});
}

// batch merge: the parts' rows joined into one CSV (-o FILE, else stdout), and the totals
// recomputed from them (stdout with -o, else stderr).
void add_merge_command(CLI::App &batch_command, const std::shared_ptr<BatchInput> &batch) {
  CLI::App *merge = batch_command.add_subcommand(
      "merge", "join the CSVs of batch --shard parts (in the order given) and recompute the totals");
  merge->add_option("CSV", batch->merge_csvs, "the parts' --csv files, part 1 first")->required();
  merge->add_option("-o,--out", batch->merge_out, "FILE: write the joined CSV here (default stdout)");
  merge->callback([batch] {
    if (!batch->merge_out.empty()) common::refuse_output_over_input("-o", batch->merge_out, batch->merge_csvs);
    const std::vector<BatchRow> rows = read_batch_csvs(batch->merge_csvs);
    std::string csv = batch_csv_header() + '\n';
    BatchTotals totals;
    for (const BatchRow &row : rows) {
      csv += format_batch_csv_row(row);
      add_to_totals(totals, row);
    }
    const std::string line = format_totals(totals) + "\n";
    if (batch->merge_out.empty()) {
      std::cout << csv;
      std::cerr << line;
    } else {
      common::write_file_atomically(batch->merge_out, csv);
      std::cout << line;
    }
  });
}

bool holds_kind(const std::vector<BatchJob> &jobs, RunKind kind) {
  return std::any_of(jobs.begin(), jobs.end(), [kind](const BatchJob &job) { return job.kind == kind; });
}

// A batch that holds room runs: the maze runs' own options given to it say they apply to those
// only, once each.
void warn_maze_only_options(const BatchInput &batch, const RunOptions &options, const GivenOptions &given) {
  for (const char *name : {"--speed-run", "--start", "--goal", "--subcells"}) {
    if (given.given(name)) {
      common::print_stderr("warning: {} applies to the maze runs only: a room run starts from its world's start\n", name);
    }
  }
  if (!batch.strategy.empty() && !room_strategy(batch.strategy)) {
    common::print_stderr("warning: --strategy {} applies to the maze runs only: the room runs explore with {}\n",
                         batch.strategy, explore::to_string(batch.room.strategy));
  }
  if (given.given("--model") && options.model.kind == sensing::ModelKind::cell) {
    common::print_stderr("warning: --model cell reads a maze's cell sides: the room runs mark with --model ray\n");
  }
}

// The room runs' own options given to a batch that holds maze runs (a room strategy) or no
// room run (the rest) say so, once each.
void warn_room_only_options(const BatchInput &batch, const RunOptions &options, const GivenOptions &given,
                            const std::vector<BatchJob> &jobs) {
  if (holds_kind(jobs, RunKind::maze) && !batch.strategy.empty() && !maze_strategy(batch.strategy)) {
    common::print_stderr("warning: --strategy {} applies to the room runs only: the maze runs explore with {}\n",
                         batch.strategy, explore::to_string(options.strategy));
  }
  if (holds_kind(jobs, RunKind::room)) return;
  for (const char *name : {"--waypoints", "--laps", "--cells", "--resolution", "--depth-reading", "--depth-origin"}) {
    if (given.given(name)) common::print_stderr("warning: {} applies to the room runs only: this batch holds none\n", name);
  }
}

// The worlds a batch runs (folders expanded, its shard taken), checked: --csv is none of
// them, and an empty list is an error (an empty shard a warning).
WorldList batch_world_list(const BatchInput &batch, KindChoice choice) {
  WorldList list = expand_worlds(batch.worlds, choice);
  if (!batch.csv.empty()) common::refuse_output_over_input("--csv", batch.csv, list.worlds);
  if (!batch.shard.empty()) list.worlds = shard_of(list.worlds, parse_shard(batch.shard));
  if (list.worlds.empty() && !batch.shard.empty()) {
    common::print_stderr("warning: --shard {}: this part holds no world (more parts than worlds)\n", batch.shard);
  } else if (list.worlds.empty()) {
    throw common::InputError(fmt::format("no world to run: the folders hold no {} file ({} other file{} skipped)",
                                         choice == KindChoice::maze ? "maze" : "world", list.skipped.size(),
                                         list.skipped.size() == 1 ? "" : "s"));
  }
  return list;
}

// A batch of maze and room runs: its progress line, the runs, the table, the CSV; the exit status.
int run_world_batch(const CLI::App &command, const RunOptions &options, const BatchInput &batch,
                    const WorldList &list, KindChoice choice, int jobs) {
  const auto started = std::chrono::steady_clock::now();
  std::optional<BatchProgressLine> progress_line;
  std::function<void(std::size_t, std::size_t)> progress;
  if (is_terminal(STDERR_FILENO)) {
    progress_line.emplace(STDERR_FILENO);
    progress = [&progress_line](std::size_t done, std::size_t total) { progress_line->update(done, total); };
  }
  const common::SignalsStopWork stop_signals;  // until the CSV holds the finished runs
  const std::vector<BatchJob> batch_jobs = batch.each_start
                                               ? each_start_jobs(list.worlds, options.world_overrides, choice)
                                               : plain_jobs(list.worlds, choice);
  const GivenOptions given{command.get_name(), [&command](std::string_view name) {
                             const CLI::Option *option = command.get_option_no_throw(std::string(name));
                             return option != nullptr && option->count() > 0;
                           }};
  if (holds_kind(batch_jobs, RunKind::room)) warn_maze_only_options(batch, options, given);
  warn_room_only_options(batch, options, given, batch_jobs);
  const BatchOptions batch_options(options, room_options_for(options, batch.room, given.given));
  if (holds_kind(batch_jobs, RunKind::room)) {
    // --goal and --dilate are the maze runs' here (warned about above), not the room's.
    const GivenOptions room_given{given.command, [&given](std::string_view name) {
                                    return name != "--goal" && name != "--dilate" && given.given(name);
                                  }};
    print_warnings(check_metres_options_apply(room_given, batch_options.room));
  }
  const std::vector<BatchItem> items = run_batch(batch_options, batch_jobs, jobs, progress, &common::interrupted);
  progress_line.reset();  // cleared before the table
  const double elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  for (const BatchItem &item : items) {
    if (!item.ran && !item.interrupted) common::print_stderr("{}\n", item.error);
  }
  std::cout << format_batch_table(items, elapsed_ms, list.skipped, list.skipped_as) << std::flush;
  if (!batch.csv.empty()) common::write_file_atomically(batch.csv, format_batch_csv(items));
  return batch_exit_status(items);
}

}  // namespace

void add_batch_command(CLI::App &cli, CommandContext &context) {
  auto parsed = std::make_shared<RunOptions>();
  auto batch = std::make_shared<BatchInput>();
  CLI::App *command = cli.add_subcommand(
      "batch", "run many worlds (files, or folders of them) in parallel; print a table and totals");
  accept_shipped_world_names(command->add_option("WORLD", batch->worlds, "world files (mazes, arenas) or folders, or shipped worlds' names"));
  command->add_option("--jobs", batch->jobs, "N: parallel runs (default all cores)");
  command->add_option("--csv", batch->csv, "FILE: also write the table as CSV");
  command->add_option("--shard", batch->shard,
                      "K/N: run only the K-th of N contiguous parts of the world list (job arrays; join the "
                      "parts' CSVs with batch merge)");
  command->add_flag("--each-start", batch->each_start,
                    "run each world once per start position it states (XML <pos>), a row each");
  command->add_option("--kind", batch->kind,
                      "auto, maze or room: run each world as what it is (a maze as a maze run, an arena as a room "
                      "run), mazes only (arenas skipped), or every world as a room run (default auto)");
  add_merge_command(*command, batch);
  add_room_run_options(*command, *batch);
  add_mapping_run_options(*command, *parsed);
  add_speed_run_option(*command, *parsed);
  auto mms = std::make_shared<MmsOptions>();
  add_mms_options(*command, *mms);
  command->callback([command, parsed, batch, mms, &context] {
    if (command->got_subcommand("merge")) return;
    if (batch->worlds.empty()) throw common::InputError("batch needs a WORLD (world files or folders), or: batch merge CSV...");
    if (!batch->strategy.empty()) read_strategy(batch->strategy, *parsed, batch->room);
    validate_metres(batch->room);
    RunOptions options = checked_run_options(*command, *parsed, false);
    options.output.quiet = true;
    print_warnings(options_not_applying(*command, options));
    const maze::WorldOverrides &w = options.world_overrides;
    if (batch->each_start && (w.start || w.start_position || w.random_start)) {
      throw common::InputError("--each-start runs every start position: leave --start out");
    }
    if (batch->jobs < 0) throw common::InputError(fmt::format("--jobs must be at least 1 (got {})", batch->jobs));
    const int jobs = batch->jobs > 0 ? batch->jobs
                                     : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (!batch->csv.empty()) common::check_writable(batch->csv);  // before the runs, not after
    const bool mms_batch = !context.child_command.empty() || mms_options_given(*command);
    const KindChoice choice = parse_kind_choice(batch->kind);
    if (mms_batch && choice == KindChoice::room) {
      throw common::InputError("--kind room: an mms algorithm runs in mazes (--kind maze or auto)");
    }
    const WorldList list = batch_world_list(*batch, mms_batch ? KindChoice::maze : choice);
    if (mms_batch) {
      context.status = run_mms_batch_command(*command, options, *mms, context.child_command, list, jobs, batch->csv);
      return;
    }
    context.status = run_world_batch(*command, options, *batch, list, choice, jobs);
  });
}

}  // namespace app
