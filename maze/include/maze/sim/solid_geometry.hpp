#pragma once
// A world's solids for ray casting and collisions (World::geometry(): an arena's own, a
// maze's walls as capped rectangles and its landmarks as cylinders), with WallGrid's queries
// (wall_grid.hpp) so the same sensor and motion code runs on both. The simulator runs a maze
// without landmarks on its WallGrid and every other world on this.
//
// The solids are the geometry's obstacles (closed oriented rectangles), its discs (closed
// circles: upright cylinders) and its boundary, walled all round unless the geometry says
// it is open (Arena::boundary_walled): walled, outside the boundary is solid, as the walls
// of a Webots RectangleArena make it; open (a Webots Floor's edge), a ray leaving it meets
// nothing more and the body is not held in. Heights play no part here: a beam at a height
// casts on the solids above it (maze::solids_above).
// A uniform grid of buckets covers the boundary, each listing the obstacles that touch it
// (built once, O(obstacles x the buckets each covers)):
//
//     +----+----+----+----+      a ray walks the buckets it crosses (Amanatides-Woo) and
//     |    |  ##|##  |    |      tests only the obstacles they list; it stops in the first
//     |  ~~~~~~~##~~>|    |      bucket whose nearest hit lies inside it. Its cost grows
//     |    |  ##|##  |    |      with the buckets it crosses, not with the obstacle count.
//     +----+----+----+----+
//
// Buckets are square, the boundary's longer side / 64 but at least 0.1 m, so at most 64 x 64
// of them for an arena of 6.4 m or more.

#include <cstdint>
#include <optional>
#include <vector>

#include "maze/world/geometry.hpp"
#include "maze/sim/wall_grid.hpp"

namespace maze::sim {

class SolidGeometry {
 public:
  // The geometry must have a non-empty boundary (validate_arena).
  explicit SolidGeometry(const Arena &geometry);

  double x_min_m() const { return x_min_m_; }
  double y_min_m() const { return y_min_m_; }
  double x_max_m() const { return x_max_m_; }
  double y_max_m() const { return y_max_m_; }
  double bucket_m() const { return bucket_m_; }
  int buckets_x() const { return nx_; }
  int buckets_y() const { return ny_; }

  // Whether the point lies within the boundary (closed).
  bool inside_bounds(double x_m, double y_m) const;
  // Whether the point lies inside or on an obstacle, or outside a walled boundary.
  bool inside_solid(double x_m, double y_m) const;

  // A ray origin with what every ray from it shares computed once.
  struct CastOrigin {
    double x_m, y_m;
    int bucket_x, bucket_y;
    bool inside;  // inside_bounds
  };
  CastOrigin cast_origin(double x_m, double y_m) const;

  // Distance from the origin along the unit vector (dx, dy) to the first solid surface (an
  // obstacle, or a walled boundary from inside), +infinity beyond max_range_m or from an origin
  // outside the boundary; 0 from inside an obstacle. normal, when given, receives the unit
  // outward normal of the surface met ((0, 0) when nothing is), the face entered last when
  // the ray meets an edge.
  double cast_from(const CastOrigin &origin, double dx, double dy, double max_range_m,
                   double *normal_x = nullptr, double *normal_y = nullptr) const;
  double cast_direction(double x_m, double y_m, double dx, double dy, double max_range_m) const;
  double cast(double x_m, double y_m, double angle_rad, double max_range_m) const;
  // The same answer by testing every obstacle (for the tests: cast_from must agree with it).
  double cast_brute_force(double x_m, double y_m, double dx, double dy, double max_range_m) const;

  // Pushes a disc of radius_m centred at (x, y) out of every solid it overlaps (the smallest
  // move: motion along a surface slides, into it stops), back inside the boundary. Returns
  // whether it moved.
  bool push_out(double &x_m, double &y_m, double radius_m) const;
  // A box of centres where a disc of radius_m touches no solid, around (x, y): the point's
  // bucket, with its eight neighbours when they are all empty, less radius_m and a margin;
  // nothing when the point's bucket lists an obstacle, or the point is outside. O(1).
  std::optional<Box> free_centres(double x_m, double y_m, double radius_m) const;
  // The nearest surface point of each obstacle, and of each boundary side, within reach_m.
  std::vector<Contact> contacts(double x_m, double y_m, double reach_m) const;

 private:
  struct Solid {
    double cx, cy, c, s, hl, hw;        // centre, axis (cos, sin), half length and width
    double x0, y0, x1, y1;              // bounding box (exact for axis-aligned ones)
    bool aligned;
    double r = 0.0;                     // a disc's radius (a disc: hl = hw = 0, not aligned)
    bool disc = false;
  };
  // A disc's entry distance along the unit ray, and the normal there (entry's, for discs).
  static double disc_entry(const Solid &k, double ox, double oy, double dx, double dy, double &nx, double &ny);
  // The entry distance of the ray into solid k, or +infinity; the entered face's normal.
  double entry(const Solid &k, double ox, double oy, double dx, double dy, double &nx, double &ny) const;
  // The obstacle indices listed in the buckets meeting [x0, x1] x [y0, y1], each once.
  std::vector<std::uint32_t> near(double x0, double y0, double x1, double y1) const;
  std::size_t bucket_index(int bx, int by) const {
    return static_cast<std::size_t>(by) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(bx);
  }
  int bucket_of_x(double x_m) const;
  int bucket_of_y(double y_m) const;

  double x_min_m_, y_min_m_, x_max_m_, y_max_m_;
  bool walled_ = true;  // Arena::boundary_walled
  double bucket_m_;
  int nx_, ny_;
  std::vector<Solid> solids_;
  std::vector<std::uint32_t> first_;  // bucket b lists items_[first_[b] .. first_[b + 1])
  std::vector<std::uint32_t> items_;
};

}  // namespace maze::sim
