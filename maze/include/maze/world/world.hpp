#pragma once
// A world: geometry in metres (walls with their thickness, boxes, landmark cylinders, the
// floor's bounds) plus starts, goals and landmarks; and, when its walls lie on a cell lattice,
// that lattice (what makes it a maze). The cell explorer, floodfill, mms and the micromouse
// formats read the lattice view; the simulator, the room strategies and pictures in metres
// read the geometry. Every reader produces a World, and a file's format is told once.
//
//     a file --read_world_file--> text, Format --load_world--> World
//                                                               |-- lattice(): Maze (cells, sides)
//                                                               `-- geometry(): Arena (metres)
//
// Which a file is: a room file is free geometry (an arena); an XML world is one by
// xml_world_is_arena's rule (xml_solids.hpp), else a maze; every other format is a maze.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "common/error.hpp"
#include "maze/world/geometry.hpp"
#include "maze/world/maze.hpp"
#include "maze/world/world_files.hpp"

namespace maze {

class World {
 public:
  // A maze: walls on a lattice.
  World(Maze maze, std::string file, Format format);
  // Free geometry (an arena): validated by the caller (validate_arena). why_not_a_maze: what
  // reading the file as a grid maze says (maze() repeats it), when it was read from one.
  World(Arena arena, std::string file, Format format,
        std::optional<common::InputError> why_not_a_maze = std::nullopt);

  // Whether its walls lie on a cell lattice.
  bool on_lattice() const { return std::holds_alternative<Maze>(shape_); }
  // The lattice view, or nullptr when the walls lie on none.
  const Maze *lattice() const { return std::get_if<Maze>(&shape_); }
  // The lattice view. Throws common::InputError when the walls lie on none: why_not_a_maze's
  // place and words, then "; it reads as an arena (a room of obstacles): map it with
  // `maze_mapper room FILE`".
  const Maze &maze() const;
  Maze &maze();
  // The free geometry of a world on no lattice; asserts !on_lattice().
  const Arena &arena() const;
  Arena &arena();
  // The geometry, whatever the world: free geometry as it is; a lattice's as
  // arena_from_maze(maze()), built on each call (O(walls)).
  Arena geometry() const;
  // The world's name: an arena's own, else the file's stem.
  std::string name() const;

  std::string file;                   // the path as the user gave it
  std::vector<std::string> warnings;  // whole lines, "FILE: warning: ...", without '\n'
  Format format = Format::text_map;   // the format it was read in

 private:
  std::variant<Maze, Arena> shape_;
  std::optional<common::InputError> why_not_a_maze_;
};

// A world built in code, read from no file (file empty): a maze (format text_map), or free
// geometry (format room), validated by the caller as World's constructor says. The world stays
// a lattice or free geometry as given: an arena whose walls happen to lie on cells is no maze.
World world_of(Maze maze);
World world_of(Arena arena);

// What a command line supplies or overrides in the world it loads, checked where it is
// parsed; load_world applies it. The cell ones (--cell-size, --start, --goal) apply to a maze
// and are refused on an arena; --boundary applies to an arena and is refused on a maze.
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

  // --boundary XS,XE,YS,YE (m): replaces an arena file's boundary, or the default one.
  std::optional<std::array<double, 4>> boundary_m;
  // The robot's body radius: an arena's starts are checked clear by it (0: the points).
  double robot_radius_m = 0.0;
};

// The 0-based index of the start position --start random picks among count (>= 1) with seed:
// the first draw of common::Rng(seed ^ 0x7374617274), modulo count.
std::size_t random_start_index(std::uint64_t seed, std::size_t count);

// The smallest and largest --cell-size: a cell wider than four default walls, and 1 km.
inline constexpr double kMinCellSize_m = 4 * kDefaultWallThickness_m;
inline constexpr double kMaxCellSize_m = 1000.0;

// Reads, detects the format once, validates, applies the overrides: a maze (an unreachable
// cell a warning, after the start is set) or an arena (its boundary: the override, the
// file's, or apply_default_boundary's). Throws common::InputError ("cannot read FILE:
// reason", the fault's place in the file, "--start 9,9 is outside the 4x4 maze", "--start
// names cells of a grid maze; FILE is an arena ...", "--boundary applies to arenas; ...").
World load_world(const std::string &path, const WorldOverrides &overrides = {});
// load_world on a file's text already read (read_world_file), its format told.
World load_world_text(std::string_view text, const std::string &path, const WorldOverrides &overrides,
                      Format format);
// Likewise, the format told from the text.
World load_world_text(std::string_view text, const std::string &path, const WorldOverrides &overrides = {});

// Whether text in `format` holds an arena: a room file does, an XML world by
// xml_world_is_arena's rule (at cell_size_m when given), no other format.
bool holds_arena(std::string_view text, Format format, const std::string &file,
                 std::optional<double> cell_size_m = std::nullopt);

// The boundary of an arena whose file states none: the obstacles' bounding box when they
// enclose the start (at 0.05 m cells, no free cell 4-connected to the start's touches the
// box's edge), else the course's floor, 17 x 17 m centred on the origin.
void apply_default_boundary(Arena &arena);

}  // namespace maze
