#pragma once
// Worlds that may be arenas: the loader that returns a maze or an arena, the boundary rule,
// and arenas written out (room format, the course's XML).
//
// Which a file is: a room file (room_format.hpp) is an arena; an XML world is an arena by
// xml_world_is_arena's rule (xml_arena.hpp), else a maze; every other format is a maze.

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "maze/world/arena.hpp"
#include "maze/world/world.hpp"

namespace maze {

// An arena read from a file, with what the user should hear about it.
struct ArenaWorld {
  Arena arena;
  std::string file;                   // the path as the user gave it
  std::vector<std::string> warnings;  // whole lines, "FILE: warning: ...", without '\n'
  Format format = Format::room;       // the format it was read in
};

// What a command line supplies for an arena.
struct ArenaOverrides {
  // --boundary XS,XE,YS,YE (m): replaces the file's boundary, or the default one.
  std::optional<std::array<double, 4>> boundary_m;
  // The robot's body radius: validate_arena checks the starts clear by it (0: the points).
  double robot_radius_m = 0.0;
};

// The boundary of an arena whose file states none: the obstacles' bounding box when they
// enclose the start (at 0.05 m cells, no free cell 4-connected to the start's touches the
// box's edge), else the course's floor, 17 x 17 m centred on the origin.
void apply_default_boundary(Arena &arena);

// Reads an arena from text in the room format or the course's XML (by content), applies the
// boundary (the override, the file's, or the default) and validates it. Throws
// common::InputError; a maze-only XML is "… is a grid maze, not an arena".
ArenaWorld read_arena_world(std::string_view text, const std::string &file, const ArenaOverrides &overrides);
// Likewise, its format already told (detect_format).
ArenaWorld read_arena_world(std::string_view text, const std::string &file, const ArenaOverrides &overrides,
                            Format format);

// Whether text in `format` holds an arena: a room file does, an XML world by
// xml_world_is_arena's rule (at cell_size_m when given), no other format.
bool holds_arena(std::string_view text, Format format, const std::string &file,
                 std::optional<double> cell_size_m = std::nullopt);

using AnyWorld = std::variant<World, ArenaWorld>;

// Reads the file and returns a maze (load_world's reading, overrides applied) or an arena
// (read_arena_world's). The maze overrides that name cells (--start, --goal, --cell-size) are
// refused on an arena, and --boundary on a maze. Throws common::InputError.
AnyWorld load_any_world(const std::string &path, const WorldOverrides &maze_overrides,
                        const ArenaOverrides &arena_overrides);
bool is_arena(const AnyWorld &world);
// A world's geometry, whatever it was read as: an arena's own, or a maze's walls as solids
// (arena_from_maze), its start cell's centre and its goal cells' centres.
Arena world_geometry(const AnyWorld &world);
// The world's cell lattice view when its walls lie on one (a grid maze), else nullptr.
const Maze *lattice_view(const AnyWorld &world);
// What the user should hear about the world as it was read ("FILE: warning: ..." lines).
const std::vector<std::string> &world_warnings(const AnyWorld &world);

// The arena in `format`: room or xml. Others throw common::InputError "a FORMAT file holds a
// grid maze; an arena is written as .room or .xml".
std::string format_arena(const Arena &arena, Format format);
// Writes the arena to `path` in the format its extension names (.room, .xml).
void save_arena(const Arena &arena, const std::string &path);

// A maze as an arena: each wall a capped rectangle (the maze's walls as solids), the start
// cell's centre facing its heading, each goal cell's centre; the boundary the maze's outer edge.
Arena arena_from_maze(const Maze &maze);

}  // namespace maze
