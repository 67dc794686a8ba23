#pragma once
// Worlds as files: reading one whatever its format (detected by content), writing one by the
// output's extension, safely.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "maze/world/maze.hpp"

namespace maze {

// room: an arena's plain format (room_format.hpp; arena_world.hpp reads arenas).
enum class Format { text_map, num, xml, wbt, maz, room };

// A maze read from a file, with what the user should hear about it.
struct World {
  Maze maze;
  std::string file;                   // the path as the user gave it
  std::vector<std::string> warnings;  // whole lines, "FILE: warning: ...", without '\n'
  Format format = Format::text_map;   // the format it was read in
};

// What a command line supplies or overrides in the world it loads (--cell-size, --start,
// --goal), checked where it is parsed; load_world applies it.
struct WorldOverrides {
  // Text and num worlds: cells of this size (m), walls kDefaultWallThickness_m, origin (0, 0).
  // An XML world has its own size: one that differs by more than 1e-9 of it is an error.
  std::optional<double> cell_size_m;
  std::optional<Cell> start;           // replaces the file's start
  // --start Xm,Ym[,HEADING]: the start given in metres, the cell that holds the point.
  std::optional<std::array<double, 2>> start_m;
  Side start_heading = Side::north;    // with start
  // --start pos:N: the world's N-th start position (1-based), cell and heading.
  std::optional<int> start_position;
  // --start random: one of the world's start positions, the same for the same seed
  // (random_start_index).
  bool random_start = false;
  std::uint64_t random_start_seed = 0;
  std::optional<std::vector<Cell>> goals;  // replace the file's goals
  // --goal centre: the goals are the maze's centre cells (the micromouse convention: 2 x 2 on
  // an even size, a row or column of 2 or one cell on odd ones), in place of the file's.
  bool centre_goals = false;
};

// The 0-based index of the start position --start random picks among count (>= 1) with seed:
// the first draw of common::Rng(seed ^ 0x7374617274), modulo count.
std::size_t random_start_index(std::uint64_t seed, std::size_t count);

// The smallest and largest --cell-size: a cell wider than four default walls, and 1 km.
inline constexpr double kMinCellSize_m = 4 * kDefaultWallThickness_m;
inline constexpr double kMaxCellSize_m = 1000.0;

// The input format by content: '<' first (after blanks) is XML, 'o' or '+' first a text map,
// a digit first a num file, a room statement first (after blank and '#' comment lines) a room
// file. Throws common::InputError when it is none of these.
Format detect_format(std::string_view text, const std::string &file);

// Reads a world from text in any input format, validated. Throws common::InputError.
Maze read_world(std::string_view text, const std::string &file);
// Likewise, the format already told (detect_format): a room file is refused as an arena.
Maze read_world(std::string_view text, const std::string &file, Format format);

// Reads, detects, validates; unreachable cells become a warning. Throws common::InputError
// ("cannot read FILE: reason", or the fault's place in the file).
World load_world(const std::string &path);
// Likewise, then applies the overrides (before the unreachable-cells warning, which follows
// the start). Throws common::InputError "--start 9,9 is outside the 4x4 maze" and the like.
World load_world(const std::string &path, const WorldOverrides &overrides);
// load_world on a file's text already read (read_world_text).
World load_world_text(const std::string &text, const std::string &path, const WorldOverrides &overrides);
// Likewise, its format already told (read_world_file): the format is detected once a load.
World load_world_text(const std::string &text, const std::string &path, const WorldOverrides &overrides,
                      Format format);

// A world file's text and its format, told once, from its first bytes.
struct WorldText {
  std::string text;
  Format format = Format::text_map;
};
// A world file's text, read in proportion: the format is told from the first bytes that are
// not blank (so an image or /dev/zero fails at once), reading stops at a NUL byte (an
// error: no text format holds one) and past a .maz's 256 bytes. Throws common::InputError;
// common::Interrupted when a stop signal ends a wait (a FIFO's writer, common/input_file.hpp).
WorldText read_world_file(const std::string &path);
// read_world_file's text alone.
std::string read_world_text(const std::string &path);

// What writing the world in `format` would drop, as one line "FORMAT holds no ...: dropped
// ...", or nothing when the format holds all of it (the text map keeps walls, start cell and
// goals, not the heading of a start or the physical set-up; num keeps only the walls).
std::optional<std::string> dropped_by(const Maze &maze, Format format);

// The output format by extension, in any case (.txt, .TXT): .txt, .num, .xml, .wbt, .maz,
// .room; throws common::InputError otherwise.
Format format_for_output(const std::string &path);

// The maze in `format` (any, wbt included; room: arena_from_maze's arena); `title` names the
// world inside a .wbt.
std::string format_world(const Maze &maze, Format format, std::string_view title);

// Writes the maze to `path` in the format its extension names.
void save_world(const Maze &maze, const std::string &path);

// The whole file; throws common::InputError "cannot read FILE: reason" (also above 1 GiB),
// common::Interrupted as read_world_text does.
std::string read_file(const std::string &path);

// common::write_file_atomically (common/atomic_file.hpp): a regular file through a temporary
// renamed over it, a symbolic link's target likewise, a device or FIFO written directly. On
// failure nothing is left behind and common::InputError "cannot write FILE: reason" is thrown.
void write_file_atomically(const std::string &path, std::string_view content);

}  // namespace maze
