#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/random.hpp"
#include "sensing/bump_depth_marks.hpp"

using sensing::LogOddsGrid;
using sensing::BumpDepthOptions;
using sensing::BumpDepthSensor;
using sensing::PoseStep;

namespace {

// 5 x 5 cells of 1 m over [0, 5] x [0, 5], base 10; bumpers 1 m from the centre, nine depth
// rays 57 deg across (7.125 deg apart, depth_5 straight ahead), max 10 m.
BumpDepthOptions five_by_five() {
  BumpDepthOptions o;
  o.cells_x = 5;
  o.cells_y = 5;
  o.x_end_m = 5.0;
  o.y_end_m = 5.0;
  o.bump_radius_m = 1.0;
  o.depth_angles_deg = {28.5, 21.375, 14.25, 7.125, 0.0, -7.125, -14.25, -21.375, -28.5};
  o.depth_max_m = 10.0;
  return o;
}

std::string matrix(const LogOddsGrid &g) {
  std::string out;
  for (int j = g.cells_y - 1; j >= 0; --j) {
    for (int i = 0; i < g.cells_x; ++i) out += fmt::format("{}{:+.3f}", i == 0 ? "" : " ", g.at(i, j));
    out += "\n";
  }
  return out;
}

// The rule written out independently: three sets of cells per step, then occupied, else
// free, else ray; cells found by dividing by the cell size, rays stepped by accumulation.
std::vector<double> reference(const BumpDepthOptions &o, BumpDepthSensor sensor, const std::vector<PoseStep> &steps) {
  const double w = (o.x_end_m - o.x_start_m) / o.cells_x, h = (o.y_end_m - o.y_start_m) / o.cells_y;
  const double l0 = std::log10(o.prior / (1 - o.prior));
  std::vector<double> l(static_cast<std::size_t>(o.cells_x * o.cells_y), l0);
  for (const PoseStep &s : steps) {
    std::set<int> occ, free, ray;
    const auto put = [&](std::set<int> &into, double x, double y) {
      const int i = static_cast<int>(std::floor((x - o.x_start_m) / w)), j = static_cast<int>(std::floor((y - o.y_start_m) / h));
      if (x >= o.x_start_m && y >= o.y_start_m && i < o.cells_x && j < o.cells_y) into.insert(j * o.cells_x + i);
    };
    put(free, s.x_m, s.y_m);
    if (sensor == BumpDepthSensor::bump) {
      const double pi = std::acos(-1.0);
      const double offsets[] = {-pi / 4, pi / 4, 0.0};
      const bool pressed[] = {s.bump_right, s.bump_left, s.bump_front};
      for (int n = 0; n < 3; ++n) {
        put(pressed[n] ? occ : free, s.x_m + o.bump_radius_m * std::cos(s.theta_rad + offsets[n]),
            s.y_m + o.bump_radius_m * std::sin(s.theta_rad + offsets[n]));
      }
    } else {
      for (int n = 0; n < 9; ++n) {
        const double z = s.depth_m[static_cast<std::size_t>(n)];
        if (z <= 0 || z >= o.depth_max_m) continue;
        const double a = s.theta_rad + o.depth_angles_deg[static_cast<std::size_t>(n)] * std::acos(-1.0) / 180;
        for (int k = 0; k * std::min(w, h) < z; ++k) put(ray, s.x_m + k * std::min(w, h) * std::cos(a), s.y_m + k * std::min(w, h) * std::sin(a));
        put(occ, s.x_m + z * std::cos(a), s.y_m + z * std::sin(a));
      }
    }
    for (int c = 0; c < o.cells_x * o.cells_y; ++c) {
      const double p = occ.count(c) ? 0.99999 : free.count(c) ? 0.3 : ray.count(c) ? 0.4 : o.prior;
      l[static_cast<std::size_t>(c)] += std::log10(p / (1 - p)) - l0;
    }
  }
  return l;
}

}  // namespace

TEST_CASE("bump marks: front pressed +5.000, the robot's cell and the side bumpers -0.368") {
  const BumpDepthOptions o = five_by_five();
  LogOddsGrid g = sensing::make_log_odds_grid(o);
  PoseStep s;
  s.x_m = 2.5, s.y_m = 2.5, s.theta_rad = 0.0, s.bump_front = true;
  sensing::apply_bump_depth_marks(o, BumpDepthSensor::bump, s, g);
  CHECK(matrix(g) ==
        "+0.000 +0.000 +0.000 +0.000 +0.000\n"
        "+0.000 +0.000 +0.000 -0.368 +0.000\n"
        "+0.000 +0.000 -0.368 +5.000 +0.000\n"
        "+0.000 +0.000 +0.000 -0.368 +0.000\n"
        "+0.000 +0.000 +0.000 +0.000 +0.000\n");
}

TEST_CASE("depth marks: the ray's cells -0.176, its end +5.000, the robot's cell -0.368; 0 and max ignored") {
  const BumpDepthOptions o = five_by_five();
  LogOddsGrid g = sensing::make_log_odds_grid(o);
  PoseStep s;
  s.x_m = 0.5, s.y_m = 2.5, s.theta_rad = 0.0;
  s.depth_m = {0, 0, 0, 0, 3.0, 0, 10.0, 0, 0};  // depth_5 straight ahead; depth_7 at max
  sensing::apply_bump_depth_marks(o, BumpDepthSensor::depth, s, g);
  CHECK(matrix(g) ==
        "+0.000 +0.000 +0.000 +0.000 +0.000\n"
        "+0.000 +0.000 +0.000 +0.000 +0.000\n"
        "-0.368 -0.176 -0.176 +5.000 +0.000\n"
        "+0.000 +0.000 +0.000 +0.000 +0.000\n"
        "+0.000 +0.000 +0.000 +0.000 +0.000\n");
}

TEST_CASE("depth marks: axial readings (depth along the sensor's axis) from a sensor ahead of the centre") {
  BumpDepthOptions o = five_by_five();
  o.depth_reading = sensing::DepthReading::axial;
  o.depth_origin_x_m = 1.0;  // the sensor 1 m ahead: at (1.5, 2.5)
  o.depth_angles_deg[0] = 60.0;
  LogOddsGrid g = sensing::make_log_odds_grid(o);
  PoseStep s;
  s.x_m = 0.5, s.y_m = 2.5, s.theta_rad = 0.0;
  // depth_5 straight ahead: 2 m along the axis is 2 m of range, to (3.5, 2.5); depth_1 at 60 deg:
  // 1 m along the axis is 2 m of range, to (2.5, 4.23).
  s.depth_m = {1.0, 0, 0, 0, 2.0, 0, 0, 0, 0};
  sensing::apply_bump_depth_marks(o, BumpDepthSensor::depth, s, g);
  CHECK(matrix(g) ==
        "+0.000 +0.000 +5.000 +0.000 +0.000\n"
        "+0.000 +0.000 -0.176 +0.000 +0.000\n"
        "-0.368 -0.176 -0.176 +5.000 +0.000\n"
        "+0.000 +0.000 +0.000 +0.000 +0.000\n"
        "+0.000 +0.000 +0.000 +0.000 +0.000\n");
  o.depth_angles_deg[0] = 90.0;
  CHECK_THROWS_WITH_AS(sensing::validate(o), "--depth-reading axial needs every depth angle within (-90, 90) degrees (got 90)",
                       common::InputError);
}

TEST_CASE("bump and depth marks: the same grid as the rule written out, on random poses and readings") {
  common::Rng rng(17);
  for (int trial = 0; trial < 40; ++trial) {
    BumpDepthOptions o = five_by_five();
    o.cells_x = 5 + static_cast<int>(rng.uniform(0, 40));
    o.cells_y = 5 + static_cast<int>(rng.uniform(0, 40));
    o.x_start_m = rng.uniform(-5, 0), o.x_end_m = rng.uniform(1, 6);
    o.y_start_m = rng.uniform(-5, 0), o.y_end_m = rng.uniform(1, 6);
    o.bump_radius_m = rng.uniform(0.1, 0.5);
    const BumpDepthSensor sensor = trial % 2 ? BumpDepthSensor::depth : BumpDepthSensor::bump;
    std::vector<PoseStep> steps(30);
    for (PoseStep &s : steps) {
      s.x_m = rng.uniform(o.x_start_m - 1, o.x_end_m + 1), s.y_m = rng.uniform(o.y_start_m - 1, o.y_end_m + 1);
      s.theta_rad = rng.uniform(-4, 4);
      s.bump_right = rng.uniform01() < 0.3, s.bump_left = rng.uniform01() < 0.3, s.bump_front = rng.uniform01() < 0.3;
      for (double &z : s.depth_m) z = rng.uniform01() < 0.1 ? 0.0 : rng.uniform(0.0, 12.0);
    }
    LogOddsGrid g = sensing::make_log_odds_grid(o);
    for (const PoseStep &s : steps) sensing::apply_bump_depth_marks(o, sensor, s, g);
    const auto expected = reference(o, sensor, steps);
    CAPTURE(trial);
    REQUIRE(g.log_odds.size() == expected.size());
    for (std::size_t c = 0; c < expected.size(); ++c) CHECK(g.log_odds[c] == doctest::Approx(expected[c]).epsilon(1e-9));
  }
}

TEST_CASE("bump and depth marks: bad options are refused with what was wrong") {
  BumpDepthOptions o = five_by_five();
  o.x_end_m = 0.0;
  CHECK_THROWS_WITH_AS(sensing::validate(o), "--boundary: XS must be less than XE (got 0 and 0)", common::InputError);
  o = five_by_five();
  o.cells_x = 0;
  CHECK_THROWS_WITH_AS(sensing::validate(o), "--cells must be X,Y with each 1 to 2000 (got 0,5)", common::InputError);
  o = five_by_five();
  o.prior = 1.0;
  CHECK_THROWS_WITH_AS(sensing::validate(o), "--prior must be in (0, 1) (got 1)", common::InputError);
}
