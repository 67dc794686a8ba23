// The ray model's fast path against a deliberately simple reference: trace_ray, the rules of
// models.hpp written out, std::set for "one update per sub-cell per scan, occupied wins".
// Many random scans are integrated both ways and every value must match bit for bit.

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include "common/random.hpp"
#include "mapping/log_odds.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "mapping/traversal.hpp"
#include "sensing/ray_model.hpp"
#include "sensing/scan.hpp"
#include "sensing/setups.hpp"
#include "test_values.hpp"

namespace {

using mapping::GridGeometry;
using sensing::ModelOptions;
using mapping::OccupancyGrid;
using mapping::SubCell;

bool interior(SubCell s, int k) {
  const mapping::LocalSubCell l = mapping::local_of(s, k);
  return l.i > 0 && l.i < k - 1 && l.j > 0 && l.j < k - 1;
}

bool same_cell(SubCell a, SubCell b, int k) {
  const mapping::Cell ca = mapping::cell_of(a, k);
  const mapping::Cell cb = mapping::cell_of(b, k);
  return ca.x == cb.x && ca.y == cb.y;
}

// One beam by the rules of models.hpp. path[n] is the n-th sub-cell the beam passes (with
// the path length at which it leaves it); the end is the first one it does not leave before
// `length`. Before the end: interior sub-cells free, and the two sub-cells beside each cell
// side crossed. The end and hit_depth sub-cells behind it occupied (a return), or free by the
// same rule (no return). A no-return beam that leaves the grid crossed its outer side.
struct Marks {
  std::set<std::size_t> free, occupied;
};

void reference_beam(const ModelOptions &options, const OccupancyGrid &grid, mapping::Point origin,
                    double dir_x, double dir_y, double length, bool hit, Marks &marks) {
  const int k = grid.k();
  std::vector<SubCell> path;
  int end = -1;
  mapping::trace_ray(grid.geometry(), origin, dir_x, dir_y, [&](SubCell s, double exit_m) {
    path.push_back(s);
    if (end < 0 && !(exit_m < length)) end = static_cast<int>(path.size()) - 1;
    if (end < 0) return true;
    return hit && static_cast<int>(path.size()) - 1 - end < options.hit_depth;
  });
  const int n = static_cast<int>(path.size());
  const auto at = [&](int m) { return path[static_cast<std::size_t>(m)]; };
  const auto crossed_into = [&](int m) { return m > 0 && m < n && !same_cell(at(m - 1), at(m), k); };
  const int passed = end < 0 ? n : (hit ? end : end + 1);
  for (int m = 0; m < passed; ++m) {
    const bool left_grid = !hit && end < 0 && m == n - 1;
    if (interior(at(m), k) || crossed_into(m) || crossed_into(m + 1) || left_grid) {
      marks.free.insert(grid.index(at(m)));
    }
  }
  if (hit && end >= 0) {
    for (int m = end; m < n; ++m) marks.occupied.insert(grid.index(at(m)));
  }
}

Marks reference_marks(const ModelOptions &options, const OccupancyGrid &grid,
                      const sensing::LidarScan &scan) {
  Marks marks;
  const double cy = std::cos(scan.yaw_rad);
  const double sy = std::sin(scan.yaw_rad);
  for (int i = 0; i < scan.beam_count(); ++i) {
    const sensing::ReadingKind kind = scan.kind(i);
    if (kind == sensing::ReadingKind::invalid) continue;
    const bool hit = kind == sensing::ReadingKind::hit;
    if (!hit && (options.ignore_no_return || scan.lone_no_return(i))) continue;
    const double c = std::cos(scan.beam_angle_rad(i));
    const double s = std::sin(scan.beam_angle_rad(i));
    const double length = hit ? static_cast<double>(scan.ranges[static_cast<std::size_t>(i)]) : scan.max_range_m;
    reference_beam(options, grid, scan.origin, cy * c - sy * s, sy * c + cy * s, length, hit, marks);
  }
  return marks;
}

std::size_t reference_apply(const Marks &marks, const mapping::SensorModel &model, OccupancyGrid &grid) {
  const auto &clamp = model.options().clamp;
  std::size_t updated = 0;
  for (const std::size_t i : marks.occupied) {
    if (i >= grid.size()) continue;
    grid.at_index(i) = static_cast<float>(mapping::apply(grid.at_index(i), model.occupied_increment(), clamp));
    ++updated;
  }
  for (const std::size_t i : marks.free) {
    if (i >= grid.size() || marks.occupied.count(i) != 0) continue;
    grid.at_index(i) = static_cast<float>(mapping::apply(grid.at_index(i), model.free_increment(), clamp));
    ++updated;
  }
  return updated;
}

// A reading: mostly returns, some no return (+inf or beyond max range), some invalid.
float random_range(common::Rng &rng, double max_range_m, double span_m) {
  const std::uint64_t pick = rng.below(40);
  if (pick == 0) return std::numeric_limits<float>::infinity();
  if (pick == 1) return static_cast<float>(max_range_m * 1.5);
  if (pick == 2) return std::numeric_limits<float>::quiet_NaN();
  if (pick == 3) return 0.01f;  // below min range
  if (pick == 4) return -1.0f;
  if (pick == 5) return 0.05f;  // exactly min range: a return
  if (pick < 9) return static_cast<float>(rng.uniform(0.05, max_range_m));
  return static_cast<float>(rng.uniform(0.05, span_m));
}

struct Setup {
  GridGeometry geometry;
  mapping::SensorModelOptions sensor;
  ModelOptions options;
};

Setup random_setup(common::Rng &rng, int k) {
  Setup s;
  s.geometry.subcells = k;
  s.geometry.width_cells = 1 + static_cast<int>(rng.below(9));
  s.geometry.height_cells = 1 + static_cast<int>(rng.below(9));
  const double sizes[] = {1.0, 0.1, 0.37, 0.25};
  s.geometry.cell_size_m = sizes[rng.below(4)];
  if (rng.below(3) == 0) s.geometry.origin = {rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0)};
  if (rng.below(3) == 0) s.sensor.clamp = mapping::Clamp{-2.0, 3.5};
  if (rng.below(4) == 0) s.sensor.base = mapping::LogBase::ten;
  if (rng.below(4) == 0) s.sensor.prior = 0.45;
  s.options.kind = sensing::ModelKind::ray;
  s.options.hit_depth = static_cast<int>(rng.below(3));
  s.options.ignore_no_return = rng.below(4) == 0;
  return s;
}

// An origin inside the grid (now and then on a sub-cell corner or side, where ties happen),
// rarely outside it.
mapping::Point random_origin(common::Rng &rng, const GridGeometry &g) {
  const double w = g.width_cells * g.cell_size_m;
  const double h = g.height_cells * g.cell_size_m;
  if (rng.below(30) == 0) return {g.origin.x_m - 0.5, g.origin.y_m + h / 2};
  double x = rng.uniform(0.0, w);
  double y = rng.uniform(0.0, h);
  if (rng.below(4) == 0) {
    const double sub = g.subcell_size_m();
    x = std::floor(x / sub) * sub;
    if (rng.below(2) == 0) y = std::floor(y / sub) * sub;
  }
  return {g.origin.x_m + x, g.origin.y_m + y};
}

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

}  // namespace

TEST_CASE("ray model fast path: bit-identical to the reference over random scans") {
  common::Rng rng(8);
  int scans_checked = 0;
  for (const int k : {3, 5, 9}) {
    for (int world = 0; world < 25; ++world) {
      const Setup setup = random_setup(rng, k);
      const mapping::SensorModel model(setup.sensor);
      OccupancyGrid fast(setup.geometry, static_cast<float>(model.prior_log_odds()));
      OccupancyGrid slow(setup.geometry, static_cast<float>(model.prior_log_odds()));
      mapping::ScanUpdate update;  // one for all the scans of this world, as in the controller
      const double span_m = 1.2 * std::hypot(setup.geometry.width_cells, setup.geometry.height_cells) *
                            setup.geometry.cell_size_m;
      for (int n = 0; n < 12; ++n) {
        const int beam_counts[] = {360, 360, 90, 7, 1};
        const int beams = beam_counts[rng.below(5)];
        std::vector<float> ranges;
        sensing::LidarScan scan;
        scan.origin = random_origin(rng, setup.geometry);
        const std::uint64_t yaw_pick = rng.below(3);
        scan.yaw_rad = yaw_pick == 0 ? static_cast<double>(rng.below(8)) * kPi / 4
                                     : rng.uniform(-4.0, 4.0);
        scan.fov_rad = rng.below(4) == 0 ? rng.uniform(0.5, 2 * kPi) : 2 * kPi;
        scan.min_range_m = 0.05;
        scan.max_range_m = rng.below(2) == 0 ? 12.0 : span_m / 2;
        for (int b = 0; b < beams; ++b) ranges.push_back(random_range(rng, scan.max_range_m, span_m));
        if (rng.below(2) == 0) {  // a run of beams with no return (a lone one is skipped)
          const auto first = static_cast<std::size_t>(rng.below(static_cast<std::uint64_t>(beams)));
          const std::size_t run = 3 + static_cast<std::size_t>(rng.below(40));
          for (std::size_t b = first; b < ranges.size() && b < first + run; ++b) {
            ranges[b] = rng.below(2) == 0 ? std::numeric_limits<float>::infinity()
                                          : static_cast<float>(scan.max_range_m * 2);
          }
        }
        scan.ranges = ranges;
        const mapping::Cell robot = mapping::cell_of(
            fast.subcell_at(scan.origin).value_or(SubCell{0, 0}), setup.geometry.subcells);

        Marks expected = reference_marks(setup.options, slow, scan);
        sensing::mark_scan(setup.options, fast, scan, robot, update);
        // Marks from elsewhere in the same scan (as another model would add): some inside
        // the grid, one outside, duplicates and overlaps with the ray marks.
        if (n % 3 == 2) {
          for (int m = 0; m < 6; ++m) {
            const std::size_t i = static_cast<std::size_t>(rng.below(fast.size()));
            if (m % 2 == 0) {
              update.mark_free(i);
              expected.free.insert(i);
            } else {
              update.mark_occupied(i);
              expected.occupied.insert(i);
            }
          }
          update.mark_free(fast.size() + 3);
          update.mark_occupied(std::numeric_limits<std::size_t>::max());
        }
        const std::size_t fast_updated = update.apply(fast, model);
        const std::size_t slow_updated = reference_apply(expected, model, slow);
        REQUIRE(fast_updated == slow_updated);
        CHECK(update.empty());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < fast.size(); ++i) differing += bits(fast.at_index(i)) != bits(slow.at_index(i));
        INFO("K = " << k << ", world " << world << ", scan " << n << ", origin (" << scan.origin.x_m
                    << ", " << scan.origin.y_m << "), yaw " << scan.yaw_rad);
        REQUIRE(differing == 0);
        ++scans_checked;
      }
    }
  }
  CHECK(scans_checked == 3 * 25 * 12);
}

TEST_CASE("ray model fast path: the benchmark's workload matches the reference") {
  // The ray benchmark's workload shape, 30 scans: K = 5, 0.02 m sub-cells, 0.9 to 1.1 m returns.
  GridGeometry g;
  g.width_cells = 40;
  g.height_cells = 40;
  g.subcells = 5;
  g.cell_size_m = 0.1;
  const mapping::SensorModel model{mapping::SensorModelOptions{}};
  OccupancyGrid fast(g, static_cast<float>(model.prior_log_odds()));
  OccupancyGrid slow(g, static_cast<float>(model.prior_log_odds()));
  ModelOptions options;
  options.kind = sensing::ModelKind::ray;
  mapping::ScanUpdate update;
  common::Rng rng(20261121);
  std::vector<float> ranges(360);
  for (int s = 0; s < 30; ++s) {
    sensing::LidarScan scan;
    scan.origin = {1.5 + 0.01 * s, 2.0 + 0.3 * std::sin(0.01 * s)};
    scan.yaw_rad = 0.01 * s;
    scan.fov_rad = 2 * kPi;
    scan.min_range_m = 0.05;
    scan.max_range_m = 12.0;
    for (float &r : ranges) r = static_cast<float>(rng.uniform(0.9, 1.1));
    scan.ranges = ranges;
    const std::size_t fast_updated = sensing::integrate_scan(options, fast, scan, mapping::Cell{0, 0}, model, update);
    REQUIRE(fast_updated == reference_apply(reference_marks(options, slow, scan), model, slow));
  }
  for (std::size_t i = 0; i < fast.size(); ++i) REQUIRE(bits(fast.at_index(i)) == bits(slow.at_index(i)));
}

TEST_CASE("ray model: the dispatched kernel (AVX2 where the processor has it) marks as the SSE2 baseline") {
  // The same random scans marked by both builds of the kernel, and by the reference: every
  // value bit for bit. Short beams (within the grid's edges) walk in the four lanes, so a
  // third of the scans keep their returns near the robot.
  if (sensing::ray_kernel_isa() == sensing::RayKernelIsa::baseline) {
    MESSAGE("this processor has no AVX2: only the baseline kernel ran");
  }
  common::Rng rng(20261201);
  int scans_checked = 0;
  for (const int k : {3, 5, 7, 9}) {
    for (int world = 0; world < 12; ++world) {
      Setup setup = random_setup(rng, k);
      setup.geometry.width_cells += 8;  // room for beams that cannot reach the edge
      setup.geometry.height_cells += 4;
      const mapping::SensorModel model(setup.sensor);
      const float prior = static_cast<float>(model.prior_log_odds());
      OccupancyGrid baseline(setup.geometry, prior), dispatched(setup.geometry, prior), reference(setup.geometry, prior);
      mapping::ScanUpdate update_baseline, update_dispatched;
      const double cell_m = setup.geometry.cell_size_m;
      for (int n = 0; n < 10; ++n) {
        sensing::LidarScan scan;
        scan.origin = random_origin(rng, setup.geometry);
        scan.yaw_rad = rng.below(3) == 0 ? static_cast<double>(rng.below(8)) * kPi / 4 : rng.uniform(-4.0, 4.0);
        scan.fov_rad = rng.below(4) == 0 ? rng.uniform(0.5, 2 * kPi) : 2 * kPi;
        scan.min_range_m = 0.05;
        scan.max_range_m = rng.below(2) == 0 ? 12.0 : 2 * cell_m;
        const bool near = n % 3 != 0;
        std::vector<float> ranges(rng.below(2) == 0 ? 360 : 1 + rng.below(40));
        for (float &r : ranges) {
          r = near ? static_cast<float>(rng.uniform(0.0, 2.5 * cell_m)) : random_range(rng, scan.max_range_m, 10 * cell_m);
        }
        scan.ranges = ranges;
        Marks expected = reference_marks(setup.options, reference, scan);
        // Now and then a second scan into the same update before it is applied (the kernel
        // then finds the scan's marks already begun).
        sensing::LidarScan again = scan;
        again.origin = random_origin(rng, setup.geometry);
        const int passes = n % 4 == 3 ? 2 : 1;
        for (int pass = 0; pass < passes; ++pass) {
          const sensing::LidarScan &s = pass == 0 ? scan : again;
          sensing::mark_ray_model(setup.options, baseline, s, mapping::Cell{0, 0}, update_baseline,
                                  sensing::RayKernelIsa::baseline);
          sensing::mark_ray_model(setup.options, dispatched, s, mapping::Cell{0, 0}, update_dispatched,
                                  sensing::ray_kernel_isa());
        }
        if (passes == 2) {
          const Marks more = reference_marks(setup.options, reference, again);
          expected.free.insert(more.free.begin(), more.free.end());
          expected.occupied.insert(more.occupied.begin(), more.occupied.end());
        }
        const std::size_t updated_baseline = update_baseline.apply(baseline, model);
        const std::size_t updated_dispatched = update_dispatched.apply(dispatched, model);
        const std::size_t updated_reference = reference_apply(expected, model, reference);
        INFO("K = " << k << ", world " << world << ", scan " << n);
        REQUIRE(updated_baseline == updated_reference);
        REQUIRE(updated_dispatched == updated_reference);
        std::size_t differing = 0;
        for (std::size_t i = 0; i < baseline.size(); ++i) {
          differing += bits(baseline.at_index(i)) != bits(reference.at_index(i));
          differing += bits(dispatched.at_index(i)) != bits(reference.at_index(i));
        }
        REQUIRE(differing == 0);
        ++scans_checked;
      }
    }
  }
  CHECK(scans_checked == 4 * 12 * 10);
}
