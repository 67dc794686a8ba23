#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>
#include <webots/Lidar.hpp>
#include <webots/Robot.hpp>

#include "maze/world/maze.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/scan.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/sim/simulation.hpp"
#include "test_values.hpp"

// The default robot's fixed lidar, worked by hand (docs/simulator.md, "The fixed lidar"):
// Webots points beam i of a fixed lidar at fov/2 - (i + 1/2) fov/N, measures the depth along
// the axis of the cube face the beam falls in, adds the noise to it, rounds it to the
// resolution (floor(d / r + 1/2) r), and divides by the cosine back to a range.

namespace {

const maze::sim::LidarSpec &hambot_lidar() { return maze::sim::default_profile().lidars.front(); }

// The range of beam i read from format_scan's line "i angle range".
double scanned_range(const std::string &scan, int i) {
  std::size_t at = 0;
  for (int line = 0; line < i; ++line) at = scan.find('\n', at) + 1;
  const std::size_t end = scan.find('\n', at);
  const std::string text = scan.substr(at, end - at);
  return std::stod(text.substr(text.rfind(' ') + 1));
}

}  // namespace

TEST_CASE("fixed lidar: beam i points half a beam in, at fov/2 - (i + 1/2) fov/N") {
  const maze::sim::LidarSpec &l = hambot_lidar();
  REQUIRE(l.frequency_hz == 0.0);
  CHECK(maze::sim::beam_offset(l) == 0.5);
  // 360 beams over 2 pi: beam 0 at 179.5 deg (back, just left of it), 90 at 89.5 (left), 180
  // at -0.5 (ahead, just right), 270 at -90.5 (right).
  CHECK(maze::sim::beam_angle_rad(l, 0) == doctest::Approx(179.5 * kDeg));
  CHECK(maze::sim::beam_angle_rad(l, 90) == doctest::Approx(89.5 * kDeg));
  CHECK(maze::sim::beam_angle_rad(l, 180) == doctest::Approx(-0.5 * kDeg));
  CHECK(maze::sim::beam_angle_rad(l, 270) == doctest::Approx(-90.5 * kDeg));
  CHECK(maze::sim::beam_angle_rad(l, 359) == doctest::Approx(-179.5 * kDeg));
  // A rotating lidar's beams stay on the whole degrees.
  const maze::sim::LidarSpec &rotating = maze::sim::find_profile("hambot-2025").lidars.front();
  CHECK(maze::sim::beam_offset(rotating) == 0.0);
  CHECK(maze::sim::beam_angle_rad(rotating, 180) == doctest::Approx(0.0));
}

TEST_CASE("fixed lidar: depth is measured along the nearest quarter-turn axis") {
  CHECK(maze::sim::face_cos(0.0) == doctest::Approx(1.0));
  CHECK(maze::sim::face_cos(30.5 * kDeg) == doctest::Approx(std::cos(30.5 * kDeg)));
  CHECK(maze::sim::face_cos(89.5 * kDeg) == doctest::Approx(std::cos(0.5 * kDeg)));
  CHECK(maze::sim::face_cos(-135.0 * kDeg) == doctest::Approx(std::cos(45.0 * kDeg)));
  CHECK(maze::sim::face_cos(179.5 * kDeg) == doctest::Approx(std::cos(0.5 * kDeg)));
}

TEST_CASE("fixed lidar: resolution rounds to the nearest multiple, halves up") {
  CHECK(maze::sim::quantised_m(0.494, 0.01) == doctest::Approx(0.49));
  CHECK(maze::sim::quantised_m(0.495, 0.01) == doctest::Approx(0.50));
  CHECK(maze::sim::quantised_m(3.4999, 0.01) == doctest::Approx(3.50));
  CHECK(maze::sim::quantised_m(1.23456, 0.0) == 1.23456);  // no resolution: unchanged
  CHECK(std::isinf(maze::sim::quantised_m(std::numeric_limits<double>::infinity(), 0.01)));
}

TEST_CASE("fixed lidar: a reading worked by hand, planar depth quantised, then back along the beam") {
  const maze::sim::LidarSpec &l = hambot_lidar();
  const double c = std::cos(30.5 * kDeg);
  // A wall 3.494 m ahead along the face's axis, met by a beam 30.5 deg off it: range
  // 3.494 / cos 30.5 = 4.0544 m; the depth 3.494 rounds to 3.49; back along the beam
  // 3.49 / cos 30.5 = 4.04976 m (not 4.05, the range rounded).
  const float r = maze::sim::fixed_lidar_reading(l, 3.494 / c, c, 0.0);
  CHECK(r == doctest::Approx(3.49 / c).epsilon(1e-6));
  CHECK(std::abs(r - 4.05) > 1e-4);
  // Noise is added to the depth before rounding: 3.494 + 0.004 = 3.498 rounds to 3.50.
  CHECK(maze::sim::fixed_lidar_reading(l, 3.494 / c, c, 0.004) == doctest::Approx(3.50 / c).epsilon(1e-6));
  // Outside [0.05, 12): no return. A depth of 12 is out; one of 11.996 rounds up to 12.00 and
  // is out too; 0.04 is below the minimum.
  CHECK(std::isinf(maze::sim::fixed_lidar_reading(l, 12.0, 1.0, 0.0)));
  CHECK(std::isinf(maze::sim::fixed_lidar_reading(l, 11.996, 1.0, 0.0)));
  CHECK(maze::sim::fixed_lidar_reading(l, 11.994, 1.0, 0.0) == doctest::Approx(11.99));
  CHECK(std::isinf(maze::sim::fixed_lidar_reading(l, 0.04, 1.0, 0.0)));
}

TEST_CASE("fixed lidar: the default robot's scan of an empty 4 x 4 maze, by hand") {
  // Facing east at (0.5, 0.5), walls 0.012 m thick: the west and south faces 0.494 m away,
  // the east and north faces 3.494 m away.
  const maze::Maze m(4, 4);
  maze::sim::ScanRequest request;
  request.pose = {0.5, 0.5, 0.0};
  request.noise = 0.0;
  const std::string scan = maze::sim::format_scan(m, request);
  const double half = std::cos(0.5 * kDeg);
  // Beam 0 at 179.5 deg: the west wall, depth 0.494 -> 0.49, range 0.49 / cos 0.5 deg.
  CHECK(scanned_range(scan, 0) == doctest::Approx(0.49 / half).epsilon(1e-6));
  // Beam 90 at 89.5 deg: the north wall, depth 3.494 -> 3.49.
  CHECK(scanned_range(scan, 90) == doctest::Approx(3.49 / half).epsilon(1e-6));
  // Beam 149 at 30.5 deg: the east wall (3.494 / cos 30.5 = 4.054 before the north wall's
  // 3.494 / sin 30.5 = 6.885), depth 3.494 -> 3.49.
  CHECK(scanned_range(scan, 149) == doctest::Approx(3.49 / std::cos(30.5 * kDeg)).epsilon(1e-6));
  // Beam 270 at -90.5 deg: the south wall, as beam 0.
  CHECK(scanned_range(scan, 270) == doctest::Approx(0.49 / half).epsilon(1e-6));
  // Beam 225 at -45.5 deg: the south wall 0.494 / sin 45.5 = 0.6928 m away, in the right
  // face (its axis at -90 deg, 44.5 deg off): depth 0.494 -> 0.49, range 0.49 / cos 44.5.
  CHECK(scanned_range(scan, 225) == doctest::Approx(0.49 / std::cos(44.5 * kDeg)).epsilon(1e-6));
}

TEST_CASE("fixed lidar: a fixed lidar reports no head frequency, so the controller does not wait a turn") {
  const maze::Maze m(4, 4);
  webots::embedded::Simulation sim(maze::world_of(m), maze::sim::default_profile(), {});
  webots::Lidar *lidar = sim.robot().getLidar("lidar");
  REQUIRE(lidar != nullptr);
  CHECK(lidar->getFrequency() == 0.0);
  webots::embedded::Simulation old(maze::world_of(m), maze::sim::find_profile("hambot-2025"), {});
  CHECK(old.robot().getLidar("lidar")->getFrequency() == 12.0);
}

namespace {

// range_image at one pose against the beam-by-beam form it replaced (cast, draw, read, in index
// order), bit for bit; each beam's cast also against cast_reference, one slab test a box. The
// beams compared.
int compare_range_image(const maze::sim::WallGrid &walls, const maze::sim::LidarSpec &spec,
                        const maze::sim::Pose &pose, double noise, std::uint64_t seed) {
  const maze::sim::LidarModel model(spec);
  std::vector<float> image(static_cast<std::size_t>(spec.horizontal_resolution));
  common::Rng rng(seed);
  model.range_image(walls, noise, pose, rng, image);
  common::Rng reference_rng(seed);
  const double sigma_m = noise * spec.max_range_m;
  const double reach_m = spec.max_range_m + 6.0 * sigma_m + spec.resolution_m;
  int compared = 0;
  for (int i = 0; i < spec.horizontal_resolution; ++i) {
    const double a = pose.yaw_rad;
    const double b = maze::sim::beam_angle_rad(spec, i);
    const double dx = std::cos(a) * std::cos(b) - std::sin(a) * std::sin(b);
    const double dy = std::sin(a) * std::cos(b) + std::cos(a) * std::sin(b);
    const double range = walls.cast_direction(pose.x_m, pose.y_m, dx, dy, reach_m);
    const double reference = walls.cast_reference(pose.x_m, pose.y_m, dx, dy, reach_m);
    if (std::bit_cast<std::uint64_t>(range) != std::bit_cast<std::uint64_t>(reference)) {
      FAIL_CHECK("beam " << i << " at (" << pose.x_m << ", " << pose.y_m << ", " << pose.yaw_rad
                         << "): cast " << range << " != reference " << reference);
    }
    const double noise_m = sigma_m > 0.0 ? reference_rng.normal(0.0, sigma_m) : 0.0;
    const float expected = maze::sim::fixed_lidar_reading(spec, range, maze::sim::face_cos(b), noise_m);
    const float got = image[static_cast<std::size_t>(i)];
    if (std::bit_cast<std::uint32_t>(got) != std::bit_cast<std::uint32_t>(expected)) {
      FAIL_CHECK("seed " << seed << " beam " << i << ": " << got << " != " << expected);
    }
    ++compared;
  }
  return compared;
}

maze::Maze carved_maze() {
  maze::Maze m(9, 7);
  common::Rng carve(7);
  for (int y = 0; y < m.height(); ++y) {
    for (int x = 0; x < m.width(); ++x) {
      for (const maze::Side s : maze::kSides) {
        if (carve.uniform01() < 0.45) m.set_wall({x, y}, s, true);
      }
    }
  }
  return m;
}

}  // namespace

// range_image works in blocks of passes (the fan's casts, the noise, the readings four at a
// time with AVX2 where the processor has it): held here to the beam-by-beam form it replaced,
// bit for bit, over random poses in a carved maze, with and without noise, with a
// resolution (the lane path) and without (the scalar path), ranges short enough that
// min_range and max_range cut beams.
TEST_CASE("fixed lidar: range_image gives the beam-by-beam readings bit for bit") {
  const maze::Maze m = carved_maze();
  const maze::sim::WallGrid walls(m);
  maze::sim::LidarSpec spec = hambot_lidar();
  int compared = 0;
  for (const double max_range_m : {12.0, 1.7}) {
    for (const double resolution_m : {0.01, 0.0}) {
      spec.max_range_m = max_range_m;
      spec.min_range_m = max_range_m > 2.0 ? 0.05 : 0.4;
      spec.resolution_m = resolution_m;
      spec.horizontal_resolution = max_range_m > 2.0 ? 360 : 203;  // blocks of 64 and a remainder
      common::Rng where(11);
      for (int p = 0; p < 150; ++p) {
        const maze::sim::Pose pose{where.uniform(0.06, 8.94), where.uniform(0.06, 6.94), where.uniform(-kPi, kPi)};
        if (walls.inside_wall(pose.x_m, pose.y_m)) continue;
        const double noise = p % 3 == 0 ? 0.0 : spec.noise * (1 + p % 4);
        compared += compare_range_image(walls, spec, pose, noise, static_cast<std::uint64_t>(p));
      }
    }
  }
  CHECK(compared > 100000);
}

// The cell walk leaves out the boxes a ray passes by a clear margin and tests every box near
// a corner: beams aimed at the boxes' corners (a grid vertex, or h from it either way on each
// axis), exactly and turned off by 1e-15 to 1e-4 rad either side, so that they graze, touch or
// pass each corner by less than, about and more than that margin.
TEST_CASE("fixed lidar: range_image gives the beam-by-beam readings bit for bit on beams grazing corners") {
  const maze::Maze m = carved_maze();
  const maze::sim::WallGrid walls(m);
  REQUIRE(walls.cell_size_m() == 1.0);
  const double h = walls.wall_thickness_m() / 2.0;
  const maze::sim::LidarSpec spec = hambot_lidar();
  common::Rng where(23);
  int compared = 0;
  for (int p = 0; p < 400; ++p) {
    const int cx = static_cast<int>(where.uniform(0.0, 9.0));
    const int cy = static_cast<int>(where.uniform(0.0, 7.0));
    const double x = cx + where.uniform(0.05, 0.95);
    const double y = cy + where.uniform(0.05, 0.95);
    if (walls.inside_wall(x, y)) continue;
    // A vertex of the cell or one up to two cells on, and a box corner at or around it.
    const double vx = cx + std::floor(where.uniform(-1.0, 3.0)) + h * std::floor(where.uniform(-1.0, 2.0));
    const double vy = cy + std::floor(where.uniform(-1.0, 3.0)) + h * std::floor(where.uniform(-1.0, 2.0));
    const int beam = static_cast<int>(where.uniform(0.0, spec.horizontal_resolution));
    const double aim = std::atan2(vy - y, vx - x) - maze::sim::beam_angle_rad(spec, beam);
    for (const double off : {0.0, 1e-15, 1e-12, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4}) {
      for (const double side : {1.0, -1.0}) {
        const maze::sim::Pose pose{x, y, aim + side * off};
        const double noise = p % 4 == 0 ? spec.noise : 0.0;
        compared += compare_range_image(walls, spec, pose, noise, static_cast<std::uint64_t>(p));
      }
    }
  }
  CHECK(compared > 100000);
}
