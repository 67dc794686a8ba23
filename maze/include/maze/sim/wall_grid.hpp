#pragma once
// The maze's walls as solid geometry, for ray casting and collisions (ARCHITECTURE.md, Conventions: walls as solids).
//
// A wall on a cell side is a rectangle centred on that side, as long as the side plus the
// wall thickness and as thick as the wall. Cut along the cell grid, the solid part inside
// one cell is at most four side strips (half a wall thick) and four corner squares (half a
// wall thick on each side), the corner square being solid when any wall meets that grid
// vertex. WallGrid stores those eight flags per cell, built once from the maze; every
// query then looks only at the cells it crosses, never at the whole maze.
//
//          NW corner    north strip     NE corner
//              +--+-------------------+--+
//              |##|###################|##|   <- half a wall thickness (h = t / 2)
//              +--+                   +--+
//   west strip |##|       free        |##| east strip
//              +--+                   +--+
//              |##|###################|##|
//              +--+-------------------+--+
//          SW corner    south strip     SE corner
//
// Rectangles are closed: a ray that touches a wall's face or corner hits it.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "maze/world/maze.hpp"

namespace maze::sim {

// An axis-aligned solid box in world metres.
struct Box {
  double x_min_m, y_min_m, x_max_m, y_max_m;

  // Whether (x, y) lies strictly inside.
  bool strictly_contains(double x_m, double y_m) const {
    return x_m > x_min_m && x_m < x_max_m && y_m > y_min_m && y_m < y_max_m;
  }
  // Whether the disc of radius margin_m around (x, y) lies strictly inside.
  bool contains_with_margin(double x_m, double y_m, double margin_m) const {
    return x_m - margin_m > x_min_m && x_m + margin_m < x_max_m && y_m - margin_m > y_min_m &&
           y_m + margin_m < y_max_m;
  }
};

// A point on a wall's surface within reach of a disc, and the disc centre's distance to it.
struct Contact {
  double x_m, y_m, distance_m;
};

class WallGrid {
 public:
  // O(width x height) once; afterwards no query is proportional to the maze.
  explicit WallGrid(const Maze &maze);

  int width() const { return width_; }
  int height() const { return height_; }
  double cell_size_m() const { return cell_size_m_; }
  double wall_thickness_m() const { return 2.0 * half_thickness_m_; }

  // Whether the point lies within the maze's outer edge (the outer walls' centre lines).
  bool inside_maze(double x_m, double y_m) const;
  // Whether the point lies inside (or on the surface of) a wall.
  bool inside_wall(double x_m, double y_m) const;

  // Distance from (x, y) along the direction angle_rad (0 east, counter-clockwise) to the
  // first wall surface, or +infinity when there is none within max_range_m. Walks the cells
  // the ray crosses (Amanatides-Woo) and tests only the solid boxes of those cells.
  // The origin must not be inside a wall (check it with inside_wall); on a wall's surface,
  // a ray into the wall returns 0.
  double cast(double x_m, double y_m, double angle_rad, double max_range_m) const;
  // The same along the unit vector (dx, dy).
  double cast_direction(double x_m, double y_m, double dx, double dy, double max_range_m) const;
  // A ray origin with what every ray from it shares computed once (a scan casts hundreds).
  struct CastOrigin {
    double x_m, y_m;                // world
    double local_x_m, local_y_m;    // from the maze's south-west corner
    int cell_x, cell_y;             // the cell holding it (when inside)
    bool inside;                    // inside_maze(x_m, y_m)
  };
  CastOrigin cast_origin(double x_m, double y_m) const;
  // cast_direction from a prepared origin: the same answers.
  double cast_from(const CastOrigin &origin, double dx, double dy, double max_range_m) const;
  // ranges[k] = cast_from(origin, dx[k], dy[k], max_range_m) for a fan of beams (the spans
  // of one length): the same answers, the beams' direction inverses computed in a loop of
  // their own so that their divisions overlap.
  void cast_fan(const CastOrigin &origin, std::span<const double> dx, std::span<const double> dy,
                double max_range_m, std::span<double> ranges) const;
  // cast_direction's plain form, one slab test per box: the same answers bit for bit (the
  // tests hold cast_direction to it); cast_direction uses it for rays along an axis and for
  // rays with a subnormal component.
  double cast_reference(double x_m, double y_m, double dx, double dy, double max_range_m) const;

  // Pushes a disc of radius_m centred at (x, y) out of every wall it overlaps (the smallest
  // move, so motion along a wall slides and motion into it stops). Returns whether it moved.
  bool push_out(double &x_m, double &y_m, double radius_m) const;

  // Where the centre of a disc of radius_m may be without touching any wall, around the
  // point (x, y): the part of the point's cell farther than radius_m (plus a margin far
  // above rounding) from everything solid that cell could hold, i.e. from its sides less
  // half a wall thickness; when the point is beyond that part towards an open side (and
  // within it the other way), the box spans the neighbour across that side as well. A disc
  // centred strictly inside the box touches no wall and needs no push_out.
  // Nothing when the point is outside the maze or the disc does not fit in a cell. O(1).
  std::optional<Box> free_centres(double x_m, double y_m, double radius_m) const;

  // The nearest surface point of each solid box within reach_m of (x, y).
  std::vector<Contact> contacts(double x_m, double y_m, double reach_m) const;

 private:
  enum Flag : std::uint8_t {
    kNorth = 1, kEast = 2, kSouth = 4, kWest = 8,
    kCornerNE = 16, kCornerNW = 32, kCornerSW = 64, kCornerSE = 128,
  };
  // cast_quadrant's clear margin, in cells of path along each axis: far above the rounding
  // between the walk's summed crossing distances and the slab tests' own (some ulps of a
  // coordinate, k^2 / 2 ulps of a cell after k cells: it holds to 10^5 cells).
  static constexpr double kClearPass_cells = 1e-6;
  std::uint8_t flags(int cx, int cy) const {
    return flags_[static_cast<std::size_t>(cy) * static_cast<std::size_t>(width_) +
                  static_cast<std::size_t>(cx)];
  }
  // cast_from for a ray with dx, dy != 0 from inside the maze, the signs fixed at compile time.
  // inv_dx, inv_dy: 1 / dx, 1 / dy. A ray leaving a cell across its far x side before it comes
  // within h of its far y side, by a clear margin (kClearPass_cells), passes the far y side's
  // strip and corners: their slab tests would find the entry in y after the exit in x. The walk
  // leaves those boxes out (and the same with x and y swapped); near a far corner it tests all.
  template <bool kEastward, bool kNorthward>
  [[gnu::always_inline]] inline double cast_quadrant(const CastOrigin &origin, double inv_dx, double inv_dy,
                                                     double max_range_m) const;
  // cast_from with 1 / dx and 1 / dy given.
  double cast_with_inverses(const CastOrigin &origin, double dx, double dy, double inv_dx, double inv_dy,
                            double max_range_m) const;
  // Where a ray of that quadrant enters the solid boxes f (flags, those facing it) of cell
  // (cx, cy): the path length, or infinity when it misses them all.
  template <bool kEastward, bool kNorthward>
  double entry_in_cell(std::uint8_t f, int cx, int cy, const CastOrigin &origin, double inv_dx, double inv_dy) const;
  // Calls visit(const Box &) for each solid box of cell (cx, cy) whose flags are in mask.
  template <typename Visit>
  void for_each_box(int cx, int cy, std::uint8_t mask, Visit &&visit) const;
  // Calls visit(const Box &) for the solid boxes of every cell meeting the square of
  // half-side reach_m around (x, y), row by row from the south, without allocating.
  template <typename Visit>
  void for_each_box_near(double x_m, double y_m, double reach_m, Visit &&visit) const;

  int width_;
  int height_;
  double cell_size_m_;
  double half_thickness_m_;
  double origin_x_m_;
  double origin_y_m_;
  std::vector<std::uint8_t> flags_;  // flags_[y * width + x]
};

}  // namespace maze::sim
