#pragma once
// The true maze: W x H cells, a wall flag on every cell side, a start, goals and the
// physical set-up. This is the world side; the controller never sees it.
//
// Cells (x, y): column x from the west (0 ... W-1), row y from the south (0 ... H-1).
// A wall between two cells is stored once, so the two sides always agree.

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string_view>
#include <utility>
#include <vector>

#include "common/compass.hpp"

namespace maze {

struct Cell {
  int x = 0;
  int y = 0;
  friend constexpr auto operator<=>(const Cell &, const Cell &) = default;
};

// A side of a cell: the one compass type (common/compass.hpp).
using Side = common::Compass;
inline constexpr const auto &kSides = common::kCompassPoints;
using common::opposite;
using common::to_string;  // "north", "east", ...

constexpr Cell neighbour(Cell c, Side s) { return {c.x + common::dx(s), c.y + common::dy(s)}; }

// A wall as a segment on the cell grid, in metres (the wall's centre line, without thickness).
struct WallSegment {
  double x1_m, y1_m, x2_m, y2_m;
};

// A start position: a cell and the heading the robot faces there.
struct StartPosition {
  Cell cell;
  Side heading = Side::north;
  friend bool operator==(const StartPosition &, const StartPosition &) = default;
};

// A landmark of the course's worlds: a coloured cylinder standing at (x, y), in metres, of
// the given height; red, green, blue in [0, 1]. Its radius is the course's,
// kLandmarkRadius_m: a solid the robot's sensors see and its body meets (arena_from_maze).
struct Landmark {
  double x_m = 0.0;
  double y_m = 0.0;
  double height_m = 0.0;
  double red = 1.0, green = 1.0, blue = 1.0;
  friend bool operator==(const Landmark &, const Landmark &) = default;
};
inline constexpr double kLandmarkRadius_m = 0.25;

inline constexpr int kMaxMazeSide = 4096;
inline constexpr double kDefaultCellSize_m = 1.0;
inline constexpr double kDefaultWallThickness_m = 0.012;

class Maze {
 public:
  // An enclosed maze with no interior walls; asserts 1 <= width, height <= kMaxMazeSide.
  Maze(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  bool contains(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }

  // Whether side s of cell c is walled. The outer boundary is a side like any other.
  bool has_wall(Cell c, Side s) const;
  // Sets the wall on side s of c (and so on the opposite side of the neighbour).
  void set_wall(Cell c, Side s, bool present);

  Cell start() const { return start_; }
  Side start_heading() const { return start_heading_; }
  void set_start(Cell c, Side heading) {
    start_ = c;
    start_heading_ = heading;
  }

  // Every start position the world states, in its order (an XML world's <pos> elements);
  // just the start when it states one. The start is one of them unless --start chose another.
  std::vector<StartPosition> start_positions() const;
  // Keeps the list when it holds more than the start alone (so a maze with one start
  // position equals one that never had a list).
  void set_start_positions(std::vector<StartPosition> positions);

  const std::vector<Landmark> &landmarks() const { return landmarks_; }
  void set_landmarks(std::vector<Landmark> landmarks) { landmarks_ = std::move(landmarks); }

  // Goal cells in (x, y) order, each once.
  const std::vector<Cell> &goals() const { return goals_; }
  // Adds c to the goals (nothing if it is one already).
  void add_goal(Cell c);
  void clear_goals() { goals_.clear(); }

  double cell_size_m() const { return cell_size_m_; }
  double wall_thickness_m() const { return wall_thickness_m_; }
  double origin_x_m() const { return origin_x_m_; }
  double origin_y_m() const { return origin_y_m_; }
  void set_physical(double cell_size_m, double wall_thickness_m, double origin_x_m,
                    double origin_y_m);
  // The walls' height above the floor: infinity (above every sensor) unless the file states
  // one (the course's XML: 0.5 m).
  double wall_height_m() const { return wall_height_m_; }
  void set_wall_height_m(double height_m) { wall_height_m_ = height_m; }

  // Cells that can be reached from the start through openings; reachable[y * W + x].
  std::vector<bool> reachable_from_start() const;
  std::size_t reachable_count() const;

  // Open sides between two cells of the maze, each shared side counted once. A perfect maze
  // (one path between any two cells) has width * height - 1.
  std::size_t passage_count() const;
  // Sides between two cells of the maze, open or walled: W(H-1) + H(W-1).
  std::size_t interior_side_count() const;
  bool is_goal(Cell c) const;

  // Every wall as a segment in metres, horizontal runs joined, then vertical runs joined.
  std::vector<WallSegment> wall_segments() const;

  friend bool operator==(const Maze &, const Maze &) = default;

 private:
  // Horizontal walls: (W) x (H + 1), index y * W + x is the wall on the south side of row y.
  // Vertical walls: (W + 1) x H, index y * (W + 1) + x is the wall on the west side of column x.
  std::size_t horizontal_index(int x, int y_line) const;
  std::size_t vertical_index(int x_line, int y) const;

  int width_;
  int height_;
  std::vector<std::uint8_t> horizontal_;
  std::vector<std::uint8_t> vertical_;
  Cell start_{0, 0};
  Side start_heading_ = Side::north;
  std::vector<Cell> goals_;
  std::vector<StartPosition> start_positions_;  // empty: the start alone
  std::vector<Landmark> landmarks_;
  double cell_size_m_ = kDefaultCellSize_m;
  double wall_thickness_m_ = kDefaultWallThickness_m;
  double origin_x_m_ = 0.0;
  double origin_y_m_ = 0.0;
  double wall_height_m_ = std::numeric_limits<double>::infinity();
};

// The lattice's truth for scoring with its solids standing in cells (docs/models.md, "A solid
// inside a cell"): the maze with a wall on every side where a landmark's disc overlaps a
// sub-cell on the robot's path across it: in either cell, along the middle row or column,
// the sub-cells after the centre up to that side's band middle (K = subcells a cell, odd; at
// K = 3 the band middle alone: the sub-cells the wall reading judges a side on,
// controller/mapping/walls.hpp). A landmark on no such sub-cell changes nothing; a maze
// without landmarks comes back as it is.
Maze with_solid_sides(const Maze &maze, int subcells);

}  // namespace maze
