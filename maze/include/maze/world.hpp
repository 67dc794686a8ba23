#pragma once
// Worlds as files: reading one whatever its format (detected by content), writing one by the
// output's extension, safely.

#include <string>
#include <string_view>
#include <vector>

#include "maze/maze.hpp"

namespace maze {

enum class Format { text_map, num, xml, wbt };

// A maze read from a file, with what the user should hear about it.
struct World {
  Maze maze;
  std::string file;                   // the path as the user gave it
  std::vector<std::string> warnings;  // whole lines, "FILE: warning: ...", without '\n'
};

// The input format by content: '<' first (after blanks) is XML, 'o' or '+' first a text map,
// a digit first a num file. Throws common::InputError when it is none of these.
Format detect_format(std::string_view text, const std::string &file);

// Reads a world from text in any input format, validated. Throws common::InputError.
Maze read_world(std::string_view text, const std::string &file);

// Reads, detects, validates; unreachable cells become a warning. Throws common::InputError
// ("cannot read FILE: reason", or the fault's place in the file).
World load_world(const std::string &path);

// The output format by extension: .txt, .num, .xml, .wbt; throws common::InputError otherwise.
Format format_for_output(const std::string &path);

// The maze in `format` (any, wbt included); `title` names the world inside a .wbt.
std::string format_world(const Maze &maze, Format format, std::string_view title);

// Writes the maze to `path` in the format its extension names.
void save_world(const Maze &maze, const std::string &path);

// The whole file; throws common::InputError "cannot read FILE: reason" (also above 1 GiB).
std::string read_file(const std::string &path);

// Writes to a temporary file in the target's directory, then renames it over the target, so
// readers never see half a file. On failure nothing is left behind and common::InputError
// "cannot write FILE: reason" is thrown.
void write_file_atomically(const std::string &path, std::string_view content);

}  // namespace maze
