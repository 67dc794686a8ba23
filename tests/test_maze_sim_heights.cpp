// Solids with heights: the course's XML walls 0.5 m high, a lidar's beams passing over a box
// lower than its plane, Webots' occlusion test for a camera's recognition (a tall landmark
// seen over a lower wall where the line to its centre clears it), what a camera's column
// meets, and the open edge of the course's empty floor.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <webots/Lidar.hpp>
#include <webots/Robot.hpp>

#include "maze/formats/xml_format.hpp"
#include "maze/formats/xml_solids.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/sight.hpp"
#include "maze/sim/simulation.hpp"
#include "maze/sim/simulation_sight.hpp"
#include "maze/world/geometry.hpp"
#include "maze/world/world.hpp"
#include "maze/world/world_files.hpp"
#include "test_values.hpp"

namespace {

// The course's shape: a 4 x 4 m arena of 0.5 m walls (the BoundaryWall's and Obstacle's
// height) with a wall 1 m long across x = 0, and a landmark of `height_m` at (2, 0.5).
maze::Arena wall_and_landmark(double height_m) {
  maze::Arena a;
  a.x_min_m = -3;
  a.x_max_m = 3;
  a.y_min_m = -2;
  a.y_max_m = 2;
  a.boundary_walled = false;
  maze::Obstacle wall = maze::Obstacle::from_segment(0, -0.5, 0, 1.5, 0.01, maze::WallEnds::flush);
  wall.height_m = maze::kCourseWallHeight_m;
  a.obstacles.push_back(wall);
  a.discs.push_back({2, 0.5, 0.25, maze::ArenaDisc::Look{height_m, 1, 0, 0}});
  return a;
}

// A camera 0.08 m up at (x, 0.5), the landmark's centre half its height up.
bool hidden_from(const maze::Arena &a, double camera_x_m, double height_m) {
  return maze::sim::sight_blocked(a, {camera_x_m, 0.5, 0.08}, {2, 0.5, height_m / 2}, 0.25, 0);
}

maze::sim::SimulationOptions start_at(double x, double y, double yaw) {
  maze::sim::SimulationOptions o;
  o.noise = 0.0;
  o.start = maze::sim::Pose{x, y, yaw};
  return o;
}

// Beam 180 of the HamBot's fixed lidar (half a beam right of ahead) after one step.
double beam_ahead_m(webots::embedded::Simulation &sim) {
  webots::Lidar *lidar = sim.robot().getLidar("lidar");
  lidar->enable(32);
  sim.robot().step(32);
  return lidar->getRangeImage()[180];
}

}  // namespace

TEST_CASE("Heights: the course's XML walls are 0.5 m high, read as an arena or as a lattice; other formats state none") {
  const std::string arena_xml = "<world><wall x1=\"0\" y1=\"0\" x2=\"2\" y2=\"0\"/>"
                                "<landmark x=\"1\" y=\"1\" height=\"4.5\" red=\"1\" green=\"0\" blue=\"0\"/></world>";
  const maze::Arena arena = maze::read_xml_arena(arena_xml, "a.xml").arena;
  CHECK(arena.obstacles.front().height_m == maze::kCourseWallHeight_m);
  CHECK(arena.discs.front().top_m() == 4.5);
  const maze::World grid = maze::load_world_text("o---o---o\n| S   G |\no---o---o\n", "m.txt");
  CHECK(grid.maze().wall_height_m() == kInf);
  CHECK(maze::arena_from_maze(grid.maze()).obstacles.front().height_m == kInf);
  CHECK(maze::arena_from_maze(grid.maze()).boundary_walled);
}

TEST_CASE("Heights: a 4.5 m landmark behind a 0.5 m wall is seen where the line to its centre clears the wall's top") {
  const maze::Arena a = wall_and_landmark(4.5);
  // From x = -d the line to (2, 0.5, 2.25) crosses x = 0 at 0.08 + 2.17 d / (d + 2) m: above
  // 0.5 m from d = 0.48 m on.
  CHECK_FALSE(hidden_from(a, -1.0, 4.5));  // 0.80 m at the wall
  CHECK_FALSE(hidden_from(a, -0.6, 4.5));  // 0.58 m
  CHECK(hidden_from(a, -0.4, 4.5));        // 0.44 m: the wall hides its centre
  CHECK(hidden_from(a, -0.1, 4.5));
  // In front of the wall nothing is between.
  CHECK_FALSE(hidden_from(a, 1.0, 4.5));
}

TEST_CASE("Heights: a landmark lower than the wall is hidden behind it from anywhere") {
  const maze::Arena a = wall_and_landmark(0.4);
  for (const double x : {-2.5, -1.0, -0.2}) {
    CAPTURE(x);
    CHECK(hidden_from(a, x, 0.4));
  }
}

TEST_CASE("Heights: Webots' occlusion leaves out an entry within half the object's depth of its centre") {
  // A second cylinder touching the target on the camera's side: entered 0.3 m before the
  // target's centre along the ray (more than its radius 0.25): occluded; a thin plate 0.2 m
  // before the centre (inside the radius): not.
  maze::Arena a = wall_and_landmark(4.5);
  a.obstacles.clear();
  maze::Arena plate = a;
  maze::Obstacle thin = maze::Obstacle::from_segment(1.8, 0, 1.8, 1, 0.001, maze::WallEnds::flush);
  plate.obstacles.push_back(thin);
  CHECK_FALSE(maze::sim::sight_blocked(plate, {0, 0.5, 2.25}, {2, 0.5, 2.25}, 0.25, 0));
  thin.centre_x_m = 1.7;
  plate.obstacles.back() = thin;
  CHECK(maze::sim::sight_blocked(plate, {0, 0.5, 2.25}, {2, 0.5, 2.25}, 0.25, 0));
}

TEST_CASE("Heights: a column's hits come nearest first with their tops, a walled boundary last") {
  maze::Arena a = wall_and_landmark(4.5);
  a.boundary_walled = true;
  const auto hits = maze::sim::hits_along(a, -1, 0.5, 0, 10);
  REQUIRE(hits.size() == 3);
  CHECK(hits[0].distance_m == doctest::Approx(0.995));
  CHECK(hits[0].top_m == 0.5);
  CHECK(hits[0].disc == -1);
  CHECK(hits[1].distance_m == doctest::Approx(2.75));
  CHECK(hits[1].top_m == 4.5);
  CHECK(hits[1].disc == 0);
  CHECK(hits[2].distance_m == doctest::Approx(4.0));
  CHECK(hits[2].top_m == kInf);
  a.boundary_walled = false;
  CHECK(maze::sim::hits_along(a, -1, 0.5, 0, 10).size() == 2);
}

TEST_CASE("Heights: the lidar at its height passes over a box lower than it and meets a taller one") {
  const maze::sim::RobotProfile &hambot = maze::sim::find_profile("hambot");
  REQUIRE(hambot.lidars.front().height_m == doctest::Approx(0.13));
  maze::Arena a;
  a.x_min_m = 0;
  a.x_max_m = 10;
  a.y_min_m = 0;
  a.y_max_m = 10;
  maze::Obstacle box = maze::Obstacle::from_box(4, 4, 6, 6);
  box.height_m = 0.1;
  a.obstacles.push_back(box);
  const double slant = 1.0 / std::cos(0.5 * kPi / 180);
  {
    webots::embedded::Simulation sim(maze::world_of(a), hambot, start_at(3, 5, 0));
    CHECK(beam_ahead_m(sim) == doctest::Approx(7.0 * slant).epsilon(1e-3));  // over the box to the boundary
    sim.teleport({3, 5, 0}, -0.05);  // the plane now at 0.08 m: below the box's top
    CHECK(beam_ahead_m(sim) == doctest::Approx(1.0 * slant).epsilon(1e-3));
  }
  a.obstacles.front().height_m = 0.2;
  webots::embedded::Simulation sim(maze::world_of(a), hambot, start_at(3, 5, 0));
  CHECK(beam_ahead_m(sim) == doctest::Approx(1.0 * slant).epsilon(1e-3));
}

TEST_CASE("Heights: the simulation's camera queries see the world's solids with their tops") {
  webots::embedded::Simulation sim(maze::world_of(wall_and_landmark(4.5)), maze::sim::default_profile(),
                                   start_at(-1, 0, kPi / 2));
  CHECK_FALSE(webots::embedded::sight_blocked(sim, {-1.0, 0.5, 0.08}, {2, 0.5, 2.25}, 0.25));
  CHECK(webots::embedded::sight_blocked(sim, {-0.4, 0.5, 0.08}, {2, 0.5, 2.25}, 0.25));
  const auto hits = webots::embedded::hits_along(sim, -1, 0.5, 0, 10);
  REQUIRE(hits.size() == 2);
  CHECK(hits[1].top_m == 4.5);
}

TEST_CASE("The course's empty floor: no wall at its edge, beams past it read inf, a robot past it is off the floor") {
  webots::embedded::Simulation sim(maze::world_of(maze::course_empty_floor()), maze::sim::default_profile(),
                                   start_at(0, 0, 0));
  webots::Lidar *lidar = sim.robot().getLidar("lidar");
  lidar->enable(32);
  sim.robot().step(32);
  for (int i = 0; i < 360; i += 45) CHECK(std::isinf(lidar->getRangeImage()[i]));
  CHECK_FALSE(webots::embedded::off_floor(sim));
  sim.teleport({8.6, 0, 0}, 0);
  CHECK(webots::embedded::off_floor(sim));
  CHECK(webots::embedded::hits_along(sim, 0, 0, 0, 100).empty());
}
