// The range-filtering stage (mapping/scan_filter.hpp): faulty beams become "no information"
// (NaN) before any model marks the scan, and what a fault-free lidar sees passes unchanged
// (issue 9).

#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "common/random.hpp"
#include "mapping/models.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/scan_filter.hpp"
#include "mapping/sensor_model.hpp"

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr double kDeg = std::numbers::pi / 180.0;

mapping::LidarScan full_circle(const std::vector<float> &ranges) {
  mapping::LidarScan s;
  s.origin = {0.5, 0.5};
  s.yaw_rad = std::numbers::pi / 2.0;
  s.fov_rad = 2.0 * std::numbers::pi;
  s.min_range_m = 0.05;
  s.max_range_m = 12.0;
  s.ranges = ranges;
  return s;
}

std::vector<float> filtered(const std::vector<float> &ranges,
                            const mapping::ScanFilterOptions &options = {}) {
  mapping::ScanFilter filter(options);
  const mapping::LidarScan out = filter.apply(full_circle(ranges));
  return {out.ranges.begin(), out.ranges.end()};
}

// Readings as text, one per beam: the value to two decimals, "inf", or "-" (no information).
std::string text(const std::vector<float> &r, int from, int to) {
  std::string out;
  for (int i = from; i <= to; ++i) {
    const float v = r[static_cast<std::size_t>(i)];
    if (!out.empty()) out += ' ';
    if (std::isnan(v)) {
      out += '-';
    } else if (std::isinf(v)) {
      out += "inf";
    } else {
      out += std::to_string(std::lround(v * 100.0f));
    }
  }
  return out;
}

// `r` with the beams `gone` read as no information.
std::vector<float> without(std::vector<float> r, std::initializer_list<int> gone) {
  for (const int i : gone) r[static_cast<std::size_t>(i)] = kNaN;
  return r;
}

// What a 1-degree lidar at the centre of a 1 m cell reads when the cell is closed on every
// side (12 mm walls): 0.494 / cos of the angle to the nearest side's normal.
std::vector<float> closed_cell() {
  std::vector<float> r(360);
  for (int i = 0; i < 360; ++i) {
    const double a = std::remainder(i * kDeg, std::numbers::pi / 2.0);
    r[static_cast<std::size_t>(i)] = static_cast<float>(0.494 / std::cos(a));
  }
  return r;
}

}  // namespace

TEST_CASE("scan filter: what a fault-free lidar sees passes unchanged") {
  const std::vector<float> cell = closed_cell();
  CHECK(text(filtered(cell), 0, 359) == text(cell, 0, 359));
  // A wall seen at a grazing angle: the range grows by up to 10 % a beam out to 80 degrees,
  // then a nearer wall cuts it off (a depth step on both sides).
  std::vector<float> corridor(360, 0.494f);
  for (int i = 0; i <= 80; ++i) corridor[static_cast<std::size_t>(100 + i)] = static_cast<float>(0.494 / std::cos(i * kDeg));
  corridor[181] = 1.6f;
  CHECK(text(filtered(corridor), 95, 185) == text(corridor, 95, 185));
  // A real view past max range, wider than a few beams, stays a no return.
  std::vector<float> open(360, 1.5f);
  for (int i = 170; i < 190; ++i) open[static_cast<std::size_t>(i)] = kInf;
  CHECK(text(filtered(open), 165, 195) == text(open, 165, 195));
  // Down a corridor longer than max range: its walls, seen at a grazing angle, return up to
  // near 12 m on both sides of a few no returns; those are a view, not dropped beams.
  std::vector<float> corridor_end(360, 1.5f);
  for (int i = 0; i < 8; ++i) {
    corridor_end[static_cast<std::size_t>(170 + i)] = static_cast<float>(0.494 / std::sin((10 - i) * kDeg));
    corridor_end[static_cast<std::size_t>(190 - i)] = corridor_end[static_cast<std::size_t>(170 + i)];
  }
  for (int i = 178; i <= 182; ++i) corridor_end[static_cast<std::size_t>(i)] = kInf;
  CHECK(corridor_end[177] > 9.0f);  // 3 degrees off the axis; at 2 degrees 14 m
  CHECK(text(filtered(corridor_end), 165, 195) == text(corridor_end, 165, 195));
  // Nothing returns at all (an empty hall): every no return stands.
  const std::vector<float> nothing(360, kInf);
  CHECK(text(filtered(nothing), 0, 359) == text(nothing, 0, 359));
}

TEST_CASE("scan filter: a spike that agrees with neither neighbour is no information") {
  std::vector<float> r = closed_cell();
  r[180] = 7.3f;   // through the wall ahead
  r[90] = 0.2f;    // a phantom obstacle
  r[0] = 3.0f;     // beside a no return, across the wrap
  r[1] = kInf;
  const std::vector<float> expected = without(r, {180, 90, 0, 1});  // beam 1: a dropped beam
  const std::vector<float> f = filtered(r);
  CHECK(text(f, 0, 359) == text(expected, 0, 359));
  CHECK(text(f, 178, 182) == "49 49 - 49 49");
}

TEST_CASE("scan filter: two spikes side by side cannot vouch for each other") {
  std::vector<float> r = closed_cell();
  // Agreeing with each other, further than both sides: a view through a wall.
  r[200] = 3.05f;
  r[201] = 3.17f;
  // Disagreeing, one between its neighbours at first: rejected in a later round.
  r[300] = 2.0f;
  r[301] = 6.0f;
  mapping::ScanFilter filter;
  const mapping::LidarScan out = filter.apply(full_circle(r));
  const std::vector<float> f(out.ranges.begin(), out.ranges.end());
  CHECK(text(f, 0, 359) == text(without(r, {200, 201, 300, 301}), 0, 359));
  CHECK(filter.counts().spikes == 4);
  CHECK(filter.counts().dropouts == 0);
}

TEST_CASE("scan filter: a short run of no returns between returns is dropped beams") {
  std::vector<float> r = closed_cell();
  for (int i = 10; i < 16; ++i) r[static_cast<std::size_t>(i)] = kInf;   // 6 beams: dropped
  for (int i = 100; i < 107; ++i) r[static_cast<std::size_t>(i)] = kInf;  // 7 beams: a view
  r[359] = kInf;  // wraps around beam 0
  mapping::ScanFilter filter;
  const mapping::LidarScan out = filter.apply(full_circle(r));
  const std::vector<float> f(out.ranges.begin(), out.ranges.end());
  CHECK(text(f, 0, 359) == text(without(r, {10, 11, 12, 13, 14, 15, 359}), 0, 359));
  CHECK(text(f, 99, 107) == "50 inf inf inf inf inf inf inf 52");
  CHECK(filter.counts().dropouts == 7);
  mapping::ScanFilterOptions longer;
  longer.max_dropout_run = 7;
  CHECK(text(filtered(r, longer), 99, 107) == "50 - - - - - - - 52");
  mapping::ScanFilterOptions none;
  none.max_dropout_run = 0;
  CHECK(text(filtered(r, none), 0, 359) == text(r, 0, 359));
}

TEST_CASE("scan filter: a partial field of view keeps no returns at its ends") {
  std::vector<float> r{kInf, kInf, 1.0f, 1.0f, kInf, 1.0f, 1.0f, kInf};
  mapping::LidarScan s = full_circle(r);
  s.fov_rad = 8 * kDeg;
  mapping::ScanFilter filter;
  const mapping::LidarScan out = filter.apply(s);
  CHECK(text({out.ranges.begin(), out.ranges.end()}, 0, 7) == "inf inf 100 100 - 100 100 inf");
}

TEST_CASE("scan filter: NaN, negative and below-minimum readings are no information") {
  std::vector<float> r = closed_cell();
  r[45] = kNaN;
  r[46] = -0.5f;
  r[47] = 0.01f;
  r[48] = -kInf;
  mapping::ScanFilter filter;
  const mapping::LidarScan out = filter.apply(full_circle(r));
  CHECK(text({out.ranges.begin(), out.ranges.end()}, 0, 359) == text(without(r, {45, 46, 47, 48}), 0, 359));
  CHECK(filter.counts().invalid == 4);
  // The scan's pose and limits are kept; only the ranges are the filter's.
  CHECK(out.origin.x_m == 0.5);
  CHECK(out.yaw_rad == std::numbers::pi / 2.0);
  CHECK(out.beam_count() == 360);
  CHECK(out.max_range_m == 12.0);
}

TEST_CASE("scan filter: NaN and negative readings are never stored in the grid") {
  mapping::GridGeometry g;
  g.width_cells = 3;
  g.height_cells = 3;
  g.subcells = 3;
  const mapping::SensorModel model;
  for (const mapping::ModelKind kind : {mapping::ModelKind::cell, mapping::ModelKind::ray}) {
    CAPTURE(mapping::to_string(kind));
    mapping::MappingOptions options;
    options.kind = kind;
    mapping::ScanFilter filter;
    mapping::ScanUpdate update;
    // Nothing valid at all: nothing is updated but the centre the robot stands on (the cell
    // model frees it whatever the lidar says).
    std::vector<float> bad(360);
    for (std::size_t i = 0; i < bad.size(); ++i) bad[i] = i % 3 == 0 ? kNaN : (i % 3 == 1 ? -1.0f : -kInf);
    mapping::OccupancyGrid grid(g, 0.0f);
    mapping::LidarScan scan = full_circle(bad);
    scan.origin = {1.5, 1.5};
    const std::size_t expected = kind == mapping::ModelKind::cell ? 1 : 0;
    CHECK(mapping::integrate_scan(options, grid, filter.apply(scan), mapping::Cell{1, 1}, model, update) == expected);
    int changed = 0;
    for (int y = 0; y < g.height_subcells(); ++y) {
      for (int x = 0; x < g.width_subcells(); ++x) changed += grid.at(mapping::SubCell{x, y}) != 0.0f ? 1 : 0;
    }
    CHECK(changed == static_cast<int>(expected));
    // Every other beam invalid, the rest a closed cell: every value stored is finite.
    std::vector<float> mixed = closed_cell();
    for (std::size_t i = 0; i < mixed.size(); i += 2) mixed[i] = i % 4 == 0 ? kNaN : -0.3f;
    scan.ranges = mixed;
    CHECK(mapping::integrate_scan(options, grid, filter.apply(scan), mapping::Cell{1, 1}, model, update) > 0);
    for (int y = 0; y < g.height_subcells(); ++y) {
      for (int x = 0; x < g.width_subcells(); ++x) {
        CAPTURE(x);
        CAPTURE(y);
        CHECK(std::isfinite(grid.at(mapping::SubCell{x, y})));
      }
    }
    CHECK(grid.at(mapping::Cell{1, 1}, mapping::LocalSubCell{0, 1}) > 0.0f);  // the north wall
  }
}

TEST_CASE("scan filter: any scan comes out the same size, each reading kept or no information") {
  common::Rng rng(9);
  for (int trial = 0; trial < 2000; ++trial) {
    CAPTURE(trial);
    const int n = static_cast<int>(rng.uniform(0.0, 40.0));
    std::vector<float> r(static_cast<std::size_t>(n));
    for (float &v : r) {
      const double u = rng.uniform01();
      v = u < 0.2 ? kInf : (u < 0.25 ? kNaN : (u < 0.3 ? -1.0f : static_cast<float>(rng.uniform(0.0, 13.0))));
    }
    mapping::LidarScan s = full_circle(r);
    if (trial % 2 == 1) s.fov_rad = n * kDeg;  // a partial field of view
    mapping::ScanFilter filter;
    const mapping::LidarScan out = filter.apply(s);
    REQUIRE(out.beam_count() == n);
    std::size_t gone = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const float v = out.ranges[i];
      const bool kept = v == r[i] || (std::isnan(v) && std::isnan(r[i]));
      CHECK((kept || std::isnan(v)));
      CHECK_FALSE((std::isnan(v) == false && s.kind_of(v) == mapping::ReadingKind::invalid));
      if (std::isnan(v)) ++gone;
    }
    const mapping::ScanFilterCounts &c = filter.counts();
    CHECK(c.invalid + c.spikes + c.dropouts == gone);
  }
}

TEST_CASE("scan filter: options checked, messages to the letter") {
  const auto error_of = [](const mapping::ScanFilterOptions &o) {
    try {
      mapping::validate(o);
    } catch (const common::InputError &e) {
      return e.diagnostic();
    }
    return std::string("no error");
  };
  mapping::ScanFilterOptions o;
  CHECK(error_of(o) == "no error");
  CHECK(o.spike_tolerance_m() == doctest::Approx(0.1));
  CHECK(o.grazing_step(kDeg) == doctest::Approx(0.099).epsilon(0.01));
  o.range_noise_m = -0.1;
  CHECK(error_of(o) == "error: scan filter: range noise must be a finite number of m >= 0 (got -0.1)");
  o = {};
  o.neighbour_reach = 0;
  CHECK(error_of(o) == "error: scan filter: neighbour reach must be 1 to 10 beams (got 0)");
  o = {};
  o.max_see_through = 9;
  CHECK(error_of(o) == "error: scan filter: see-through cluster must be 1 to 8 beams (got 9)");
  o = {};
  o.max_grazing_rad = 2.0;
  CHECK(error_of(o) == "error: scan filter: grazing angle must be at least 0 and below pi/2 rad (got 2)");
  o = {};
  o.max_dropout_run = 33;
  CHECK(error_of(o) == "error: scan filter: dropout run must be 0 to 32 beams (got 33)");
}
