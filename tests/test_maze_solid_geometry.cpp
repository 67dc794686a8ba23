// The simulator's geometry for arenas (SolidGeometry) against hand-computed distances,
// normals and contacts, against its own brute force on random arenas, and the embedded
// simulation's devices and collisions in an arena.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>
#include <webots/DistanceSensor.hpp>
#include <webots/GPS.hpp>
#include <webots/InertialUnit.hpp>
#include <webots/Lidar.hpp>
#include <webots/Motor.hpp>
#include <webots/PositionSensor.hpp>
#include <webots/Robot.hpp>
#include <webots/TouchSensor.hpp>

#include "common/error.hpp"
#include "common/random.hpp"
#include "maze/world/geometry.hpp"
#include "maze/generate/solids_generator.hpp"
#include "maze/formats/solids_format.hpp"
#include "maze/sim/solid_geometry.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/sim/simulation.hpp"
#include "test_values.hpp"

namespace {

const double kRoot2 = std::sqrt(2.0);

// 10 x 10 m, a 2 m box at (4..6, 4..6) and a 2 m square turned 45 degrees about (5, 8.5)...
// kept apart: the diamond's corners are at (5 +- sqrt 2, 8.5) and (5, 8.5 +- sqrt 2).
maze::Arena two_obstacles() {
  maze::Arena a = maze::read_room("boundary 0 10 0 10\nrect 4 4 6 6\nstart 1 1 0\n", "f");
  a.obstacles.push_back(maze::Obstacle::oriented(5, 8.5, 1, 1, kPi / 4));
  maze::validate_arena(a, 0.1);
  return a;
}

struct Hit {
  double t, nx, ny;
};

Hit cast(const maze::sim::SolidGeometry &g, double x, double y, double angle) {
  Hit h{0, 0, 0};
  h.t = g.cast_from(g.cast_origin(x, y), std::cos(angle), std::sin(angle), 50.0, &h.nx, &h.ny);
  return h;
}

const maze::sim::RobotProfile &test_robot() {
  static const maze::sim::RobotProfile p = [] {
    maze::sim::RobotProfile r = maze::sim::default_profile();
    r.lidars[0] = {"lidar", 360, 2.0 * kPi, 0.05, 12.0, 0.000833, 0.0, 0.0};
    r.bumpers = maze::sim::find_profile("bumper-depth").bumpers;
    return r;
  }();
  return p;
}

maze::sim::SimulationOptions at(double x, double y, double yaw) {
  maze::sim::SimulationOptions o;
  o.noise = 0.0;
  o.start = maze::sim::Pose{x, y, yaw};
  return o;
}

}  // namespace

TEST_CASE("arena geometry: casts meet boxes, rotated rectangles and the boundary where drawn") {
  const maze::sim::SolidGeometry g(two_obstacles());
  // East from (1, 5): the box's west face at x = 4.
  Hit h = cast(g, 1, 5, 0);
  CHECK(h.t == 3.0);
  CHECK(h.nx == -1.0);
  CHECK(h.ny == 0.0);
  // West from (1, 5): the boundary at x = 0, its inward normal.
  h = cast(g, 1, 5, kPi);
  CHECK(h.t == doctest::Approx(1.0));
  CHECK(h.nx == 1.0);
  // North from (5, 1): the box's south face.
  h = cast(g, 5, 1, kPi / 2);
  CHECK(h.t == doctest::Approx(3.0));
  CHECK(h.ny == doctest::Approx(-1.0));
  // East along y = 9 from (1, 9): the diamond's upper-left face, y = x - 5 + 8.5 + sqrt 2, at
  // x = 5.5 - sqrt 2; its outward normal (-1, 1) / sqrt 2.
  h = cast(g, 1, 9, 0);
  CHECK(h.t == doctest::Approx(4.5 - kRoot2));
  CHECK(h.nx == doctest::Approx(-1 / kRoot2));
  CHECK(h.ny == doctest::Approx(1 / kRoot2));
  // Diagonally up from (1, 1) at 45 degrees: the box's corner (4, 4), 3 sqrt 2 away.
  CHECK(cast(g, 1, 1, kPi / 4).t == doctest::Approx(3 * kRoot2));
  // Beyond the range: infinity; outside the boundary: infinity; inside an obstacle: 0.
  CHECK(g.cast(1, 5, 0, 2.5) == kInf);
  CHECK(g.cast(-1, 5, 0, 50) == kInf);
  CHECK(g.cast(5, 5, 0, 50) == 0.0);
  CHECK(g.inside_solid(5, 5));
  CHECK(g.inside_solid(4, 4));  // closed
  CHECK(g.inside_solid(5, 8.5 + kRoot2 - 1e-9));
  CHECK(!g.inside_solid(5.8, 9.3));  // beside the diamond's corner, inside its bounding box
  CHECK(g.inside_solid(10.5, 5));    // outside the boundary
}

TEST_CASE("arena geometry: contacts and push-out, along the contact normal") {
  const maze::sim::SolidGeometry g(two_obstacles());
  // A disc of 0.1 m at (3.9, 5) touches the box's west face at (4, 5).
  const std::vector<maze::sim::Contact> touching = g.contacts(3.9, 5, 0.1 + 1e-6);
  REQUIRE(touching.size() == 1);
  CHECK(touching[0].x_m == 4.0);
  CHECK(touching[0].y_m == 5.0);
  CHECK(touching[0].distance_m == doctest::Approx(0.1));
  // Overlapping by 0.05: pushed straight back west.
  double x = 3.95, y = 5.0;
  CHECK(g.push_out(x, y, 0.1));
  CHECK(x == doctest::Approx(3.9));
  CHECK(y == 5.0);
  // Against the diamond's west corner (5 - sqrt 2, 8.5): away from the corner.
  x = 5 - kRoot2 - 0.05;
  y = 8.5;
  CHECK(g.push_out(x, y, 0.1));
  CHECK(x == doctest::Approx(5 - kRoot2 - 0.1));
  CHECK(y == doctest::Approx(8.5));
  // Into the boundary's corner: back inside by the radius on both sides.
  x = 0.02;
  y = 9.97;
  CHECK(g.push_out(x, y, 0.1));
  CHECK(x == doctest::Approx(0.1));
  CHECK(y == doctest::Approx(9.9));
  // Far from everything: not moved, and a box of free centres holds it.
  x = 2;
  y = 2;
  CHECK(!g.push_out(x, y, 0.1));
  const auto free = g.free_centres(2, 2, 0.1);
  REQUIRE(free.has_value());
  CHECK(free->strictly_contains(2, 2));
  CHECK(!g.free_centres(4.9, 4.9, 0.1).has_value());  // its bucket lists the box
  // The boundary's sides are contacts too.
  CHECK(g.contacts(0.05, 5, 0.1).size() == 1);
}

TEST_CASE("arena geometry: the bucket walk gives the brute force's answers on random arenas") {
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    maze::ArenaGeneration gen;
    gen.seed = seed;
    gen.width_m = 12;
    gen.height_m = 9;
    gen.obstacles = 30;
    gen.rotated = seed % 2 == 0;
    const maze::sim::SolidGeometry g(maze::generate_arena(gen));
    common::Rng rng(seed);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
      const double x = rng.uniform(0, 12);
      const double y = rng.uniform(0, 9);
      const double a = rng.uniform(-kPi, kPi);
      const double range = rng.uniform(0.5, 20);
      const double dx = std::cos(a);
      const double dy = std::sin(a);
      const double walked = g.cast_direction(x, y, dx, dy, range);
      const double brute = g.cast_brute_force(x, y, dx, dy, range);
      if (walked != brute) {
        CAPTURE(seed);
        CAPTURE(i);
        CHECK(walked == brute);
      }
      hits += std::isfinite(walked) ? 1 : 0;
    }
    CHECK(hits > 1000);
    // Along the axes too (no bucket step in one direction).
    for (int i = 0; i < 200; ++i) {
      const double x = rng.uniform(0, 12);
      const double y = rng.uniform(0, 9);
      for (const std::pair<double, double> &d : {std::pair{1.0, 0.0}, std::pair{-1.0, 0.0}, std::pair{0.0, 1.0},
                                                std::pair{0.0, -1.0}}) {
        CHECK(g.cast_direction(x, y, d.first, d.second, 30) == g.cast_brute_force(x, y, d.first, d.second, 30));
      }
    }
  }
}

TEST_CASE("Simulation in an arena: lidar, GPS, IMU, bumpers, distance sensors and collisions") {
  const maze::Arena arena = two_obstacles();
  // Facing east at (3, 5): the box's face 1 m ahead, the boundary 3 m behind.
  webots::embedded::Simulation sim(maze::world_of(arena), test_robot(), at(3, 5, 0));
  CHECK(sim.on_solid_geometry());
  webots::Robot &robot = sim.robot();
  webots::Lidar *lidar = robot.getLidar("lidar");
  REQUIRE(lidar != nullptr);
  lidar->enable(32);
  robot.step(32);
  const float *image = lidar->getRangeImage();
  REQUIRE(image != nullptr);
  // Beam 180 of a fixed 360-beam lidar looks half a beam right of ahead: the face at x = 4.
  CHECK(image[180] == doctest::Approx(1.0 / std::cos(0.5 * kPi / 180)).epsilon(1e-6));
  CHECK(image[0] == doctest::Approx(3.0 / std::cos(0.5 * kPi / 180)).epsilon(1e-6));
  webots::GPS *gps = robot.getGPS("gps");
  gps->enable(32);
  webots::InertialUnit *imu = robot.getInertialUnit("imu");
  imu->enable(32);
  robot.step(32);
  CHECK(gps->getValues()[0] == 3.0);
  CHECK(imu->getRollPitchYaw()[2] == 0.0);

  // Drive east into the box: stopped with the body against its face, the front bumper pressed.
  webots::TouchSensor *front = robot.getTouchSensor("bumper front");
  REQUIRE(front != nullptr);
  front->enable(32);
  webots::Motor *l = robot.getMotor("left motor");
  webots::Motor *r = robot.getMotor("right motor");
  l->setPosition(kInf);
  r->setPosition(kInf);
  l->setVelocity(5);
  r->setVelocity(5);
  for (int i = 0; i < 200; ++i) robot.step(32);
  const double radius = test_robot().body_radius_m;
  CHECK(sim.pose().x_m == doctest::Approx(4 - radius).epsilon(1e-9));
  CHECK(sim.pose().y_m == doctest::Approx(5).epsilon(1e-9));
  CHECK(front->getValue() == 1.0);
  CHECK(sim.collisions() == 1);  // pressing on against the face is the same collision
  webots::PositionSensor *encoder = robot.getPositionSensor("left wheel encoder");
  encoder->enable(32);
  robot.step(32);
  CHECK(encoder->getValue() > 6.0);  // the wheels turned on against the box (they slip)

  // The start is checked: inside an obstacle, or the body overlapping one.
  CHECK_THROWS_WITH_AS(webots::embedded::Simulation(maze::world_of(arena), test_robot(), at(5, 5, 0)),
                       "pose (5, 5) is inside an obstacle", common::InputError);
  CHECK_THROWS_WITH_AS(webots::embedded::Simulation(maze::world_of(arena), test_robot(), at(3.95, 5, 0)),
                       doctest::Contains("overlaps an obstacle at (3.95, 5)"), common::InputError);
}

TEST_CASE("Simulation in an arena: distance sensors read what sensor_distance_m computes, by type") {
  const maze::Arena arena = two_obstacles();
  for (const char *name : {"ir-ring", "sonar-ring"}) {
    CAPTURE(name);
    const maze::sim::RobotProfile &profile = maze::sim::find_profile(name);
    webots::embedded::Simulation sim(maze::world_of(arena), profile, at(3.5, 5, 0));
    const maze::sim::SolidGeometry solids(arena);
    for (const maze::sim::DistanceSensorSpec &spec : profile.distance_sensors) {
      webots::DistanceSensor *d = sim.robot().getDistanceSensor(spec.name);
      REQUIRE(d != nullptr);
      d->enable(32);
    }
    sim.robot().step(32);
    const maze::sim::Pose pose{3.5, 5, 0};
    const maze::sim::DistanceSensorSpec &ahead = profile.distance_sensors.front();
    // The sensor ahead sees the box 0.5 m off the centre, less the body's radius.
    const double distance = maze::sim::sensor_distance_m(solids, ahead, profile.body_radius_m, pose);
    CHECK(distance == doctest::Approx(0.5 - profile.body_radius_m).epsilon(1e-3));
    const double value = sim.robot().getDistanceSensor(ahead.name)->getValue();
    CHECK(value == doctest::Approx(maze::sim::lookup_value(ahead.lookup_table, distance)).epsilon(0.3));
  }
}

TEST_CASE("Simulation in an arena: a rotating lidar sweeps the arena's solids") {
  // hambot-2025's rotating 3 m lidar at 12 Hz: after a revolution at rest every beam is swept.
  const maze::sim::RobotProfile &profile = maze::sim::find_profile("hambot-2025");
  webots::embedded::Simulation sim(maze::world_of(two_obstacles()), profile, at(3, 5, 0));
  webots::Lidar *lidar = sim.robot().getLidar(profile.lidars.front().name);
  REQUIRE(lidar != nullptr);
  lidar->enable(32);
  for (int i = 0; i < 4; ++i) sim.robot().step(32);
  const float *image = lidar->getRangeImage();
  REQUIRE(image != nullptr);
  // A rotating lidar's beam 180 of 360 looks straight ahead: the box's face 1 m away.
  const int n = profile.lidars.front().horizontal_resolution;
  CHECK(image[n / 2] == doctest::Approx(1.0).epsilon(0.02));
  // Beam 0 looks back: the boundary 3 m behind, out of its 3 m range or at it.
  CHECK((std::isinf(image[0]) || image[0] == doctest::Approx(3.0).epsilon(0.02)));
}

TEST_CASE("arena geometry: a disc meets rays on its circle, holds bodies out and agrees with the brute force") {
  maze::Arena a = maze::read_room("boundary 0 10 0 10\nstart 1 1 0\n", "f");
  a.discs.push_back({5, 5, 0.25});
  const maze::sim::SolidGeometry g(a);
  // East from (1, 5): the circle at x = 4.75, its outward normal (-1, 0).
  Hit h = cast(g, 1, 5, 0);
  CHECK(h.t == doctest::Approx(3.75));
  CHECK(h.nx == doctest::Approx(-1.0));
  CHECK(h.ny == doctest::Approx(0.0));
  // East along y = 5.2: the chord's near end, x = 5 - sqrt(0.25^2 - 0.2^2) = 4.85.
  CHECK(cast(g, 1, 5.2, 0).t == doctest::Approx(3.85));
  // Along y = 5.3 the ray passes it: the boundary at x = 10. From inside: 0.
  CHECK(cast(g, 1, 5.3, 0).t == doctest::Approx(9.0));
  CHECK(g.cast(5.1, 5, 0, 50) == 0.0);
  CHECK(g.inside_solid(5.17, 5.17));
  CHECK(!g.inside_solid(5.18, 5.18));  // inside its bounding box, outside the circle
  // A body of 0.1 m at (5.3, 5) is pushed out along the radius to 0.35 m from the centre.
  double x = 5.3;
  double y = 5.0;
  CHECK(g.push_out(x, y, 0.1));
  CHECK(x == doctest::Approx(5.35));
  CHECK(y == doctest::Approx(5.0));
  const std::vector<maze::sim::Contact> touching = g.contacts(5.35, 5, 0.1 + 1e-6);
  REQUIRE(touching.size() == 1);
  CHECK(touching[0].x_m == doctest::Approx(5.25));
  common::Rng rng(7);
  for (int i = 0; i < 2000; ++i) {
    const double ox = rng.uniform(0.5, 9.5);
    const double oy = rng.uniform(0.5, 9.5);
    const double angle = rng.uniform(-kPi, kPi);
    CAPTURE(ox);
    CAPTURE(oy);
    CAPTURE(angle);
    CHECK(g.cast(ox, oy, angle, 50) ==
          doctest::Approx(g.cast_brute_force(ox, oy, std::cos(angle), std::sin(angle), 50)).epsilon(1e-12));
  }
}

TEST_CASE("Simulation in an arena: a supervisor adds solids the sensors see at once, teleports and resets") {
  const maze::Arena arena = maze::read_room("boundary 0 10 0 10\nstart 1 5 0\n", "f");
  webots::embedded::Simulation sim(maze::world_of(arena), test_robot(), at(1, 5, 0));
  webots::Robot &robot = sim.robot();
  webots::Lidar *lidar = robot.getLidar("lidar");
  lidar->enable(32);
  robot.step(32);
  CHECK(lidar->getRangeImage()[180] == doctest::Approx(9.0 / std::cos(0.5 * kPi / 180)).epsilon(1e-6));
  sim.add_disc({5, 5, 0.25});
  sim.add_obstacle(maze::Obstacle::oriented(1, 7, 1, 0.006, 0));  // a wall along y = 7
  // Read in the same step: the new solids are there at once.
  CHECK(lidar->getRangeImage()[180] == doctest::Approx(3.75).epsilon(1e-3));
  CHECK(lidar->getRangeImage()[90] == doctest::Approx(2.0 - 0.006).epsilon(1e-3));
  webots::GPS *gps = robot.getGPS("gps");
  gps->enable(32);
  sim.teleport({8, 2, kPi / 2}, 0.02);
  CHECK(gps->getValues()[0] == 8.0);
  CHECK(gps->getValues()[2] == 0.02);
  CHECK(sim.pose().yaw_rad == doctest::Approx(kPi / 2));
  sim.reset_world();
  CHECK(sim.pose().x_m == 1.0);
  CHECK(gps->getValues()[2] == 0.0);
  CHECK(lidar->getRangeImage()[180] == doctest::Approx(9.0 / std::cos(0.5 * kPi / 180)).epsilon(1e-6));
  CHECK_THROWS_WITH_AS(sim.add_disc({kInf, 5, 0.25}), "a cylinder's x must be finite (got inf)", common::InputError);
}

TEST_CASE("Simulation: a supervisor's reset puts the time back at 0 and the time limit still counts the whole run") {
  const maze::Arena arena = maze::read_room("boundary 0 10 0 10\nstart 1 5 0\n", "f");
  maze::sim::SimulationOptions options = at(1, 5, 0);
  options.time_limit_s = 0.32;  // ten basic steps
  webots::embedded::Simulation sim(maze::world_of(arena), test_robot(), options);
  webots::Robot &robot = sim.robot();
  webots::PositionSensor *encoder = robot.getPositionSensor(test_robot().left_encoder);
  encoder->enable(32);
  webots::Motor *left = robot.getMotor(test_robot().left_motor);
  left->setPosition(INFINITY);
  left->setVelocity(5.0);
  for (int i = 0; i < 6; ++i) REQUIRE(robot.step(32) == 0);
  CHECK(robot.getTime() == doctest::Approx(0.192));
  CHECK(encoder->getValue() > 0.5);
  sim.reset_world();
  CHECK(robot.getTime() == 0.0);
  CHECK(sim.steps() == 6);
  CHECK(encoder->getValue() == 0.0);
  for (int i = 0; i < 3; ++i) REQUIRE(robot.step(32) == 0);
  CHECK(robot.getTime() == doctest::Approx(0.096));
  CHECK(robot.step(32) == -1);  // the tenth step of the run
}

TEST_CASE("Simulation in a maze: a solid added is seen at once, and gone after a reset") {
  maze::Maze m(2, 2);  // 1 m cells, no inner wall: east of the start's centre the outer wall at 2 m
  webots::embedded::Simulation sim(maze::world_of(m), test_robot(), {});
  const double to_wall_m = 1.5 - maze::kDefaultWallThickness_m / 2;
  CHECK(sim.cast(0.5, 0.5, 0.0, 10.0) == doctest::Approx(to_wall_m));
  CHECK_FALSE(sim.on_solid_geometry());
  sim.add_disc({1.5, 0.5, 0.1});
  CHECK(sim.on_solid_geometry());  // the maze's geometry from then on
  CHECK(sim.cast(0.5, 0.5, 0.0, 10.0) == doctest::Approx(0.9));
  CHECK(sim.cast(0.5, 0.5, 1.5707963267948966, 10.0) == doctest::Approx(to_wall_m));  // the walls as ever
  sim.reset_world();
  CHECK_FALSE(sim.on_solid_geometry());
  CHECK(sim.cast(0.5, 0.5, 0.0, 10.0) == doctest::Approx(to_wall_m));
}

TEST_CASE("Simulation in a maze: its landmarks are solid cylinders") {
  maze::Maze m(2, 2);
  m.set_landmarks({maze::Landmark{1.5, 0.5, 0.5, 1.0, 0.0, 0.0}});
  webots::embedded::Simulation sim(maze::world_of(m), test_robot(), {});
  CHECK(sim.cast(0.5, 0.5, 0.0, 10.0) == doctest::Approx(1.0 - maze::kLandmarkRadius_m));
}
