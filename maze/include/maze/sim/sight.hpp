#pragma once
// Heights along a line through a world's solids (maze/world/geometry.hpp): what a camera's
// column of pixels shows, and whether a camera sees a recognisable object, as Webots decides.
// Both test every solid of the arena (O(solids) a call): the camera asks a few hundred times
// an image, the lidar never (it casts on SolidGeometry, with the solids below its plane left
// out: maze::solids_above).
//
// Webots' Recognition with occlusion TRUE (its default; src/webots/nodes/WbCamera.cpp and
// utils/WbObjectDetection.cpp): one ray from the camera to the object's position (the
// Solid's origin, a landmark's centre), collided with every other solid; each solid it
// enters reports the distance from that entry to the object's position, and the object is
// occluded when the largest of those exceeds half the object's size along the camera's axis
// (a cylinder's radius seen level). The ray is 3-D: it enters a solid only where it passes
// below the solid's top (and above the floor).

#include <optional>
#include <vector>

#include "maze/sim/profile.hpp"
#include "maze/sim/solid_geometry.hpp"
#include "maze/world/geometry.hpp"
#include "maze/world/maze.hpp"

namespace maze::sim {

// A solid a horizontal ray enters: the distance to its entry (0 from inside), its top above
// the floor, and which disc it is (an index into Arena::discs; -1: an obstacle or the
// boundary, whose top is kTallerThanEverySensor_m).
struct SolidHit {
  double distance_m;
  double top_m;
  int disc;
};

// Every solid the ray from (x, y) along angle_rad enters within max_range_m, nearest first,
// a walled boundary's exit among them.
std::vector<SolidHit> hits_along(const Arena &arena, double x_m, double y_m, double angle_rad, double max_range_m);

struct Point3 {
  double x_m, y_m, z_m;
};

// Webots' occlusion test (above) of an object at `to` seen from `from`: whether a solid other
// than the disc target_disc (-1: none left out) is entered farther than half_depth_m from
// `to` along the segment.
bool sight_blocked(const Arena &arena, const Point3 &from, const Point3 &to, double half_depth_m, int target_disc);

// Per lidar of a profile, the solids above its beam plane when some solid of the world is
// no taller than the plane (a lattice's walls: when their height is), else none: the lidar
// casts on the world's own solids (its wall grid, or its SolidGeometry), the fast case.
class LidarPlanes {
 public:
  // For the world's solids now (geometry, else the lattice's walls) and the robot's origin
  // robot_z_m above the floor. O(solids) for each lidar whose plane some solid is below.
  void place(const Arena *geometry, const Maze *lattice, const RobotProfile &profile, double robot_z_m);
  // The solids lidar (the profile's index) meets, or null: the world's own.
  const SolidGeometry *of(int lidar) const {
    const auto i = static_cast<std::size_t>(lidar);
    return i < planes_.size() && planes_[i] ? &*planes_[i] : nullptr;
  }

 private:
  std::vector<std::optional<SolidGeometry>> planes_;
};

}  // namespace maze::sim
