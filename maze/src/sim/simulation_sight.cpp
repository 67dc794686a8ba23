// What a camera sees in a simulation's world (maze/sim/simulation_sight.hpp).

#include "maze/sim/simulation_sight.hpp"

#include <cmath>
#include <cstddef>

#include "maze/world/world_files.hpp"

namespace webots::embedded {

std::vector<maze::sim::SolidHit> hits_along(const Simulation &simulation, double x_m, double y_m, double angle_rad,
                                            double max_range_m) {
  if (const maze::Arena *geometry = simulation.geometry()) {
    return maze::sim::hits_along(*geometry, x_m, y_m, angle_rad, max_range_m);
  }
  const double distance_m = simulation.walls().cast(x_m, y_m, angle_rad, max_range_m);
  if (!std::isfinite(distance_m)) return {};
  return {{distance_m, simulation.lattice()->wall_height_m(), -1}};
}

bool sight_blocked(const Simulation &simulation, const maze::sim::Point3 &from, const maze::sim::Point3 &to,
                   double half_depth_m) {
  const maze::Arena *geometry = simulation.geometry();
  const maze::Arena walls = geometry != nullptr ? maze::Arena{} : maze::arena_from_maze(*simulation.lattice());
  const maze::Arena &arena = geometry != nullptr ? *geometry : walls;
  int target = -1;
  for (std::size_t i = 0; i < arena.discs.size(); ++i) {
    const maze::ArenaDisc &d = arena.discs[i];
    if (std::hypot(d.centre_x_m - to.x_m, d.centre_y_m - to.y_m) <= 1e-9) target = static_cast<int>(i);
  }
  return maze::sim::sight_blocked(arena, from, to, half_depth_m, target);
}

bool off_floor(const Simulation &simulation) {
  const maze::Arena *geometry = simulation.geometry();
  const maze::sim::Pose &pose = simulation.pose();
  return geometry != nullptr && !geometry->boundary_walled && !geometry->inside_boundary(pose.x_m, pose.y_m);
}

}  // namespace webots::embedded
