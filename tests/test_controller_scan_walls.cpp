#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "common/angles.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/walls.hpp"
#include "sensing/scan.hpp"
#include "test_values.hpp"

using mapping::Cell;
using mapping::Heading;
using mapping::LocalSubCell;
using mapping::SideState;

namespace {

sensing::LidarScan scan_of(const std::vector<float> &ranges, double yaw, double fov) {
  sensing::LidarScan s;
  s.yaw_rad = yaw;
  s.fov_rad = fov;
  s.min_range_m = 0.05;
  s.max_range_m = 12.0;
  s.ranges = ranges;
  return s;
}

}  // namespace

TEST_CASE("LidarScan: the conventions' beam order (0 back, 90 left, 180 ahead, 270 right)") {
  const std::vector<float> ranges(360, 1.0f);
  const auto north = scan_of(ranges, kPi / 2, 2 * kPi);
  CHECK(north.beam_angle_rad(0) == doctest::Approx(kPi));
  CHECK(north.beam_angle_rad(90) == doctest::Approx(kPi / 2));
  CHECK(north.beam_angle_rad(180) == doctest::Approx(0.0));
  CHECK(north.beam_angle_rad(270) == doctest::Approx(-kPi / 2));
  CHECK(north.beam_towards(kPi / 2) == 180);   // north, ahead
  CHECK(north.beam_towards(0.0) == 270);       // east, on the right
  CHECK(north.beam_towards(kPi) == 90);        // west, on the left
  CHECK(north.beam_towards(-kPi / 2) == 0);    // south, behind
  CHECK(north.beam_towards(3 * kPi / 2) == 0); // the same direction, unwrapped
  // A yaw between beams: the nearest beam.
  const auto tilted = scan_of(ranges, 0.3, 2 * kPi);
  CHECK(tilted.beam_towards(kPi / 2) == 107);  // (pi - (pi/2 - 0.3)) / 1 degree = 107.19
  CHECK(tilted.beam_towards(0.3 + kPi - 0.001) == 0);
  CHECK(tilted.beam_towards(0.3 - kPi + 0.001) == 0);
}

TEST_CASE("LidarScan: a narrow field of view has nothing behind") {
  const std::vector<float> ranges(4, 1.0f);  // beams at +pi/2, +pi/4, 0, -pi/4
  const auto s = scan_of(ranges, 0.0, kPi);
  CHECK(s.beam_towards(kPi / 2) == 0);
  CHECK(s.beam_towards(0.0) == 2);
  CHECK(s.beam_towards(-kPi / 4) == 3);
  CHECK_FALSE(s.beam_towards(-kPi / 2).has_value());
  CHECK_FALSE(s.beam_towards(kPi).has_value());
  CHECK_FALSE(scan_of({}, 0.0, kPi).beam_towards(0.0).has_value());
}

TEST_CASE("LidarScan: hits, no returns, invalid readings") {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> ranges{0.5f, 12.0f, inf, 12.5f, nan, -0.1f, 0.01f, 0.05f};
  const auto s = scan_of(ranges, 0.0, 2 * kPi);
  using K = sensing::ReadingKind;
  const std::vector<K> expected{K::hit, K::hit, K::no_return, K::no_return,
                                K::invalid, K::invalid, K::invalid, K::hit};
  for (int i = 0; i < s.beam_count(); ++i) {
    CAPTURE(i);
    CHECK(s.kind(i) == expected[static_cast<std::size_t>(i)]);
  }
}

TEST_CASE("wrap_angle_rad: into (-pi, pi]") {
  CHECK(common::wrap_angle_rad(0.0) == 0.0);
  CHECK(common::wrap_angle_rad(kPi) == doctest::Approx(kPi));
  CHECK(common::wrap_angle_rad(-kPi) == doctest::Approx(kPi));
  CHECK(common::wrap_angle_rad(3 * kPi / 2) == doctest::Approx(-kPi / 2));
  CHECK(common::wrap_angle_rad(-7 * kPi / 2) == doctest::Approx(kPi / 2));
}

TEST_CASE("walls from the grid: unknown, open, wall; either half of the side decides a wall") {
  mapping::GridGeometry g;
  g.width_cells = 2;
  g.height_cells = 1;
  g.subcells = 3;
  const float prior = -0.405465f;  // l(0.4): not 0, so "unknown" is not "open"
  mapping::OccupancyGrid grid(g, prior);
  const Cell a{0, 0}, b{1, 0};
  CHECK(mapping::band_middle(Heading::north, 5) == LocalSubCell{0, 2});
  CHECK(mapping::band_middle(Heading::east, 5) == LocalSubCell{2, 4});
  CHECK(mapping::band_middle(Heading::south, 5) == LocalSubCell{4, 2});
  CHECK(mapping::band_middle(Heading::west, 5) == LocalSubCell{2, 0});

  CHECK(mapping::side_state(grid, prior, a, Heading::east) == SideState::unknown);
  CHECK(mapping::side_state(grid, prior, a, Heading::north) == SideState::unknown);
  // Corners do not count.
  grid.at(a, LocalSubCell{0, 2}) = 0.4f;
  CHECK(mapping::side_state(grid, prior, a, Heading::north) == SideState::unknown);
  // a's half of the shared side seen free: open, from both cells.
  grid.at(a, LocalSubCell{1, 2}) = -0.85f;
  CHECK(mapping::side_state(grid, prior, a, Heading::east) == SideState::open);
  CHECK(mapping::side_state(grid, prior, b, Heading::west) == SideState::open);
  // b's half seen occupied (the hit landed beyond the boundary): a wall, from both cells.
  grid.at(b, LocalSubCell{1, 0}) = 0.41f;
  CHECK(mapping::side_state(grid, prior, a, Heading::east) == SideState::wall);
  CHECK(mapping::side_state(grid, prior, b, Heading::west) == SideState::wall);
  // Exactly 0 (p = 0.5) is not "more likely occupied".
  grid.at(b, LocalSubCell{1, 0}) = 0.0f;
  CHECK(mapping::side_state(grid, prior, a, Heading::east) == SideState::open);
  // The outer boundary has one half only.
  grid.at(b, LocalSubCell{1, 2}) = 0.41f;
  CHECK(mapping::side_state(grid, prior, b, Heading::east) == SideState::wall);
  CHECK(mapping::to_char(SideState::wall) == 'W');
}
