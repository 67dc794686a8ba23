#pragma once
// The subcommands of maze_mapper. Each add_*_command registers its options and a callback
// with CLI11; the callback does the work and stores the process exit status in `status`.
// User errors are thrown as common::InputError and reported by main().

#include <string>
#include <string_view>
#include <vector>

#include "maze/world/world.hpp"

// CLI11 is header-only and its code is generated again in every file that includes it (about
// 10 s a file under the sanitizer build): this header names its App only, so the files that
// call a command's parts without building a command line do not pay for it.
namespace CLI {
class App;
}

namespace app {

struct RunOptions;

struct CommandContext {
  int status = 0;  // exit status of the command that ran
  // When set, `run` stores its checked options here instead of running (fuzzing, tests).
  RunOptions *run_parse_only = nullptr;
  // `mms ... -- COMMAND ARGS...` and `batch ... -- COMMAND ARGS...`: the words after the first
  // `--`, cut off the command line before CLI11 reads it (split_child_command).
  std::vector<std::string> child_command;
};

// For `mms` and `batch`: the arguments before the first `--` (what CLI11 parses) and the
// words after it into context.child_command; other command lines unchanged.
std::vector<std::string> split_child_command(const std::vector<std::string> &args, CommandContext &context);
// `mms [WORLD] [options] -- COMMAND [ARGS...]`: an mms-protocol algorithm drives the robot
// (cmd_mms.cpp, mms_session.hpp).
void add_mms_command(CLI::App &cli, CommandContext &context);

// The program's own flags (--help, --version) and its subcommands, in the order `maze_mapper
// --help` lists them: one list, in cli_app.cpp. `first_word` is the command line's first word:
// when it names a subcommand only that one is built, and for `--version` none (a start that
// builds every command's options costs about half a millisecond); otherwise (empty, --help, a
// misspelt name, `reference`, which describes them all) every one.
void add_commands(CLI::App &cli, CommandContext &context, std::string_view first_word = {});

// maze_mapper demo 1d: the textbook 1-D log-odds exercise; `demo` alone lists the demos
// (cmd_demo.cpp).
void add_demo_command(CLI::App &cli, CommandContext &context);

// maze_mapper explain: the sensor model's numbers (cmd_explain.cpp).
void add_explain_command(CLI::App &cli, CommandContext &context);

// `map-log LOG.csv [options]` (cmd_map_log.cpp): the bump/depth log homework.
void add_map_log_command(CLI::App &cli, CommandContext &context);

// `room WORLD --strategy ...` (cmd_room.cpp): a robot in a room maps it onto a numCells grid.
void add_room_command(CLI::App &cli, CommandContext &context);

// Loads a world (maze::load_world) and prints its warnings on stderr, one a line.
maze::World load_world_reporting(const std::string &path, const maze::WorldOverrides &overrides = {});

// `worlds`: the shipped worlds, one a line: file name, maze or arena, size (world_commands.cpp).
void add_worlds_command(CLI::App &cli, CommandContext &context);
// `show WORLD`: the canonical text map on stdout, nothing else.
void add_show_command(CLI::App &cli, CommandContext &context);
// `convert WORLD OUT [--cell-size M]`: writes OUT in the format its extension names (.txt,
// .num, .xml, .wbt); what that format cannot hold is dropped with one warning on stderr.
void add_convert_command(CLI::App &cli, CommandContext &context);
// `generate WxH [--seed N] [--loops F] [--algorithm dfs|kruskal|prim] [-o FILE]`.
void add_generate_command(CLI::App &cli, CommandContext &context);
// `run [WORLD] [options]`: explore and map a world (cmd_run.cpp, run.hpp).
void add_run_command(CLI::App &cli, CommandContext &context);
// `plan [WORLD] [--from X,Y] [--to X,Y] [options]`: explore, then a wavefront path on the
// learned map; exit status 1 when none is found (cmd_run.cpp).
void add_plan_command(CLI::App &cli, CommandContext &context);
// `compare [WORLD] --subcells K1,K2,... [options]` (cmd_compare.cpp).
void add_compare_command(CLI::App &cli, CommandContext &context);
// The options `maze_mapper run ...` would run with (argv as main gets it: the program, then
// `run` and its arguments), parsed and checked without running (tests, fuzzing). Throws
// CLI::Error or common::InputError as the command line would.
RunOptions parse_run_options(int argc, const char *const *argv);
// `batch WORLD... [--jobs N] [--csv FILE] [run options]` (cmd_batch.cpp, batch.hpp).
void add_batch_command(CLI::App &cli, CommandContext &context);
// `scan WORLD --pose X Y YAW [--cell-size M]`: one lidar range image, `index angle_rad range_m`
// a line. YAW is radians, or degrees with a `deg` suffix (90deg).
void add_scan_command(CLI::App &cli, CommandContext &context);
// `robot [NAME|FILE.json]`: the built-in profiles, one a line, or one profile as JSON.
void add_robot_command(CLI::App &cli, CommandContext &context);

}  // namespace app
