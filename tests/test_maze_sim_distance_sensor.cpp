// Distance sensors as Webots computes them (docs/reference/distancesensor.md): hand-worked
// cases for each type's rule, and the rules held to a plain reference on random inputs.

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "common/random.hpp"
#include "maze/generate/generator.hpp"
#include "maze/world/maze.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/sim/wall_grid.hpp"
#include "test_values.hpp"

namespace {

using maze::sim::DistanceSensorSpec;
using maze::sim::DistanceSensorType;
using maze::sim::Pose;

constexpr double kRange_m = 5.0;

// A sensor looking along the robot's heading, its table distance -> metres up to 5 m.
DistanceSensorSpec sensor(DistanceSensorType type, int rays, double aperture_rad, double gaussian_width = 1.0) {
  return {"s", 0.0, aperture_rad, rays, {{0.0, 0.0, 0.0}, {kRange_m, kRange_m, 0.0}}, type, gaussian_width};
}

double measured(const maze::sim::WallGrid &walls, const DistanceSensorSpec &s, Pose at) {
  return maze::sim::sensor_distance_m(walls, s, 0.0, at);
}

// 2 x 2 cells of 1 m, one interior wall: the north side of (0, 0), x = 0 ... 1, its east
// end a post whose end face is x = 1 + kHalfWall_m, y = 1 - kHalfWall_m ... 1 + kHalfWall_m.
maze::Maze post_maze() {
  maze::Maze m(2, 2);
  m.set_wall({0, 0}, maze::Side::north, true);
  return m;
}

}  // namespace

TEST_CASE("ray weights: Webots' Gaussian exp(-(t / (a g))^2), normalised") {
  const std::vector<double> three = maze::sim::ray_weights(sensor(DistanceSensorType::generic, 3, 0.03));
  const double edge = std::exp(-0.25);  // t = a / 2
  REQUIRE(three.size() == 3);
  CHECK(three[0] == doctest::Approx(edge / (1 + 2 * edge)));
  CHECK(three[1] == doctest::Approx(1 / (1 + 2 * edge)));
  CHECK(three[2] == doctest::Approx(edge / (1 + 2 * edge)));
  // Gaussian width 0.5: the edge rays weigh exp(-1).
  const std::vector<double> narrow = maze::sim::ray_weights(sensor(DistanceSensorType::generic, 3, 0.4, 0.5));
  CHECK(narrow[0] == doctest::Approx(std::exp(-1.0) / (1 + 2 * std::exp(-1.0))));
  // Five rays: offsets -a/2, -a/4, 0, a/4, a/2.
  const DistanceSensorSpec five = sensor(DistanceSensorType::generic, 5, 0.4);
  CHECK(maze::sim::ray_offset_rad(five, 0) == doctest::Approx(-0.2));
  CHECK(maze::sim::ray_offset_rad(five, 1) == doctest::Approx(-0.1));
  CHECK(maze::sim::ray_offset_rad(five, 2) == 0.0);
  CHECK(maze::sim::ray_offset_rad(five, 4) == doctest::Approx(0.2));
  const std::vector<double> w = maze::sim::ray_weights(five);
  const double sum = 1 + 2 * std::exp(-1.0 / 16) + 2 * std::exp(-0.25);
  CHECK(w[1] == doctest::Approx(std::exp(-1.0 / 16) / sum));
  CHECK(maze::sim::ray_weights(sensor(DistanceSensorType::generic, 1, 0.4)) == std::vector<double>{1.0});
}

TEST_CASE("sonar square to a wall: the nearest ray, the axis, not the rays' mean") {
  const maze::sim::WallGrid walls(maze::Maze(1, 1));
  const Pose centre{0.5, 0.5, kPi / 2};
  const double d = 0.5 - kHalfWall_m;  // centre to the north face
  // Every ray's incidence is at most 0.2 rad < pi / 8: all return; the axis is nearest.
  CHECK(measured(walls, sensor(DistanceSensorType::sonar, 5, 0.4), centre) == doctest::Approx(d).epsilon(1e-12));
  // generic: the weighted mean of d / cos t over the five rays, longer than d.
  const DistanceSensorSpec generic = sensor(DistanceSensorType::generic, 5, 0.4);
  const std::vector<double> w = maze::sim::ray_weights(generic);
  double mean = 0.0;
  for (int k = 0; k < 5; ++k) mean += w[static_cast<std::size_t>(k)] * d / std::cos(maze::sim::ray_offset_rad(generic, k));
  CHECK(measured(walls, generic, centre) == doctest::Approx(mean).epsilon(1e-12));
  CHECK(mean > d * 1.005);
}

TEST_CASE("sonar at 30 degrees to a wall: only the ray within 22.5 degrees of the normal returns") {
  const maze::sim::WallGrid walls(maze::Maze(5, 1));
  // Heading 60 deg from east: incidence on the north face 30 deg; the rays at +0.2, +0.1,
  // 0, -0.1, -0.2 rad meet it at 18.5, 24.3, 30, 35.7, 41.5 deg: only the first returns.
  const Pose at{0.5, 0.5, kPi / 3};
  const double to_face = 1.0 - kHalfWall_m - 0.5;
  CHECK(measured(walls, sensor(DistanceSensorType::sonar, 5, 0.4), at) ==
        doctest::Approx(to_face / std::sin(kPi / 3 + 0.2)).epsilon(1e-12));
  // One ray on the axis, 30 deg: lost, the sonar reads its range.
  CHECK(measured(walls, sensor(DistanceSensorType::sonar, 1, 0.0), at) == kRange_m);
  // 22 deg returns, 23 deg does not.
  const double deg = kPi / 180;
  CHECK(measured(walls, sensor(DistanceSensorType::sonar, 1, 0.0), {0.5, 0.5, kPi / 2 - 22 * deg}) ==
        doctest::Approx(to_face / std::cos(22 * deg)).epsilon(1e-12));
  CHECK(measured(walls, sensor(DistanceSensorType::sonar, 1, 0.0), {0.5, 0.5, kPi / 2 - 23 * deg}) == kRange_m);
  // generic and infra-red see the wall whatever the angle.
  CHECK(measured(walls, sensor(DistanceSensorType::infra_red, 1, 0.0), at) ==
        doctest::Approx(to_face / std::sin(kPi / 3)).epsilon(1e-12));
}

TEST_CASE("a sonar ray grazing a post: the end face returns a shallow ray, the side face loses it") {
  const maze::sim::WallGrid walls(post_maze());
  const DistanceSensorSpec sonar = sensor(DistanceSensorType::sonar, 1, 0.0);
  const DistanceSensorSpec generic = sensor(DistanceSensorType::generic, 1, 0.0);
  const double run = 1.5 - (1.0 + kHalfWall_m);  // x from the sensor to the post's end face
  // Westward and 0.3 rad up (17 deg): meets the end face x = 1 + kHalfWall_m at y = 1: 17 deg incidence.
  const double a = 0.3;
  const Pose shallow{1.5, 1.0 - run * std::tan(a), kPi - a};
  CHECK(measured(walls, sonar, shallow) == doctest::Approx(run / std::cos(a)).epsilon(1e-12));
  // A micrometre under the post's lower corner: the ray grazes the corner and meets the
  // wall's south face 3 micrometres on, at 90 - 17 = 73 deg: lost. generic sees it there.
  const Pose grazing{1.5, 1.0 - kHalfWall_m - run * std::tan(a) - 1e-6, kPi - a};
  CHECK(measured(walls, sonar, grazing) == kRange_m);
  CHECK(measured(walls, generic, grazing) == doctest::Approx(run / std::cos(a)).epsilon(1e-4));
  // 0.5 rad (29 deg) on the end face: lost.
  CHECK(measured(walls, sonar, {1.5, 1.0 - run * std::tan(0.5), kPi - 0.5}) == kRange_m);
  // Down onto the wall's north face, 0.3 rad below the horizontal (73 deg incidence): lost.
  const Pose above{0.9, 1.1, -kPi + a};
  CHECK(measured(walls, sonar, above) == kRange_m);
  CHECK(measured(walls, generic, above) == doctest::Approx((0.1 - kHalfWall_m) / std::sin(a)).epsilon(1e-12));
  // Steeply down onto it (1.3 rad below the horizontal, 15 deg incidence): returns.
  CHECK(measured(walls, sonar, {0.9, 1.5, -kPi + 1.3}) ==
        doctest::Approx((0.5 - kHalfWall_m) / std::sin(1.3)).epsilon(1e-12));
}

TEST_CASE("cast_hit: the face's normal along x or y") {
  const maze::sim::WallGrid walls(post_maze());
  const maze::sim::RayHit east = maze::sim::cast_hit(walls, 1.5, 1.0, kPi, 5.0);
  CHECK(east.distance_m == doctest::Approx(0.5 - kHalfWall_m));
  CHECK(east.normal_x == 1.0);
  CHECK(east.normal_y == 0.0);
  const maze::sim::RayHit north = maze::sim::cast_hit(walls, 0.5, 1.5, -kPi / 2, 5.0);
  CHECK(north.normal_x == 0.0);
  CHECK(north.normal_y == 1.0);
  // Through a grid vertex at 45 deg: both faces at once, the tie goes to the x face.
  const maze::sim::RayHit corner = maze::sim::cast_hit(maze::sim::WallGrid(maze::Maze(1, 1)), 0.5, 0.5, kPi / 4, 5.0);
  CHECK(corner.distance_m == doctest::Approx(std::sqrt(2.0) * (0.5 - kHalfWall_m)));
  CHECK(corner.normal_x == -1.0);
  CHECK(corner.normal_y == 0.0);
  const maze::sim::RayHit none = maze::sim::cast_hit(walls, 0.5, 0.5, 0.0, 0.1);
  CHECK(none.distance_m == std::numeric_limits<double>::infinity());
  CHECK(none.normal_x == 0.0);
}

TEST_CASE("lookup_reading: the table's value plus noise of sigma fraction x value, one variate") {
  const std::vector<maze::sim::LookupRow> table{{0.0, 1000.0, 0.0}, {0.1, 1000.0, 0.1}, {0.2, 400.0, 0.1}};
  common::Rng a(7);
  common::Rng b(7);
  const double noisy = maze::sim::lookup_reading(table, 0.15, true, a);
  CHECK(noisy == doctest::Approx(700.0 + b.normal(0.0, 0.1 * 700.0)).epsilon(1e-12));
  CHECK(a.next_u64() == b.next_u64());
  CHECK(maze::sim::lookup_reading(table, 0.15, false, a) == doctest::Approx(700.0));
  CHECK(maze::sim::lookup_reading(table, 9.0, false, a) == 400.0);
}

namespace {

// The plain reference: each ray cast with the slab test of every box (cast_reference); a
// ray's incidence from the wall's tangent, found from the hits of two rays 1e-7 rad either
// side (two points on the face the ray meets). false when a case is too close to call: a
// ray within 1e-4 rad of pi / 8, or its neighbours on two faces (near a corner).
bool reference_distance(const maze::sim::WallGrid &walls, const DistanceSensorSpec &s, const Pose &at,
                        double &out_m) {
  const double direction = at.yaw_rad + s.angle_rad;
  double weighted = 0.0, weights = 0.0, nearest = kRange_m;
  for (int k = 0; k < s.rays; ++k) {
    const double t = s.rays == 1 ? 0.0 : -s.aperture_rad / 2 + k * s.aperture_rad / (s.rays - 1);
    const double a = direction + t;
    const double d = walls.cast_reference(at.x_m, at.y_m, std::cos(a), std::sin(a), kRange_m);
    const double spread = s.aperture_rad * s.gaussian_width;
    const double w = spread > 0 ? std::exp(-(t / spread) * (t / spread)) : 1.0;
    weighted += w * std::min(d, kRange_m);
    weights += w;
    if (!(d < kRange_m) || d >= nearest) continue;
    const double e = 1e-7;
    const double d1 = walls.cast_reference(at.x_m, at.y_m, std::cos(a - e), std::sin(a - e), 2 * kRange_m);
    const double d2 = walls.cast_reference(at.x_m, at.y_m, std::cos(a + e), std::sin(a + e), 2 * kRange_m);
    const double tx = d2 * std::cos(a + e) - d1 * std::cos(a - e);
    const double ty = d2 * std::sin(a + e) - d1 * std::sin(a - e);
    const double norm = std::hypot(tx, ty);
    if (!(std::min(std::abs(tx), std::abs(ty)) < 1e-3 * norm)) return false;
    // incidence = 90 deg - the angle between the ray and the tangent
    const double incidence = kPi / 2 - std::acos(std::abs(tx * std::cos(a) + ty * std::sin(a)) / norm);
    if (std::abs(incidence - kPi / 8) < 1e-4) return false;
    if (incidence < kPi / 8) nearest = d;
  }
  out_m = s.type == DistanceSensorType::sonar ? nearest : weighted / weights;
  return true;
}

}  // namespace

TEST_CASE("sensor_distance_m against the plain reference: random mazes, poses and sensors") {
  common::Rng rng(20261201);
  int compared = 0, sonar_lost = 0;
  for (int world = 0; world < 20; ++world) {
    maze::GeneratorOptions g;
    g.width = 3 + world % 5;
    g.height = 3 + world % 4;
    g.seed = static_cast<std::uint64_t>(world);
    g.loops = 0.2;
    const maze::sim::WallGrid walls(maze::generate_maze(g));
    for (int trial = 0; trial < 100; ++trial) {
      const Pose at{rng.uniform(0.1, 0.9) + static_cast<double>(rng.next_u64() % static_cast<std::uint64_t>(g.width)),
                    rng.uniform(0.1, 0.9) + static_cast<double>(rng.next_u64() % static_cast<std::uint64_t>(g.height)),
                    rng.uniform(-kPi, kPi)};
      const auto type = static_cast<DistanceSensorType>(rng.next_u64() % 3);
      const DistanceSensorSpec s = sensor(type, 1 + static_cast<int>(rng.next_u64() % 7), rng.uniform(0.0, 1.0),
                                          rng.uniform(0.3, 3.0));
      double expected = 0.0;
      if (!reference_distance(walls, s, at, expected)) continue;
      CAPTURE(world);
      CAPTURE(trial);
      CAPTURE(maze::sim::to_string(type));
      CHECK(measured(walls, s, at) == doctest::Approx(expected).epsilon(1e-9));
      ++compared;
      if (type == DistanceSensorType::sonar && expected == kRange_m) ++sonar_lost;
    }
  }
  CHECK(compared > 1900);
  CHECK(sonar_lost > 10);  // the specular loss happens in the sample
}
