// LidarScan::median_range: what the cell model reads a side through, so that a lone dropped
// or spiked beam cannot flip a wall (issue 9).

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "mapping/scan.hpp"

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr double kDeg = std::numbers::pi / 180.0;

mapping::LidarScan full_circle(const std::vector<float> &ranges) {
  mapping::LidarScan s;
  s.fov_rad = 2.0 * std::numbers::pi;
  s.min_range_m = 0.05;
  s.max_range_m = 12.0;
  s.ranges = ranges;
  return s;
}

}  // namespace

TEST_CASE("median_range: a lone dropout or spike among five 1-degree beams is outvoted") {
  std::vector<float> r(360, 0.5f);
  r[180] = kInf;
  CHECK(*full_circle(r).median_range(180, 2.5 * kDeg) == 0.5f);
  r[180] = 0.5f;
  r[90] = 7.0f;                       // a spike beside a wall
  CHECK(*full_circle(r).median_range(90, 2.5 * kDeg) == 0.5f);
  std::vector<float> open(360, kInf);
  open[270] = 0.2f;                   // a spike into an opening
  CHECK(std::isinf(*full_circle(open).median_range(270, 2.5 * kDeg)));
}

TEST_CASE("median_range: invalid readings are left out; none valid gives nothing") {
  std::vector<float> r(360, kNaN);
  CHECK_FALSE(full_circle(r).median_range(0, 2.5 * kDeg).has_value());
  r[359] = 1.0f;                      // wraps around beam 0
  r[1] = -1.0f;
  CHECK(*full_circle(r).median_range(0, 2.5 * kDeg) == 1.0f);
}

TEST_CASE("median_range: beams further apart than the window read one beam, as before") {
  const std::vector<float> r{1.0f, kInf, 2.0f, 3.0f};
  CHECK(*full_circle(r).median_range(2, 2.5 * kDeg) == 2.0f);
  CHECK(std::isinf(*full_circle(r).median_range(1, 2.5 * kDeg)));
}
