// LidarScan::median_range: what the cell model reads a side through, so that a lone dropped
// or spiked beam cannot flip a wall.

#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "common/random.hpp"
#include "full_circle_scan.hpp"
#include "sensing/scan.hpp"
#include "test_values.hpp"

namespace {

// median_range as first written (a vector per call): the reference the allocation-free one
// must match bit for bit.
std::optional<float> reference_median(const sensing::LidarScan &s, int centre, double half_window_rad) {
  const int n = s.beam_count();
  const double step = s.fov_rad / n;
  const bool full = s.fov_rad >= 2.0 * std::numbers::pi - 1e-9;
  const int reach = std::min(static_cast<int>(half_window_rad / step), (n - 1) / 2);
  std::vector<float> valid;
  for (int offset = -reach; offset <= reach; ++offset) {
    int i = centre + offset;
    if (full) i = ((i % n) + n) % n;
    if (i < 0 || i >= n) continue;
    const float r = s.ranges[static_cast<std::size_t>(i)];
    const sensing::ReadingKind k = s.kind_of(r);
    if (k == sensing::ReadingKind::invalid) continue;
    valid.push_back(k == sensing::ReadingKind::no_return ? kFloatInf : r);
  }
  if (valid.empty()) return std::nullopt;
  const auto returns = std::count_if(valid.begin(), valid.end(), [](float v) { return std::isfinite(v); });
  if (returns >= 2) std::erase_if(valid, [](float v) { return !std::isfinite(v); });
  const auto middle = valid.begin() + static_cast<std::ptrdiff_t>((valid.size() - 1) / 2);
  std::nth_element(valid.begin(), middle, valid.end());
  return *middle;
}

}  // namespace

TEST_CASE("median_range: a lone dropout or spike among five 1-degree beams is outvoted") {
  std::vector<float> r(360, 0.5f);
  r[180] = kFloatInf;
  CHECK(*full_circle(r).median_range(180, 2.5 * kDeg) == 0.5f);
  r[180] = 0.5f;
  r[90] = 7.0f;                       // a spike beside a wall
  CHECK(*full_circle(r).median_range(90, 2.5 * kDeg) == 0.5f);
  std::vector<float> open(360, kFloatInf);
  open[270] = 0.2f;                   // a spike into an opening
  CHECK(std::isinf(*full_circle(open).median_range(270, 2.5 * kDeg)));
}

TEST_CASE("median_range: invalid readings are left out; none valid gives nothing") {
  std::vector<float> r(360, kFloatNaN);
  CHECK_FALSE(full_circle(r).median_range(0, 2.5 * kDeg).has_value());
  r[359] = 1.0f;                      // wraps around beam 0
  r[1] = -1.0f;
  CHECK(*full_circle(r).median_range(0, 2.5 * kDeg) == 1.0f);
}

TEST_CASE("median_range: beams further apart than the window read one beam, as before") {
  const std::vector<float> r{1.0f, kFloatInf, 2.0f, 3.0f};
  CHECK(*full_circle(r).median_range(2, 2.5 * kDeg) == 2.0f);
  CHECK(std::isinf(*full_circle(r).median_range(1, 2.5 * kDeg)));
}

TEST_CASE("median_range: the same reading, bit for bit, as the reference, on any window") {
  common::Rng rng(77);
  const float pool[] = {0.5f, 0.5f, 0.51f, 0.0f, -0.0f, kFloatInf, -kFloatInf, kFloatNaN, -1.0f, 0.01f, 12.0f, 12.5f, 3.0f};
  int compared = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    CAPTURE(trial);
    const int n = 1 + static_cast<int>(rng.below(rng.uniform01() < 0.5 ? 12 : 400));
    std::vector<float> r(static_cast<std::size_t>(n));
    for (float &v : r) {
      v = rng.uniform01() < 0.5 ? pool[rng.below(std::size(pool))] : static_cast<float>(rng.uniform(0.0, 13.0));
    }
    sensing::LidarScan s = full_circle(r);
    s.min_range_m = rng.uniform01() < 0.3 ? 0.0 : 0.05;
    if (rng.uniform01() < 0.5) s.fov_rad = rng.uniform(0.01, 6.28);
    const int centre = static_cast<int>(rng.below(static_cast<std::uint64_t>(n)));
    // Windows from one beam to past the small buffer (the fallback) and the whole scan.
    const double half_window_rad = rng.uniform01() < 0.1 ? -0.1 : rng.uniform(0.0, rng.uniform01() < 0.7 ? 0.1 : 3.5);
    CAPTURE(n);
    CAPTURE(centre);
    CAPTURE(half_window_rad);
    const std::optional<float> expected = reference_median(s, centre, half_window_rad);
    const std::optional<float> got = s.median_range(centre, half_window_rad);
    REQUIRE(got.has_value() == expected.has_value());
    if (got) {
      CHECK(std::bit_cast<std::uint32_t>(*got) == std::bit_cast<std::uint32_t>(*expected));
      ++compared;
    }
  }
  CHECK(compared > 15000);
}
