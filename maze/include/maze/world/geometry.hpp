#pragma once
// An arena: a world that is a boundary and solid obstacles in metres, on no lattice (a room,
// an obstacle field, the course's arenas of thick walls). The world frame is the conventions'
// (ARCHITECTURE.md): x east, y north, metres; yaw 0 east, counter-clockwise, radians.
//
//     y_max_m +----------------------------+      the boundary: the floor the robot stays
//             |        ####                |      on, walled all round (a ray stops at it,
//             |        ####   ######  G    |      the body cannot leave it)
//             |  S            ######       |      obstacles: solid oriented rectangles
//     y_min_m +----------------------------+      S a start pose, G a goal point
//          x_min_m                       x_max_m
//
// An obstacle is a rectangle with a centre, a long axis at angle_rad from east, a half length
// along it and a half width across it. Made from a wall segment (x1, y1)-(x2, y2) and a width
// (WallEnds says how long): the rectangle centred on the segment's midpoint along it, as wide
// as the width and, with WallEnds::flush (the course's XML: a Webots box of size width x
// length), exactly as long as the segment; with WallEnds::capped (the maze's walls as solids),
// half a width longer at each end, so walls meeting at a corner close it.
//
// Rectangles are closed: a point on an edge is inside; a ray that touches an edge hits it.
//
// Heights: every solid stands on the floor up to its top, z up from the floor in metres. A
// format that states none (a maze's walls, a room's obstacles, a plain cylinder) gives
// kTallerThanEverySensor_m, so every beam and line of sight meets it; the course's XML walls
// are 0.5 m high (its library's Obstacle), a landmark is its own height tall. A horizontal
// beam at height z is blocked by a solid only when z is below its top (top > z).

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "common/error.hpp"

namespace maze {

struct ArenaPoint {
  double x_m = 0.0;
  double y_m = 0.0;
};

struct ArenaPose {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;
};

enum class WallEnds { flush, capped };

// The height of a solid whose file states none: above every sensor.
inline constexpr double kTallerThanEverySensor_m = std::numeric_limits<double>::infinity();
// The course's walls (its library's Obstacle and BoundaryWall: size z 0.5 m).
inline constexpr double kCourseWallHeight_m = 0.5;

struct Obstacle {
  double centre_x_m = 0.0;
  double centre_y_m = 0.0;
  double half_length_m = 0.0;  // along the axis at angle_rad
  double half_width_m = 0.0;   // across it
  double angle_rad = 0.0;
  common::SourceLocation where;  // where the file states it (line 0: it does not)
  // from_box's extent {x_min, y_min, x_max, y_max}, which bounds() returns while angle_rad is 0
  // (the centre and half sizes, halved, would round it).
  std::optional<std::array<double, 4>> box;
  double height_m = kTallerThanEverySensor_m;  // its top above the floor

  // The axis-aligned rectangle [x0, x1] x [y0, y1] (corners in any order), its extent kept
  // exactly as given.
  static Obstacle from_box(double x0_m, double y0_m, double x1_m, double y1_m);
  // The rectangle centred on (cx, cy), its long axis at angle_rad from east.
  static Obstacle oriented(double centre_x_m, double centre_y_m, double half_length_m, double half_width_m,
                           double angle_rad);
  // The wall from (x1, y1) to (x2, y2), width_m thick; see the drawing above for `ends`. A
  // zero-length segment makes a width x width square (capped) or an empty one (flush).
  static Obstacle from_segment(double x1_m, double y1_m, double x2_m, double y2_m, double width_m, WallEnds ends);

  // The four corners, counter-clockwise from the one at -length, -width.
  std::array<ArenaPoint, 4> corners() const;
  // The smallest axis-aligned box holding it: {x_min, y_min, x_max, y_max}.
  std::array<double, 4> bounds() const;
  // Whether its sides are parallel to the axes (to 1e-12 rad), and then its extent exactly.
  bool axis_aligned() const;
  // Whether (x, y) lies inside or on its edge.
  bool contains(double x_m, double y_m) const;
  // The distance from (x, y) to it (0 inside), and its nearest point.
  double distance_m(double x_m, double y_m) const;
  ArenaPoint nearest_point(double x_m, double y_m) const;
  // The segment along its longer side's middle, end to end, and the shorter side, as
  // {x1, y1, x2, y2, width}: a flush wall of these is the same solid.
  std::array<double, 5> centre_line() const;
};

// An upright cylinder standing on the floor, radius_m round its centre (the course's
// landmarks, in a world file or placed by a supervisor): as solid as an obstacle, and on no
// lattice either. A landmark's height and colour (red, green, blue in [0, 1]) come with it.
struct ArenaDisc {
  double centre_x_m = 0.0;
  double centre_y_m = 0.0;
  double radius_m = 0.0;
  struct Look {
    double height_m = 0.0;
    double red = 1.0, green = 1.0, blue = 1.0;
  };
  std::optional<Look> landmark = std::nullopt;  // a landmark's (a file's <landmark>, a maze's landmarks)
  // Its top above the floor: a landmark's height, else kTallerThanEverySensor_m.
  double top_m() const { return landmark ? landmark->height_m : kTallerThanEverySensor_m; }
};

struct Arena {
  std::string name;    // from the file ("name ..."), or its file name
  std::string source;  // the file it was read from ("" when built in code)
  double x_min_m = 0.0;
  double x_max_m = 0.0;
  double y_min_m = 0.0;
  double y_max_m = 0.0;
  common::SourceLocation boundary_where;
  std::vector<Obstacle> obstacles;
  std::vector<ArenaDisc> discs;  // the course XML's landmarks, a maze's, a supervisor's cylinders
  std::vector<ArenaPose> starts;  // the first is the start; may be empty (then the caller's)
  std::vector<common::SourceLocation> start_where;  // one per start
  std::vector<ArenaPoint> goals;
  std::vector<common::SourceLocation> goal_where;  // one per goal
  // Whether the boundary is walled (a RectangleArena's walls, taller than every sensor: a beam
  // stops at it, the body stays inside), or the open edge of a Webots Floor (a beam past it
  // meets nothing and reads +infinity; the body may leave, and a run says so).
  bool boundary_walled = true;

  double width_m() const { return x_max_m - x_min_m; }
  double height_m() const { return y_max_m - y_min_m; }
  bool inside_boundary(double x_m, double y_m) const {
    return x_m >= x_min_m && x_m <= x_max_m && y_m >= y_min_m && y_m <= y_max_m;
  }
  // The start pose: the first start, else the boundary's centre facing north.
  ArenaPose start() const;
};

// The solids whose top is above z_m (a beam at that height meets exactly these), the rest of
// the arena as it is; whether every solid's top is above z_m (then it is the arena itself).
Arena solids_above(const Arena &arena, double z_m);
bool every_solid_above(const Arena &arena, double z_m);

// The course's floor (a Webots RectangleArena of 17 x 17 m centred on the origin): an arena
// whose file gives no boundary is bounded by it.
inline constexpr double kCourseFloorSide_m = 17.0;
// The course's empty floor (a Webots Floor: kCourseFloorSide_m square centred on the origin,
// its edge open) with nothing on it; the robot at the origin facing north, where a
// supervisor's load_environment begins.
Arena course_empty_floor();
// Limits: obstacles per arena, and the boundary's longer side.
inline constexpr std::size_t kMaxObstacles = 10000;
inline constexpr double kMaxArenaSide_m = 1000.0;

// ---- named checks (each a located error, or nothing) ----
using ArenaCheck = std::optional<common::InputError>;
// Every number finite: "obstacle 3 has a non-finite coordinate", at it.
ArenaCheck check_arena_finite(const Arena &arena);
// "the boundary x 2 to 1 m, y 0 to 3 m is empty: XS < XE and YS < YE", at the boundary.
ArenaCheck check_arena_boundary(const Arena &arena);
// "12000 obstacles: an arena holds at most 10000" / "the boundary spans 2000 x 3 m: ...".
ArenaCheck check_arena_size(const Arena &arena);
// "start (9, 1) is outside the boundary x 0 to 5 m, y 0 to 3 m", at the start.
ArenaCheck check_starts_inside(const Arena &arena);
// "goal (9, 1) is outside the boundary ...", at the goal.
ArenaCheck check_goals_inside(const Arena &arena);
// "start (1, 1) is inside the obstacle at line 4" / "a robot of radius 0.1 m at start (1, 1)
// touches the obstacle at line 4" / "... touches the boundary", at the start. Radius 0 checks
// the point alone.
ArenaCheck check_starts_clear(const Arena &arena, double robot_radius_m);

// Runs the checks above in that order (the clearance one with robot_radius_m) and throws
// the first failure as common::InputError.
void validate_arena(const Arena &arena, double robot_radius_m = 0.0);

}  // namespace maze
