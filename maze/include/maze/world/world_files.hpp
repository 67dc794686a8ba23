#pragma once
// World files: the formats, told once from a file's first bytes; reading a file's text in
// proportion; writing a maze or an arena in the format an output's extension names, safely.
// world.hpp turns the text into a World.

#include <optional>
#include <string>
#include <string_view>

#include "maze/world/geometry.hpp"
#include "maze/world/maze.hpp"

namespace maze {

// room: an arena's plain format (solids_format.hpp).
enum class Format { text_map, num, xml, wbt, maz, room };

// The input format by content, by the rule of format_detector.hpp (a .maz's first bytes, else
// the first line not blank or a comment: '<' XML, 'o' or '+' a text map, a digit num, a room
// keyword a room file). Throws common::InputError when it is none of these.
Format detect_format(std::string_view text, const std::string &file);

// Reads a grid maze from text in any input format, validated. Throws common::InputError.
Maze read_world(std::string_view text, const std::string &file);
// Likewise, the format already told (detect_format): a room file is refused as an arena.
Maze read_world(std::string_view text, const std::string &file, Format format);

// A world file's text and its format, told once, from its first bytes.
struct WorldText {
  std::string text;
  Format format = Format::text_map;
};
// A world file's text, read in proportion: the format is told as the bytes arrive, as soon
// as they tell it (format_detector.hpp: an image or /dev/zero fails at once, a file of blank
// lines after its first 1 MiB), reading stops at a NUL byte (an error: no text format holds
// one), past a .maz's 256 bytes and past 1 GiB (common::kMaxWorldBytes). Throws
// common::InputError; common::Interrupted when a stop signal ends a wait (a FIFO's writer,
// common/input_file.hpp).
WorldText read_world_file(const std::string &path);
// The format of a world file, reading only as much of it as telling it takes (the rule and
// errors of read_world_file).
Format read_world_format(const std::string &path);
// read_world_file's text alone.
std::string read_world_text(const std::string &path);

// What writing the maze in `format` would drop, as one line "FORMAT holds no ...: dropped
// ...", or nothing when the format holds all of it (the text map keeps walls, start cell and
// goals, not the heading of a start or the physical set-up; num keeps only the walls).
std::optional<std::string> dropped_by(const Maze &maze, Format format);

// Likewise for an arena: a room file holds no landmark ("dropped 4 landmarks: a room file holds
// the walls as rectangles, the start and the goals"); XML holds all of it.
std::optional<std::string> dropped_by(const Arena &arena, Format format);

// The output format by extension, in any case (.txt, .TXT): .txt, .num, .xml, .wbt, .maz,
// .room; throws common::InputError otherwise.
Format format_for_output(const std::string &path);

// The maze in `format` (any, wbt included; room: arena_from_maze's arena); `title` names the
// world inside a .wbt.
std::string format_world(const Maze &maze, Format format, std::string_view title);
// Writes the maze to `path` in the format its extension names.
void save_world(const Maze &maze, const std::string &path);

// The arena in `format`: room or xml. Others throw common::InputError "a FORMAT file holds a
// grid maze; an arena is written as .room or .xml".
std::string format_arena(const Arena &arena, Format format);
// Writes the arena to `path` in the format its extension names (.room, .xml).
void save_arena(const Arena &arena, const std::string &path);

// A maze as an arena: each wall a capped rectangle (the maze's walls as solids), each
// landmark a disc of kLandmarkRadius_m, the start cell's centre facing its heading, each goal
// cell's centre; the boundary the maze's outer edge.
Arena arena_from_maze(const Maze &maze);

// The whole file; throws common::InputError "cannot read FILE: reason" (also above 1 GiB),
// common::Interrupted as read_world_text does.
std::string read_file(const std::string &path);

// common::write_file_atomically (common/atomic_file.hpp): a regular file through a temporary
// renamed over it, a symbolic link's target likewise, a device or FIFO written directly. On
// failure nothing is left behind and common::InputError "cannot write FILE: reason" is thrown.
void write_file_atomically(const std::string &path, std::string_view content);

}  // namespace maze
