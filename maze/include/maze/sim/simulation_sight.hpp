#pragma once
// What a camera sees in a simulation's world, heights included (maze/sim/sight.hpp): for the
// composition roots' camera (python/maze_mapper/camera.py), never a robot-side controller.

#include <vector>

#include "maze/sim/sight.hpp"
#include "maze/sim/simulation.hpp"

namespace webots::embedded {

// Every solid the ray from (x, y) along angle_rad enters within max_range_m, nearest first,
// with its top: the world's solids now (a lattice's walls on its wall grid: the first one, as
// high as Maze::wall_height_m()).
std::vector<maze::sim::SolidHit> hits_along(const Simulation &simulation, double x_m, double y_m, double angle_rad,
                                            double max_range_m);

// Webots' Recognition occlusion test (maze::sim::sight_blocked) of an object at `to` seen from
// `from`; the cylinder standing at (to.x, to.y), if one does, is the object itself.
bool sight_blocked(const Simulation &simulation, const maze::sim::Point3 &from, const maze::sim::Point3 &to,
                   double half_depth_m);

// Whether the robot's centre has left an open floor (Arena::boundary_walled false): in Webots
// it would fall off the Floor's edge.
bool off_floor(const Simulation &simulation);

}  // namespace webots::embedded
