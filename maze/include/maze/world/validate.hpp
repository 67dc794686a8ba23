#pragma once
// What a reader saw, before it becomes a Maze, and the named checks all formats share.
//
// A Maze stores a wall between two cells once, so it cannot disagree with itself; a file can
// (the num format states every shared wall twice). Readers therefore fill a RawMaze, each cell
// with its four sides as the file states them, run the checks, and only then build the Maze.
// Format-specific checks (rectangular, known characters, on the grid) live in the readers.

#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "maze/world/maze.hpp"

namespace maze {

struct RawMaze {
  int width = 0;
  int height = 0;
  // walls[y * width + x][static_cast<int>(side)]: whether the file walls that side of (x, y).
  std::vector<std::array<bool, 4>> walls;
  Cell start{0, 0};
  Side start_heading = Side::north;
  common::SourceLocation start_where;  // where the file states the start (line 0: it does not)
  std::vector<Cell> goals;
  std::vector<common::SourceLocation> goal_where;  // one per goal
  // Every start position when the file states several, the first being the start; checked
  // inside like the start (start_positions_where: one per position).
  std::vector<StartPosition> start_positions;
  std::vector<common::SourceLocation> start_positions_where;
  std::vector<Landmark> landmarks;
  double cell_size_m = kDefaultCellSize_m;
  double wall_thickness_m = kDefaultWallThickness_m;
  double wall_height_m = std::numeric_limits<double>::infinity();  // Maze::wall_height_m
  double origin_x_m = 0.0;
  double origin_y_m = 0.0;
  // Where side s of cell c is written in the file; the file name alone if nowhere.
  std::function<common::SourceLocation(Cell, Side)> where;

  // Allocates width * height cells with no walls; asserts the size is within limits.
  void resize(int w, int h);
  bool wall(Cell c, Side s) const;
  void set(Cell c, Side s, bool present);
};

using CheckResult = std::optional<common::InputError>;

// "maze is WxH cells; each side must be 1 to 4096"
CheckResult check_size(const RawMaze &raw);
// "cell (0,2): west wall missing on the maze's edge", at that side.
CheckResult check_enclosed(const RawMaze &raw);
// "cell (3,4): east wall missing on the west side of (4,4)", at the side that lacks it.
CheckResult check_consistent(const RawMaze &raw);
// "start (5,0) is outside the 4x4 maze", at the start.
CheckResult check_start_inside(const RawMaze &raw);
// "goal (5,0) is outside the 4x4 maze", at that goal.
CheckResult check_goals_inside(const RawMaze &raw);

// Runs the checks above in that order, throws the first failure as common::InputError, then
// builds the Maze.
Maze build_maze(const RawMaze &raw);

// "N cells cannot be reached from the start: (3,3), (3,2)" (the first few), or nothing.
std::optional<std::string> unreachable_summary(const Maze &maze);

// A byte as a message shows it: 'x', "tab", "byte 0xe2".
std::string describe_byte(char c);

}  // namespace maze
