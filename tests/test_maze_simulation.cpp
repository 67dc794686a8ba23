#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>
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
#include "maze/world/maze.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/sim/simulation.hpp"
#include "test_values.hpp"

namespace {

using webots::embedded::Simulation;

maze::sim::SimulationOptions exact() {
  maze::sim::SimulationOptions o;
  o.noise = 0.0;
  return o;
}

maze::sim::SimulationOptions at(double x, double y, double yaw) {
  maze::sim::SimulationOptions o = exact();
  o.start = maze::sim::Pose{x, y, yaw};
  return o;
}

// The simulator's test robot: hambot's body, wheels and devices with a fixed 12 m lidar that
// does not round (so ranges are the exact distances) and bumper-depth's three bumpers;
// hambot itself rounds to 1 cm (tests/test_maze_sim_fixed_lidar.cpp) and has no bumpers (the
// rotating lidar has its own tests below).
const maze::sim::RobotProfile &hambot() {
  static const maze::sim::RobotProfile p = [] {
    maze::sim::RobotProfile r = maze::sim::default_profile();
    r.lidars[0] = {"lidar", 360, 2.0 * kPi, 0.05, 12.0, 0.000833, 0.0, 0.0};
    r.bumpers = maze::sim::find_profile("bumper-depth").bumpers;
    return r;
  }();
  return p;
}

void drive(webots::Robot &robot, double left_rad_s, double right_rad_s) {
  webots::Motor *l = robot.getMotor("left motor");
  webots::Motor *r = robot.getMotor("right motor");
  REQUIRE(l != nullptr);
  REQUIRE(r != nullptr);
  l->setPosition(std::numeric_limits<double>::infinity());
  r->setPosition(std::numeric_limits<double>::infinity());
  l->setVelocity(left_rad_s);
  r->setVelocity(right_rad_s);
}

}  // namespace

TEST_CASE("Simulation: devices by name and kind, as Webots' Robot::get*") {
  Simulation sim(maze::world_of(maze::Maze(3, 3)), hambot(), exact());
  webots::Robot &robot = sim.robot();
  CHECK(robot.getBasicTimeStep() == 32.0);
  CHECK(robot.getTime() == 0.0);
  CHECK(robot.getLidar("lidar") != nullptr);
  CHECK(robot.getInertialUnit("imu") != nullptr);
  CHECK(robot.getGPS("gps") != nullptr);
  CHECK(robot.getPositionSensor("left wheel encoder") != nullptr);
  CHECK(robot.getTouchSensor("bumper left") != nullptr);
  CHECK(robot.getLidar("gps") == nullptr);  // wrong kind
  CHECK(robot.getMotor("no such motor") == nullptr);
  CHECK(robot.getDevice("gps")->getName() == "gps");
  CHECK(robot.getMotor("left motor")->getMaxVelocity() == 20.0);
}

TEST_CASE("Robot(): attaches to the current simulation, and fails without one") {
  CHECK_THROWS_AS(webots::Robot(), std::logic_error);
  Simulation sim(maze::world_of(maze::Maze(2, 2)), hambot(), exact());
  webots::embedded::CurrentSimulation current(sim);
  webots::Robot robot;
  CHECK(robot.step(64) == 0);
  CHECK(sim.time_ms() == 64);
  CHECK(sim.robot().getTime() == doctest::Approx(0.064));
}

TEST_CASE("Robot::step: no time passes for a duration of 0 or less; a partial step counts whole") {
  Simulation sim(maze::world_of(maze::Maze(2, 2)), hambot(), exact());
  webots::Robot &robot = sim.robot();
  CHECK(robot.step(0) == 0);
  CHECK(robot.step(-1) == 0);
  CHECK(robot.step(std::numeric_limits<int>::min()) == 0);
  CHECK(sim.time_ms() == 0);
  CHECK(robot.step(33) == 0);
  CHECK(sim.time_ms() == 64);
}

TEST_CASE("Simulation: a time limit past the millisecond clock is none") {
  maze::sim::SimulationOptions o = exact();
  o.time_limit_s = 1e300;
  Simulation sim(maze::world_of(maze::Maze(2, 2)), hambot(), o);
  CHECK(sim.robot().step(32) == 0);
  CHECK(sim.robot().step(32) == 0);
}

TEST_CASE("Lidar: the range image at a known pose, in the conventions' beam order") {
  // 3 x 3 open maze, robot in the middle facing north.
  Simulation sim(maze::world_of(maze::Maze(3, 3)), hambot(), at(1.5, 1.5, kPi / 2));
  webots::Lidar *lidar = sim.robot().getLidar("lidar");
  CHECK(lidar->getRangeImage() == nullptr);  // disabled
  lidar->enable(32);
  CHECK(lidar->getSamplingPeriod() == 32);
  CHECK(lidar->getHorizontalResolution() == 360);
  CHECK(lidar->getNumberOfLayers() == 1);
  CHECK(lidar->getFov() == doctest::Approx(2 * kPi));
  const float *ranges = lidar->getRangeImage();
  REQUIRE(ranges != nullptr);
  const double side = 1.5 - kHalfWall_m;
  // A fixed lidar's beam i points half a beam in: at pi - (i + 1/2) degrees from the heading.
  const double half = std::cos(0.5 * kPi / 180.0);
  CHECK(ranges[0] == doctest::Approx(side / half).epsilon(1e-6));    // back
  CHECK(ranges[90] == doctest::Approx(side / half).epsilon(1e-6));   // left
  CHECK(ranges[180] == doctest::Approx(side / half).epsilon(1e-6));  // ahead
  CHECK(ranges[270] == doctest::Approx(side / half).epsilon(1e-6));  // right
  const double corner = side / std::cos(44.5 * kPi / 180.0);         // 44.5 deg off a face
  CHECK(ranges[135] == doctest::Approx(corner).epsilon(1e-6));       // ahead-left corner
  CHECK(ranges[224] == doctest::Approx(corner).epsilon(1e-6));       // ahead-right corner
  // Every beam against the analytic distance to the square's inner faces.
  for (int i = 0; i < 360; ++i) {
    const double a = kPi / 2 + kPi - (i + 0.5) * 2 * kPi / 360;
    const double expected = side / std::max(std::abs(std::cos(a)), std::abs(std::sin(a)));
    CHECK(ranges[i] == doctest::Approx(expected).epsilon(1e-6));
  }
}

TEST_CASE("Lidar: +infinity outside [min range, max range]") {
  maze::Maze big(20, 1);
  Simulation sim(maze::world_of(big), hambot(), at(0.5, 0.5, 0.0));
  webots::Lidar *lidar = sim.robot().getLidar("lidar");
  lidar->enable(32);
  const float *ranges = lidar->getRangeImage();
  CHECK(std::isinf(ranges[180]));                               // the east end is 19.494 m away
  CHECK(ranges[0] ==
        doctest::Approx((0.5 - kHalfWall_m) / std::cos(0.5 * kPi / 180.0)).epsilon(1e-6));  // west wall behind
}

TEST_CASE("Lidar: noise has mean 0 and sigma noise x max range (10^5 samples)") {
  maze::sim::SimulationOptions o;  // hambot's own noise, 0.000833
  o.start = maze::sim::Pose{1.5, 1.5, kPi / 2};
  o.seed = 11;
  Simulation noisy(maze::world_of(maze::Maze(3, 3)), hambot(), o);
  Simulation truth(maze::world_of(maze::Maze(3, 3)), hambot(), at(1.5, 1.5, kPi / 2));
  noisy.robot().getLidar("lidar")->enable(32);
  truth.robot().getLidar("lidar")->enable(32);
  const float *exact_ranges = truth.robot().getLidar("lidar")->getRangeImage();
  double sum = 0.0, sum_sq = 0.0;
  int n = 0;
  for (int step = 0; step < 280; ++step) {
    const float *ranges = noisy.robot().getLidar("lidar")->getRangeImage();
    for (int i = 0; i < 360; ++i) {
      // A fixed lidar's noise is on the depth along its cube face's axis (Webots adds it before
      // the merge divides by the cosine): back on that axis, sigma is noise x max range.
      const double along_face = maze::sim::face_cos(maze::sim::beam_angle_rad(hambot().lidars[0], i));
      const double e = (static_cast<double>(ranges[i]) - static_cast<double>(exact_ranges[i])) * along_face;
      sum += e;
      sum_sq += e * e;
      ++n;
    }
    REQUIRE(noisy.robot().step(32) == 0);
  }
  const double sigma = 0.000833 * 12.0;
  const double mean = sum / n;
  const double sd = std::sqrt(sum_sq / n - mean * mean);
  CHECK(n >= 100000);
  CHECK(std::abs(mean) < 0.03 * sigma);
  CHECK(std::abs(sd / sigma - 1.0) < 0.03);
}

TEST_CASE("Lidar: the same seed gives the same bytes, however often it is read") {
  const auto run = [](std::uint64_t seed, bool read_every_step) {
    maze::sim::SimulationOptions o;
    o.seed = seed;
    Simulation sim(maze::world_of(maze::Maze(4, 4)), hambot(), o);
    webots::Lidar *lidar = sim.robot().getLidar("lidar");
    lidar->enable(32);
    for (int i = 0; i < 5; ++i) {
      if (read_every_step) {
        lidar->getRangeImage();
        lidar->getRangeImage();
      }
      sim.robot().step(32);
    }
    const float *r = lidar->getRangeImage();
    return std::vector<float>(r, r + 360);
  };
  const std::vector<float> a = run(7, false);
  const std::vector<float> b = run(7, true);
  const std::vector<float> c = run(8, false);
  CHECK(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
  CHECK(std::memcmp(a.data(), c.data(), a.size() * sizeof(float)) != 0);
}

TEST_CASE("Driving: 1 m straight at a set wheel speed ends on the analytic pose") {
  maze::Maze corridor(4, 1);
  corridor.set_start({0, 0}, maze::Side::east);
  Simulation sim(maze::world_of(corridor), hambot(), exact());
  webots::Robot &robot = sim.robot();
  webots::PositionSensor *left = robot.getPositionSensor("left wheel encoder");
  webots::GPS *gps = robot.getGPS("gps");
  left->enable(32);
  gps->enable(32);
  CHECK(left->getValue() == 0.0);
  const double speed = 1.0 / (1.6 * 0.045);  // 1 m in 50 steps of 32 ms
  drive(robot, speed, speed);
  for (int i = 0; i < 50; ++i) REQUIRE(robot.step(32) == 0);
  CHECK(std::abs(sim.pose().x_m - 1.5) < 1e-3);
  CHECK(std::abs(sim.pose().y_m - 0.5) < 1e-9);
  CHECK(sim.pose().x_m == doctest::Approx(1.5).epsilon(1e-9));
  CHECK(gps->getValues()[0] == doctest::Approx(1.5).epsilon(1e-9));
  CHECK(gps->getValues()[1] == doctest::Approx(0.5).epsilon(1e-9));
  CHECK(left->getValue() == doctest::Approx(speed * 1.6).epsilon(1e-9));
  CHECK(robot.getTime() == doctest::Approx(1.6));
}

TEST_CASE("Driving: a commanded turn matches the IMU and the encoders") {
  Simulation sim(maze::world_of(maze::Maze(3, 3)), hambot(), at(1.5, 1.5, kPi / 2));
  webots::Robot &robot = sim.robot();
  webots::InertialUnit *imu = robot.getInertialUnit("imu");
  imu->enable(32);
  CHECK(imu->getRollPitchYaw()[2] == doctest::Approx(kPi / 2));
  drive(robot, -5.0, 5.0);
  for (int i = 0; i < 10; ++i) robot.step(32);
  const double turned = 0.045 * 10.0 / 0.184 * 0.32;  // r (wR - wL) / axle x t
  CHECK(imu->getRollPitchYaw()[2] == doctest::Approx(kPi / 2 + turned).epsilon(1e-9));
  CHECK(imu->getRollPitchYaw()[0] == 0.0);
  CHECK(sim.pose().x_m == doctest::Approx(1.5).epsilon(1e-9));
  CHECK(sim.pose().y_m == doctest::Approx(1.5).epsilon(1e-9));
  // Half a turn more wraps the yaw into (-pi, pi].
  for (int i = 0; i < 20; ++i) robot.step(32);
  const double expected = kPi / 2 + 3 * turned - 2 * kPi;
  CHECK(imu->getRollPitchYaw()[2] == doctest::Approx(expected).epsilon(1e-9));
}

TEST_CASE("Driving: position control turns each wheel to its target") {
  maze::Maze corridor(4, 1);
  corridor.set_start({0, 0}, maze::Side::east);
  Simulation sim(maze::world_of(corridor), hambot(), exact());
  webots::Robot &robot = sim.robot();
  robot.getPositionSensor("right wheel encoder")->enable(32);
  robot.getMotor("left motor")->setPosition(2 * kPi);
  robot.getMotor("right motor")->setPosition(2 * kPi);
  for (int i = 0; i < 50; ++i) robot.step(32);
  CHECK(robot.getPositionSensor("right wheel encoder")->getValue() == doctest::Approx(2 * kPi));
  CHECK(sim.pose().x_m == doctest::Approx(0.5 + 2 * kPi * 0.045));
}

TEST_CASE("Driving: the velocity is clamped to the maximum") {
  Simulation sim(maze::world_of(maze::Maze(2, 2)), hambot(), exact());
  webots::Motor *m = sim.robot().getMotor("left motor");
  m->setVelocity(100.0);
  CHECK(m->getVelocity() == 20.0);
  m->setVelocity(-100.0);
  CHECK(m->getVelocity() == -20.0);
}

TEST_CASE("Driving into a wall stops at the wall and presses the bumpers touching it") {
  Simulation sim(maze::world_of(maze::Maze(1, 1)), hambot(), at(0.5, 0.5, kPi / 2));
  webots::Robot &robot = sim.robot();
  webots::TouchSensor *front = robot.getTouchSensor("bumper front");
  webots::TouchSensor *left = robot.getTouchSensor("bumper left");
  webots::TouchSensor *right = robot.getTouchSensor("bumper right");
  front->enable(32);
  left->enable(32);
  right->enable(32);
  CHECK(front->getValue() == 0.0);
  drive(robot, 10.0, 10.0);
  for (int i = 0; i < 100; ++i) robot.step(32);
  CHECK(sim.pose().y_m == doctest::Approx(1.0 - kHalfWall_m - 0.09).epsilon(1e-9));
  CHECK(sim.pose().x_m == doctest::Approx(0.5).epsilon(1e-9));
  CHECK(front->getValue() == 1.0);
  CHECK(left->getValue() == 0.0);
  CHECK(right->getValue() == 0.0);
  // Backing off releases it.
  drive(robot, -10.0, -10.0);
  robot.step(32);
  CHECK(front->getValue() == 0.0);
}

TEST_CASE("Driving diagonally into a corner presses the two side bumpers") {
  Simulation sim(maze::world_of(maze::Maze(1, 1)), hambot(), at(0.5, 0.5, kPi / 4));
  webots::Robot &robot = sim.robot();
  for (const char *name : {"bumper front", "bumper left", "bumper right"}) {
    robot.getTouchSensor(name)->enable(32);
  }
  drive(robot, 10.0, 10.0);
  for (int i = 0; i < 100; ++i) robot.step(32);
  CHECK(sim.pose().x_m == doctest::Approx(1.0 - kHalfWall_m - 0.09).epsilon(1e-9));
  CHECK(sim.pose().y_m == doctest::Approx(1.0 - kHalfWall_m - 0.09).epsilon(1e-9));
  CHECK(robot.getTouchSensor("bumper front")->getValue() == 0.0);
  CHECK(robot.getTouchSensor("bumper left")->getValue() == 1.0);
  CHECK(robot.getTouchSensor("bumper right")->getValue() == 1.0);
}

TEST_CASE("Driving along a wall at an angle slides along it") {
  maze::Maze corridor(4, 1);
  Simulation sim(maze::world_of(corridor), hambot(), at(0.5, 0.5, 0.3));
  drive(sim.robot(), 10.0, 10.0);
  for (int i = 0; i < 100; ++i) sim.robot().step(32);  // 1.44 m, the wall after 1.36 m
  CHECK(sim.pose().y_m == doctest::Approx(1.0 - kHalfWall_m - 0.09).epsilon(1e-9));
  CHECK(sim.pose().x_m > 1.5);
}

TEST_CASE("Robot::step returns -1 at the time limit, and after a stop request") {
  maze::sim::SimulationOptions o = exact();
  o.time_limit_s = 0.32;
  Simulation sim(maze::world_of(maze::Maze(2, 2)), hambot(), o);
  for (int i = 0; i < 9; ++i) CHECK(sim.robot().step(32) == 0);
  CHECK(sim.robot().step(32) == -1);
  CHECK(sim.robot().step(32) == -1);
  CHECK(sim.time_ms() == 320);

  Simulation other(maze::world_of(maze::Maze(2, 2)), hambot(), exact());
  CHECK(other.robot().step(32) == 0);
  other.request_stop();
  CHECK(other.robot().step(32) == -1);
}

TEST_CASE("Simulation: a start pose outside the maze, in a wall or too close is an error") {
  CHECK_THROWS_WITH_AS(Simulation(maze::world_of(maze::Maze(2, 2)), hambot(), at(3.0, 0.5, 0.0)),
                       "pose (3, 0.5) is outside the maze", common::InputError);
  CHECK_THROWS_WITH_AS(Simulation(maze::world_of(maze::Maze(2, 2)), hambot(), at(0.003, 0.5, 0.0)),
                       "pose (0.003, 0.5) is inside a wall", common::InputError);
  CHECK_THROWS_WITH_AS(Simulation(maze::world_of(maze::Maze(2, 2)), hambot(), at(0.05, 0.5, 0.0)),
                       "the robot's body (radius 0.09 m) overlaps a wall at (0.05, 0.5)",
                       common::InputError);
  maze::sim::SimulationOptions bad = exact();
  bad.noise = -1.0;
  CHECK_THROWS_WITH_AS(Simulation(maze::world_of(maze::Maze(2, 2)), hambot(), bad),
                       "--noise must be a finite number >= 0 (got -1)", common::InputError);
}

TEST_CASE("DistanceSensor: the IR ring averages its three rays like Webots") {
  Simulation sim(maze::world_of(maze::Maze(1, 1)), maze::sim::find_profile("ir-ring"), at(0.5, 0.5, kPi / 2));
  webots::DistanceSensor *front = sim.robot().getDistanceSensor("ir0");
  REQUIRE(front != nullptr);
  CHECK(std::isnan(front->getValue()));  // disabled
  front->enable(32);
  CHECK(front->getAperture() == 0.03);
  CHECK(front->getMinValue() == 0.0);
  CHECK(front->getMaxValue() == 1.5);
  const double d = 0.5 - kHalfWall_m - 0.09;  // from the rim to the north wall
  const double w = std::exp(-0.25);  // rays at +-aperture / 2
  const double expected = (d + 2 * w * d / std::cos(0.015)) / (1 + 2 * w);
  CHECK(front->getValue() == doctest::Approx(expected).epsilon(1e-9));
}

TEST_CASE("DistanceSensor: beyond the table's last distance the value is the last value") {
  maze::Maze corridor(5, 1);
  Simulation sim(maze::world_of(corridor), maze::sim::find_profile("ir-ring"), at(0.5, 0.5, 0.0));
  webots::DistanceSensor *front = sim.robot().getDistanceSensor("ir0");
  front->enable(32);
  CHECK(front->getValue() == doctest::Approx(1.5));
}

TEST_CASE("DistanceSensor: sonar noise is the table's fraction of the value") {
  maze::sim::SimulationOptions o;
  o.start = maze::sim::Pose{0.5, 0.5, kPi / 2};
  Simulation sim(maze::world_of(maze::Maze(1, 1)), maze::sim::find_profile("sonar-ring"), o);
  webots::DistanceSensor *so0 = sim.robot().getDistanceSensor("so0");
  so0->enable(32);
  Simulation exact_sim(maze::world_of(maze::Maze(1, 1)), maze::sim::find_profile("sonar-ring"), at(0.5, 0.5, kPi / 2));
  exact_sim.robot().getDistanceSensor("so0")->enable(32);
  const double truth = exact_sim.robot().getDistanceSensor("so0")->getValue();
  double sum = 0.0, sum_sq = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double e = so0->getValue() - truth;
    sum += e;
    sum_sq += e * e;
    sim.robot().step(32);
  }
  const double sd = std::sqrt(sum_sq / n - (sum / n) * (sum / n));
  CHECK(std::abs(sum / n) < 0.03 * 0.066 * truth);
  CHECK(sd == doctest::Approx(0.066 * truth).epsilon(0.03));
}

TEST_CASE("DistanceSensor: the depth fan of the bumper-depth robot") {
  Simulation sim(maze::world_of(maze::Maze(1, 1)), maze::sim::find_profile("bumper-depth"), at(0.5, 0.5, kPi / 2));
  webots::Robot &robot = sim.robot();
  for (int i = 0; i < 9; ++i) {
    webots::DistanceSensor *ray = robot.getDistanceSensor("depth" + std::to_string(i));
    REQUIRE(ray != nullptr);
    ray->enable(32);
    const double a = (60.0 - 15.0 * i) * kPi / 180.0;  // from the heading, left positive
    // From the rim point (0.09 sin a left, 0.09 cos a ahead) to the nearest face.
    const double ahead = (0.5 - kHalfWall_m - 0.09 * std::cos(a)) / std::cos(a);
    const double side = (0.5 - kHalfWall_m - 0.09 * std::abs(std::sin(a))) / std::abs(std::sin(a));
    const double expected = std::abs(std::sin(a)) < 1e-12 ? ahead : std::min(ahead, side);
    CHECK(ray->getValue() == doctest::Approx(expected).epsilon(1e-9));
  }
}

namespace {

// hambot's rotating lidar (12 Hz: 0.384 of a revolution a 32 ms step) with the test robot's
// 12 m range, and the same lidar fixed.
maze::sim::RobotProfile rotating_robot(double frequency_hz) {
  maze::sim::RobotProfile p = hambot();
  p.lidars[0].frequency_hz = frequency_hz;
  return p;
}

// The range of beam i (beam offset `offset`, in beams) of a 360-beam lidar at (x, y) facing
// yaw, in the open 3 x 3 maze: the nearest inner wall face, kHalfWall_m in from the maze's edges.
double room_range(double x, double y, double yaw, int i, double offset) {
  const double a = yaw + kPi - (i + offset) * 2 * kPi / 360;
  const double dx = std::cos(a);
  const double dy = std::sin(a);
  const double tx = dx > 0   ? (3.0 - kHalfWall_m - x) / dx
                    : dx < 0 ? (kHalfWall_m - x) / dx
                             : std::numeric_limits<double>::infinity();
  const double ty = dy > 0   ? (3.0 - kHalfWall_m - y) / dy
                    : dy < 0 ? (kHalfWall_m - y) / dy
                             : std::numeric_limits<double>::infinity();
  return std::min(tx, ty);
}

std::vector<float> image(webots::Lidar *lidar) {
  const float *r = lidar->getRangeImage();
  REQUIRE(r != nullptr);
  return {r, r + lidar->getHorizontalResolution()};
}

}  // namespace

TEST_CASE("Rotating lidar: a slice per step, from ahead clockwise, 0 where not yet swept") {
  Simulation sim(maze::world_of(maze::Maze(3, 3)), rotating_robot(12.0), at(1.5, 1.5, kPi / 2));
  webots::Lidar *lidar = sim.robot().getLidar("lidar");
  lidar->enable(32);
  CHECK(lidar->getFrequency() == 12.0);
  for (float r : image(lidar)) CHECK(r == 0.0f);
  REQUIRE(sim.robot().step(32) == 0);
  const std::vector<float> one = image(lidar);
  // Step 1 sweeps 0 to 0.384 revolution clockwise from ahead (beam 180): beams 181 ... 318.
  for (int i = 0; i < 360; ++i) {
    CAPTURE(i);
    CHECK((one[static_cast<std::size_t>(i)] != 0.0f) == (i >= 181 && i <= 318));
  }
}

TEST_CASE("Rotating lidar: after a revolution at rest, every beam is the range from the rest pose") {
  Simulation fixed(maze::world_of(maze::Maze(3, 3)), rotating_robot(0.0), at(1.5, 1.5, 0.3));
  Simulation rotating(maze::world_of(maze::Maze(3, 3)), rotating_robot(12.0), at(1.5, 1.5, 0.3));
  webots::Lidar *lidar = rotating.robot().getLidar("lidar");
  lidar->enable(32);
  CHECK(fixed.robot().getLidar("lidar")->getFrequency() == 0.0);
  for (int i = 0; i < 3; ++i) REQUIRE(rotating.robot().step(32) == 0);
  const std::vector<float> after_one = image(lidar);
  for (int i = 0; i < 360; ++i) {
    CAPTURE(i);
    CHECK(after_one[static_cast<std::size_t>(i)] == doctest::Approx(room_range(1.5, 1.5, 0.3, i, 0.0)).epsilon(1e-6));
  }
  for (int i = 0; i < 3; ++i) REQUIRE(rotating.robot().step(32) == 0);
  CHECK(image(lidar) == after_one);
}

TEST_CASE("Rotating lidar: mid-turn, each beam is as seen from the pose of the step that swept it") {
  Simulation rotating(maze::world_of(maze::Maze(3, 3)), rotating_robot(12.0), at(1.5, 1.5, 0.0));
  webots::Lidar *lidar = rotating.robot().getLidar("lidar");
  webots::InertialUnit *imu = rotating.robot().getInertialUnit("imu");
  webots::GPS *gps = rotating.robot().getGPS("gps");
  lidar->enable(32);
  imu->enable(32);
  gps->enable(32);
  drive(rotating.robot(), -5.0, 5.0);
  std::vector<std::array<double, 3>> poses;  // x, y, yaw at the end of each step
  for (int i = 0; i < 10; ++i) {
    REQUIRE(rotating.robot().step(32) == 0);
    poses.push_back({gps->getValues()[0], gps->getValues()[1], imu->getRollPitchYaw()[2]});
  }
  const std::vector<float> mixed = image(lidar);
  const auto seen_from = [&](std::size_t step, int i) {
    const std::array<double, 3> &p = poses[step];
    return std::abs(static_cast<double>(mixed[static_cast<std::size_t>(i)]) - room_range(p[0], p[1], p[2], i, 0.0)) < 1e-5;
  };
  int from_last_step = 0;
  for (int i = 0; i < 360; ++i) {
    CAPTURE(i);
    CHECK((seen_from(9, i) || seen_from(8, i) || seen_from(7, i)));
    if (seen_from(9, i)) ++from_last_step;
  }
  CHECK(from_last_step < 200);  // the rest come from the two steps before
}

TEST_CASE("Rotating lidar: lazy and deterministic, however often it is read") {
  maze::sim::SimulationOptions o = at(1.5, 1.5, 1.0);
  o.noise.reset();  // hambot's noise
  o.dropout = 0.05;
  Simulation often(maze::world_of(maze::Maze(3, 3)), rotating_robot(12.0), o);
  Simulation once(maze::world_of(maze::Maze(3, 3)), rotating_robot(12.0), o);
  often.robot().getLidar("lidar")->enable(32);
  once.robot().getLidar("lidar")->enable(32);
  for (int i = 0; i < 5; ++i) {
    REQUIRE(often.robot().step(32) == 0);
    REQUIRE(once.robot().step(32) == 0);
    image(often.robot().getLidar("lidar"));
  }
  CHECK(image(often.robot().getLidar("lidar")) == image(once.robot().getLidar("lidar")));
}
