// The range-filtering stage (mapping/scan_filter.hpp): faulty beams become "no information"
// (NaN) before any model marks the scan, and what a fault-free lidar sees passes unchanged
// (docs/robustness.md).

#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "common/random.hpp"
#include "full_circle_scan.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "sensing/scan_filter.hpp"
#include "sensing/setups.hpp"
#include "test_values.hpp"

namespace {

std::vector<float> filtered(const std::vector<float> &ranges,
                            const sensing::ScanFilterOptions &options = {}) {
  sensing::ScanFilter filter(options);
  const sensing::LidarScan out = filter.apply(full_circle(ranges));
  return {out.ranges.begin(), out.ranges.end()};
}

std::vector<float> values(const sensing::LidarScan &scan) { return {scan.ranges.begin(), scan.ranges.end()}; }

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
  for (const int i : gone) r[static_cast<std::size_t>(i)] = kFloatNaN;
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

// The filter as first written (before its neighbour search was made a sweep): one loop
// per lookup, the rules' constants computed per beam. The reference the fast filter must
// match bit for bit.
class ReferenceFilter {
 public:
  explicit ReferenceFilter(const sensing::ScanFilterOptions &options) : options_(options) {}

  // before: a scan from the same pose taken just before, or null.
  std::vector<float> apply(const sensing::LidarScan &scan, const sensing::LidarScan *before = nullptr) {
    counts_ = {};
    ranges_.assign(scan.ranges.begin(), scan.ranges.end());
    state_.assign(ranges_.size(), none);
    for (std::size_t i = 0; i < ranges_.size(); ++i) {
      switch (scan.kind_of(ranges_[i])) {
        case sensing::ReadingKind::invalid:
          ranges_[i] = kFloatNaN;
          ++counts_.invalid;
          break;
        case sensing::ReadingKind::hit: state_[i] = trusted; break;
        case sensing::ReadingKind::no_return: break;
      }
    }
    if (ranges_.size() >= 3) {
      for (int round = 0; round < 4; ++round) {
        const bool spikes = reject_spikes(scan);
        const bool see_through = reject_see_through(scan);
        if (!spikes && !see_through) break;
      }
      drop_dropouts(scan, before);
    }
    return ranges_;
  }

  const sensing::ScanFilterCounts &counts() const { return counts_; }

 private:
  enum State : unsigned char { none, trusted, rejected, candidate };
  static constexpr double kNaNRange = std::numeric_limits<double>::quiet_NaN();

  static bool full_circle(const sensing::LidarScan &scan) { return scan.fov_rad >= 2.0 * std::numbers::pi - 1e-9; }

  static int neighbour_index(int i, int offset, int n, bool wrap) {
    const int j = i + offset;
    if (wrap) return ((j % n) + n) % n;
    return j < 0 || j >= n ? -1 : j;
  }

  int nearest_trusted(const sensing::LidarScan &scan, int i, int step) const {
    const int n = static_cast<int>(ranges_.size());
    const int reach = std::min(options_.neighbour_reach, (n - 1) / 2);
    for (int d = 1; d <= reach; ++d) {
      const int j = neighbour_index(i, step * d, n, full_circle(scan));
      if (j < 0) break;
      if (state_[static_cast<std::size_t>(j)] == trusted) return j;
    }
    return -1;
  }

  double continued(const sensing::LidarScan &scan, int i, int step) const {
    const int a = nearest_trusted(scan, i, step);
    const int b = a < 0 ? -1 : nearest_trusted(scan, a, step);
    const int c = b < 0 ? -1 : nearest_trusted(scan, b, step);
    if (c < 0 || b == i || c == i || c == a) return kNaNRange;
    const double ra = ranges_[static_cast<std::size_t>(a)];
    const double rb = ranges_[static_cast<std::size_t>(b)];
    const double rc = ranges_[static_cast<std::size_t>(c)];
    const double predicted_a = rb * rb / rc;
    const double tolerance = options_.spike_tolerance_m() + options_.grazing_step(scan.fov_rad / static_cast<double>(ranges_.size())) * std::min(ra, predicted_a);
    if (!(std::abs(ra - predicted_a) <= tolerance)) return kNaNRange;
    return ra * ra / rb;
  }

  bool reject_spikes(const sensing::LidarScan &scan) {
    const int n = static_cast<int>(ranges_.size());
    const double absolute_m = options_.spike_tolerance_m();
    const double relative = options_.grazing_step(scan.fov_rad / n);
    const auto range_of = [&](int j) { return j < 0 ? kNaNRange : static_cast<double>(ranges_[static_cast<std::size_t>(j)]); };
    const auto agree = [&](double a, double b) { return std::abs(a - b) <= absolute_m + relative * std::min(a, b); };
    // A lone return: a no return (not an invalid reading) on both sides.
    const bool wrap = full_circle(scan);
    const auto no_return_at = [&](int j) {
      if (j < 0 || j >= n) {
        if (!wrap) return false;
        j = (j + n) % n;
      }
      return state_[static_cast<std::size_t>(j)] == none && !std::isnan(ranges_[static_cast<std::size_t>(j)]);
    };
    const auto lone = [&](int j) { return no_return_at(j - 1) && no_return_at(j + 1); };
    rejected_.clear();
    for (int i = 0; i < n; ++i) {
      if (state_[static_cast<std::size_t>(i)] != trusted) continue;
      const double r = ranges_[static_cast<std::size_t>(i)];
      if (lone(i)) {
        // Needs a return that is not lone to vouch for it.
        const auto vouches = [&](int j) { return j >= 0 && !lone(j) && agree(r, range_of(j)); };
        if (!vouches(nearest_trusted(scan, i, -1)) && !vouches(nearest_trusted(scan, i, +1))) rejected_.push_back(i);
        continue;
      }
      const double left = range_of(nearest_trusted(scan, i, -1));
      const double right = range_of(nearest_trusted(scan, i, +1));
      const auto near = [&](double other) { return agree(r, other); };
      const bool between = std::min(left, right) - absolute_m <= r && r <= std::max(left, right) + absolute_m;
      if (near(left) || near(right) || between) continue;
      if (near(continued(scan, i, -1)) || near(continued(scan, i, +1))) continue;
      rejected_.push_back(i);
    }
    // A candidate that the nearest return past the candidates agrees with stays.
    for (const int i : rejected_) state_[static_cast<std::size_t>(i)] = candidate;
    std::vector<int> kept;
    std::vector<int> still;
    for (const int i : rejected_) {
      bool keep = false;
      for (const int step : {-1, +1}) {
        const int j = nearest_trusted(scan, i, step);
        if (j >= 0 && agree(range_of(i), range_of(j)) && !(lone(i) && lone(j))) keep = true;
      }
      (keep ? kept : still).push_back(i);
    }
    for (const int i : kept) state_[static_cast<std::size_t>(i)] = trusted;
    rejected_ = still;
    return reject_collected();
  }

  bool reject_collected() {
    for (const int i : rejected_) {
      state_[static_cast<std::size_t>(i)] = rejected;
      ranges_[static_cast<std::size_t>(i)] = kFloatNaN;
      ++counts_.spikes;
    }
    return !rejected_.empty();
  }

  bool reject_see_through(const sensing::LidarScan &scan) {
    const int n = static_cast<int>(ranges_.size());
    const bool wrap = full_circle(scan);
    const double absolute_m = options_.spike_tolerance_m();
    const double relative = options_.grazing_step(scan.fov_rad / n);
    const auto is_trusted = [&](int i) { return i >= 0 && state_[static_cast<std::size_t>(i)] == trusted; };
    const auto range = [&](int i) { return static_cast<double>(ranges_[static_cast<std::size_t>(i)]); };
    const auto near = [&](double a, double b) { return std::abs(a - b) <= absolute_m + relative * std::min(a, b); };
    const auto bound = [&](int edge, int step) {
      const int j = nearest_trusted(scan, edge, step);
      return j < 0 ? kNaNRange : range(j);
    };
    rejected_.clear();
    for (int i = 0; i < n; ++i) {
      const int before = neighbour_index(i, -1, n, wrap);
      if (!is_trusted(i) || (is_trusted(before) && near(range(before), range(i)))) continue;
      int last = i;
      double nearest_m = range(i);
      for (int size = 1; size < options_.max_see_through; ++size) {
        const int next = neighbour_index(last, 1, n, wrap);
        if (!is_trusted(next) || !near(range(last), range(next)) || next == i) break;
        last = next;
        nearest_m = std::min(nearest_m, range(last));
      }
      const int after = neighbour_index(last, 1, n, wrap);
      if (is_trusted(after) && near(range(last), range(after))) continue;
      const double left = bound(i, -1);
      const double right = bound(last, +1);
      if (nearest_m > left + absolute_m + relative * left && nearest_m > right + absolute_m + relative * right) {
        for (int j = i;; j = neighbour_index(j, 1, n, wrap)) {
          rejected_.push_back(j);
          if (j == last) break;
        }
      }
    }
    return reject_collected();
  }

  void drop_dropouts(const sensing::LidarScan &scan, const sensing::LidarScan *before) {
    const int n = static_cast<int>(ranges_.size());
    const bool wrap = full_circle(scan);
    const auto returned = [&](int i) { return state_[static_cast<std::size_t>(i)] != none; };
    // Beams first + [from, to) read no return in the scan before too, and are enough of them.
    const auto seen_before = [&](int first, int from, int to) {
      if (before == nullptr || to - from < options_.min_repeated_view) return false;
      for (int o = from; o < to; ++o) {
        if (before->kind((first + o) % n) != sensing::ReadingKind::no_return) return false;
      }
      return true;
    };
    int first = -1;
    for (int i = 0; i < n && first < 0; ++i) {
      if (returned(i)) first = i;
    }
    if (first < 0) return;
    const int span = wrap ? n : n - first;
    int run_start = -1;
    for (int offset = 1; offset <= span; ++offset) {
      const int i = (first + offset) % n;
      if (offset < span && !returned(i)) {
        if (run_start < 0) run_start = offset;
        continue;
      }
      const bool bounded = offset < span || wrap;
      if (run_start >= 0 && bounded && offset - run_start <= options_.max_dropout_run &&
          !seen_before(first, run_start, offset)) {
        for (int o = run_start; o < offset; ++o) {
          float &r = ranges_[static_cast<std::size_t>((first + o) % n)];
          if (std::isnan(r)) continue;
          r = kFloatNaN;
          ++counts_.dropouts;
        }
      }
      run_start = -1;
    }
  }

  sensing::ScanFilterOptions options_;
  std::vector<float> ranges_;
  std::vector<State> state_;
  std::vector<int> rejected_;
  sensing::ScanFilterCounts counts_;
};

// A random scan of what the filter meets: walls at every angle (a wall seen at a grazing
// angle grows a few % a beam), depth steps, views past max range, and every fault: spikes,
// agreeing clusters seen through a wall, dropped runs, NaN, negative, -inf, -0, below
// minimum, at and just past both limits.
std::vector<float> random_scan(common::Rng &rng, int n, const sensing::LidarScan &limits) {
  std::vector<float> r(static_cast<std::size_t>(n));
  const auto pick = [&](int count) { return static_cast<int>(rng.below(static_cast<std::uint64_t>(count))); };
  // Walls: segments of a surface at distance d, angle a from square-on, stepping by
  // `step` rad a beam; the range is d / cos(angle).
  const double step = limits.fov_rad / n;
  int i = 0;
  while (i < n) {
    const int length = 1 + pick(n / 3 + 2);
    const double d = rng.uniform(0.1, 3.0);
    double angle = rng.uniform(-1.45, 1.45);
    const bool open = rng.uniform01() < 0.1;  // a view past max range
    for (int k = 0; k < length && i < n; ++k, ++i) {
      const double range = d / std::cos(std::clamp(angle, -1.5, 1.5));
      r[static_cast<std::size_t>(i)] = open || range > limits.max_range_m ? kFloatInf : static_cast<float>(range);
      angle += step;
    }
  }
  // Faults at a random rate, from none to many.
  const double rate = rng.uniform01() < 0.2 ? 0.0 : rng.uniform(0.0, 0.3);
  for (int j = 0; j < n; ++j) {
    if (!(rng.uniform01() < rate)) continue;
    float &v = r[static_cast<std::size_t>(j)];
    switch (pick(14)) {
      case 0: v = static_cast<float>(rng.uniform(0.0, 13.0)); break;  // a spike
      case 1: {  // an agreeing cluster further away (seen through a wall)
        const float far = static_cast<float>(rng.uniform(1.0, 11.0));
        const int size = 1 + pick(4);
        for (int k = 0; k < size && j + k < n; ++k) r[static_cast<std::size_t>(j + k)] = far * (1.0f + 0.01f * static_cast<float>(k));
        break;
      }
      case 2: {  // a dropped run
        const int size = 1 + pick(9);
        for (int k = 0; k < size && j + k < n; ++k) r[static_cast<std::size_t>(j + k)] = kFloatInf;
        break;
      }
      case 3: v = kFloatNaN; break;
      case 4: v = -static_cast<float>(rng.uniform(0.0, 2.0)); break;
      case 5:
        v = -kFloatInf;
        break;
      case 6: v = -0.0f; break;
      case 7: v = 0.0f; break;
      case 8: v = static_cast<float>(limits.min_range_m * rng.uniform01()); break;
      case 9: v = static_cast<float>(limits.min_range_m); break;
      case 10: v = static_cast<float>(limits.max_range_m); break;
      case 11:
        v = std::nextafter(static_cast<float>(limits.max_range_m), kFloatInf);
        break;
      case 12: v = static_cast<float>(rng.uniform(limits.max_range_m - 1.0, limits.max_range_m + 1.0)); break;
      default: v = v * static_cast<float>(rng.uniform(0.97, 1.03)); break;  // noise
    }
  }
  return r;
}

sensing::ScanFilterOptions random_options(common::Rng &rng) {
  sensing::ScanFilterOptions o;
  if (rng.uniform01() < 0.3) return o;  // the defaults
  o.range_noise_m = rng.uniform01() < 0.2 ? 0.0 : rng.uniform(0.0, 0.1);
  o.neighbour_reach = 1 + static_cast<int>(rng.below(10));
  o.max_see_through = 1 + static_cast<int>(rng.below(8));
  o.max_dropout_run = static_cast<int>(rng.below(33));
  o.max_grazing_rad = rng.uniform01() < 0.1 ? 0.0 : rng.uniform(0.0, 1.55);
  o.min_repeated_view = 1 + static_cast<int>(rng.below(8));
  return o;
}

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

// Down a corridor longer than max range, seen end-on: its walls at a grazing angle return up
// to near 12 m on both sides of five no returns (beams 178 ... 182), 1.5 m elsewhere.
std::vector<float> corridor_end_view() {
  std::vector<float> r(360, 1.5f);
  for (int i = 0; i < 8; ++i) {
    r[static_cast<std::size_t>(170 + i)] = static_cast<float>(0.494 / std::sin((10 - i) * kDeg));
    r[static_cast<std::size_t>(190 - i)] = r[static_cast<std::size_t>(170 + i)];
  }
  for (int i = 178; i <= 182; ++i) r[static_cast<std::size_t>(i)] = kFloatInf;
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
  for (int i = 170; i < 190; ++i) open[static_cast<std::size_t>(i)] = kFloatInf;
  CHECK(text(filtered(open), 165, 195) == text(open, 165, 195));
  // Down a corridor longer than max range: its walls, seen at a grazing angle, return up to
  // near 12 m on both sides of a few no returns. One scan cannot tell them from dropped
  // beams; seen again from the same pose they are a view (the next test).
  std::vector<float> corridor_end = corridor_end_view();
  CHECK(corridor_end[177] > 9.0f);  // 3 degrees off the axis; at 2 degrees 14 m
  sensing::ScanFilter again;
  CHECK(text(values(again.apply(full_circle(corridor_end), full_circle(corridor_end))), 165, 195) == text(corridor_end, 165, 195));
  // Nothing returns at all (an empty hall): every no return stands.
  const std::vector<float> nothing(360, kFloatInf);
  CHECK(text(filtered(nothing), 0, 359) == text(nothing, 0, 359));
}

TEST_CASE("scan filter: a short view past max range seen twice from the same pose stands; dropped beams do not") {
  const std::vector<float> view = corridor_end_view();  // no returns at beams 178 ... 182
  const sensing::LidarScan scan = full_circle(view);
  const std::string seen = text(view, 165, 195);
  const std::string dropped = "150 150 150 150 150 284 316 355 405 473 567 708 944 - - - - - 944 708 567 473 405 355 316 284 150 150 150 150 150";
  sensing::ScanFilter filter;
  // First sight: five no returns between returns read as dropped beams.
  CHECK(text(values(filter.apply(scan)), 165, 195) == dropped);
  CHECK(filter.counts().dropouts == 5);
  // Seen again from the same pose: a view.
  CHECK(text(values(filter.apply(scan, scan)), 165, 195) == seen);
  CHECK(filter.counts().dropouts == 0);
  // The same pose within 1 cm and a quarter beam step.
  sensing::LidarScan near = scan;
  near.origin = {near.origin.x_m + 0.006, near.origin.y_m - 0.006};
  near.yaw_rad += 0.2 * kDeg;
  CHECK(text(values(filter.apply(scan, near)), 165, 195) == seen);
  // From elsewhere, or turned by a beam, the scan before says nothing about these beams.
  sensing::LidarScan moved = scan;
  moved.origin.x_m += 0.05;
  CHECK(text(values(filter.apply(scan, moved)), 165, 195) == dropped);
  sensing::LidarScan turned = scan;
  turned.yaw_rad += kDeg;
  CHECK(text(values(filter.apply(scan, turned)), 165, 195) == dropped);
  // Dropped beams are a new draw at every scan: the run the scan before read differently
  // (one beam of the five returned) is dropped again.
  std::vector<float> other = view;
  other[180] = 7.0f;
  CHECK(text(values(filter.apply(scan, full_circle(other))), 165, 195) == dropped);
  // Two beams repeating is too likely for dropouts (5 %^4 a pair at a 5 % rate): at least three.
  std::vector<float> pair = closed_cell();
  pair[100] = kFloatInf;
  pair[101] = kFloatInf;
  CHECK(text(values(filter.apply(full_circle(pair), full_circle(pair))), 99, 102) == text(pair, 99, 99) + " - - " + text(pair, 102, 102));
}

TEST_CASE("scan filter: a spike that agrees with neither neighbour is no information") {
  std::vector<float> r = closed_cell();
  r[180] = 7.3f;   // through the wall ahead
  r[90] = 0.2f;    // a phantom obstacle
  r[0] = 3.0f;     // beside a no return, across the wrap
  r[1] = kFloatInf;
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
  sensing::ScanFilter filter;
  const sensing::LidarScan out = filter.apply(full_circle(r));
  const std::vector<float> f(out.ranges.begin(), out.ranges.end());
  CHECK(text(f, 0, 359) == text(without(r, {200, 201, 300, 301}), 0, 359));
  CHECK(filter.counts().spikes == 4);
  CHECK(filter.counts().dropouts == 0);
}

TEST_CASE("scan filter: a short run of no returns between returns is dropped beams") {
  std::vector<float> r = closed_cell();
  for (int i = 10; i < 16; ++i) r[static_cast<std::size_t>(i)] = kFloatInf;    // 6 beams: dropped
  for (int i = 100; i < 107; ++i) r[static_cast<std::size_t>(i)] = kFloatInf;  // 7 beams: a view
  r[359] = kFloatInf;                                                          // wraps around beam 0
  sensing::ScanFilter filter;
  const sensing::LidarScan out = filter.apply(full_circle(r));
  const std::vector<float> f(out.ranges.begin(), out.ranges.end());
  CHECK(text(f, 0, 359) == text(without(r, {10, 11, 12, 13, 14, 15, 359}), 0, 359));
  CHECK(text(f, 99, 107) == "50 inf inf inf inf inf inf inf 52");
  CHECK(filter.counts().dropouts == 7);
  sensing::ScanFilterOptions longer;
  longer.max_dropout_run = 7;
  CHECK(text(filtered(r, longer), 99, 107) == "50 - - - - - - - 52");
  sensing::ScanFilterOptions none;
  none.max_dropout_run = 0;
  CHECK(text(filtered(r, none), 0, 359) == text(r, 0, 359));
}

TEST_CASE("scan filter: a partial field of view keeps no returns at its ends") {
  std::vector<float> r{kFloatInf, kFloatInf, 1.0f, 1.0f, kFloatInf, 1.0f, 1.0f, kFloatInf};
  sensing::LidarScan s = full_circle(r);
  s.fov_rad = 8 * kDeg;
  sensing::ScanFilter filter;
  const sensing::LidarScan out = filter.apply(s);
  CHECK(text({out.ranges.begin(), out.ranges.end()}, 0, 7) == "inf inf 100 100 - 100 100 inf");
}

TEST_CASE("scan filter: NaN, negative and below-minimum readings are no information") {
  std::vector<float> r = closed_cell();
  r[45] = kFloatNaN;
  r[46] = -0.5f;
  r[47] = 0.01f;
  r[48] = -kFloatInf;
  sensing::ScanFilter filter;
  const sensing::LidarScan out = filter.apply(full_circle(r));
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
  for (const sensing::ModelKind kind : {sensing::ModelKind::cell, sensing::ModelKind::ray}) {
    CAPTURE(sensing::to_string(kind));
    sensing::ModelOptions options;
    options.kind = kind;
    sensing::ScanFilter filter;
    mapping::ScanUpdate update;
    // Nothing valid at all: nothing is updated but the centre the robot stands on (the cell
    // model frees it whatever the lidar says).
    std::vector<float> bad(360);
    for (std::size_t i = 0; i < bad.size(); ++i) bad[i] = i % 3 == 0 ? kFloatNaN : (i % 3 == 1 ? -1.0f : -kFloatInf);
    mapping::OccupancyGrid grid(g, 0.0f);
    sensing::LidarScan scan = full_circle(bad);
    scan.origin = {1.5, 1.5};
    const std::size_t expected = kind == sensing::ModelKind::cell ? 1 : 0;
    CHECK(sensing::integrate_scan(options, grid, filter.apply(scan), mapping::Cell{1, 1}, model, update) == expected);
    int changed = 0;
    for (int y = 0; y < g.height_subcells(); ++y) {
      for (int x = 0; x < g.width_subcells(); ++x) changed += grid.at(mapping::SubCell{x, y}) != 0.0f ? 1 : 0;
    }
    CHECK(changed == static_cast<int>(expected));
    // Every other beam invalid, the rest a closed cell: every value stored is finite.
    std::vector<float> mixed = closed_cell();
    for (std::size_t i = 0; i < mixed.size(); i += 2) mixed[i] = i % 4 == 0 ? kFloatNaN : -0.3f;
    scan.ranges = mixed;
    CHECK(sensing::integrate_scan(options, grid, filter.apply(scan), mapping::Cell{1, 1}, model, update) > 0);
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
      v = u < 0.2 ? kFloatInf : (u < 0.25 ? kFloatNaN : (u < 0.3 ? -1.0f : static_cast<float>(rng.uniform(0.0, 13.0))));
    }
    sensing::LidarScan s = full_circle(r);
    if (trial % 2 == 1) s.fov_rad = n * kDeg;  // a partial field of view
    sensing::ScanFilter filter;
    const sensing::LidarScan out = filter.apply(s);
    REQUIRE(out.beam_count() == n);
    std::size_t gone = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const float v = out.ranges[i];
      const bool kept = v == r[i] || (std::isnan(v) && std::isnan(r[i]));
      CHECK((kept || std::isnan(v)));
      CHECK_FALSE((std::isnan(v) == false && s.kind_of(v) == sensing::ReadingKind::invalid));
      if (std::isnan(v)) ++gone;
    }
    const sensing::ScanFilterCounts &c = filter.counts();
    CHECK(c.invalid + c.spikes + c.dropouts == gone);
  }
}

TEST_CASE("scan filter: options checked, messages to the letter") {
  const auto error_of = [](const sensing::ScanFilterOptions &o) {
    try {
      sensing::validate(o);
    } catch (const common::InputError &e) {
      return e.diagnostic();
    }
    return std::string("no error");
  };
  sensing::ScanFilterOptions o;
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
  o = {};
  o.min_repeated_view = 0;
  CHECK(error_of(o) == "error: scan filter: repeated view must be 1 to 32 beams (got 0)");
  o = {};
  o.same_pose_m = -1.0;
  CHECK(error_of(o) == "error: scan filter: same-pose distance must be a finite number of m >= 0 (got -1)");
}

TEST_CASE("scan filter: the same readings and counts, bit for bit, as the reference filter") {
  common::Rng rng(20261122);
  int rejected = 0;
  int dropped = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    CAPTURE(trial);
    const sensing::ScanFilterOptions options = random_options(rng);
    // One filter for several scans of different sizes: its buffers are reused.
    sensing::ScanFilter filter(options);
    ReferenceFilter reference(options);
    for (int scan_index = 0; scan_index < 3; ++scan_index) {
      CAPTURE(scan_index);
      const int sizes[] = {0, 1, 2, 3, 4, 5, 7, 12, 40, 90, 359, 360, 720};
      const int n = sizes[rng.below(std::size(sizes))];
      sensing::LidarScan limits;
      limits.fov_rad = 2.0 * std::numbers::pi;
      limits.min_range_m = rng.uniform01() < 0.2 ? 0.0 : rng.uniform(0.0, 0.2);
      limits.max_range_m = rng.uniform(1.0, 12.0);
      switch (rng.below(4)) {
        case 0: break;                                              // a full circle
        case 1: limits.fov_rad = 2.0 * std::numbers::pi - 5e-10; break;  // one by tolerance
        case 2: limits.fov_rad = n * kDeg; break;                  // 1-degree beams, partial
        default: limits.fov_rad = rng.uniform(0.1, 6.2); break;    // any partial field of view
      }
      CAPTURE(n);
      CAPTURE(limits.fov_rad);
      const std::vector<float> r = n == 0 ? std::vector<float>{} : random_scan(rng, n, limits);
      sensing::LidarScan scan = limits;
      scan.ranges = r;
      // Half the scans follow one from the same pose: the same beams, some changed (a
      // no return becomes a return and back), so that repeated and new runs both occur.
      std::vector<float> earlier = r;
      for (float &v : earlier) {
        if (rng.uniform01() < 0.15) v = rng.uniform01() < 0.5 ? kFloatInf : static_cast<float>(limits.max_range_m / 2);
      }
      sensing::LidarScan before = limits;
      before.ranges = earlier;
      const bool repeat = rng.uniform01() < 0.5;
      const std::vector<float> expected = reference.apply(scan, repeat ? &before : nullptr);
      const sensing::LidarScan out = repeat ? filter.apply(scan, before) : filter.apply(scan);
      REQUIRE(out.beam_count() == n);
      for (std::size_t i = 0; i < r.size(); ++i) {
        CAPTURE(i);
        REQUIRE(bits(out.ranges[i]) == bits(expected[i]));
      }
      CHECK(filter.counts().invalid == reference.counts().invalid);
      CHECK(filter.counts().spikes == reference.counts().spikes);
      CHECK(filter.counts().dropouts == reference.counts().dropouts);
      rejected += static_cast<int>(reference.counts().spikes);
      dropped += static_cast<int>(reference.counts().dropouts);
    }
  }
  // The scans exercise every rule (not only the fast paths).
  CHECK(rejected > 1000);
  CHECK(dropped > 1000);
}

TEST_CASE("scan filter: a fault-free closed cell with spikes matches the reference at every rotation") {
  // The cell every run sees most, with spikes, clusters and dropouts at each wrap position.
  common::Rng rng(8);
  for (int shift = 0; shift < 360; ++shift) {
    CAPTURE(shift);
    std::vector<float> r = closed_cell();
    std::rotate(r.begin(), r.begin() + shift, r.end());
    for (int k = 0; k < 6; ++k) r[static_cast<std::size_t>(rng.below(360))] = static_cast<float>(rng.uniform(0.0, 12.0));
    r[static_cast<std::size_t>(shift)] = kFloatInf;
    r[static_cast<std::size_t>((shift + 359) % 360)] = kFloatInf;
    r[static_cast<std::size_t>((shift + 180) % 360)] = 5.0f;
    r[static_cast<std::size_t>((shift + 181) % 360)] = 5.02f;
    const sensing::LidarScan scan = full_circle(r);
    ReferenceFilter reference({});
    sensing::ScanFilter filter;
    const std::vector<float> expected = reference.apply(scan);
    const sensing::LidarScan out = filter.apply(scan);
    for (std::size_t i = 0; i < r.size(); ++i) {
      CAPTURE(i);
      REQUIRE(bits(out.ranges[i]) == bits(expected[i]));
    }
    CHECK(filter.counts().spikes == reference.counts().spikes);
    CHECK(filter.counts().dropouts == reference.counts().dropouts);
  }
}

TEST_CASE("scan filter: a lone return in a view past max range is a spike, even when another agrees with it") {
  // Down a corridor longer than max range (beams 160 ... 200 read no return), two spikes
  // three beams apart (0.61 and 0.68 m) agree with each other; the cell model read the pair
  // as a wall and sealed half a 128 x 128 maze.
  std::vector<float> r = closed_cell();
  for (int i = 160; i <= 200; ++i) r[static_cast<std::size_t>(i)] = kFloatInf;
  r[179] = 0.607f;
  r[182] = 0.679f;
  // Both go; the two no returns between them, now bounded by rejected beams, are a short
  // run read as dropped beams: no information either way.
  CHECK(text(filtered(r), 177, 184) == "inf inf - - - - inf inf");
  // A real return whose neighbours were both dropped has the wall beyond them: it stays.
  std::vector<float> wall = closed_cell();
  wall[179] = kFloatInf;
  wall[181] = kFloatInf;
  wall[177] = 2.2f;  // and a spike pair that it alone tells from the wall
  wall[178] = 2.0f;
  CHECK(text(filtered(wall), 180, 180) == text(wall, 180, 180));
  // A return beside an invalid reading (below min range) is not lone: that is no view.
  r[178] = 0.01f;
  r[180] = 0.62f;
  r[182] = kFloatInf;
  CHECK(text(filtered(r), 178, 180) == "- 61 62");
}

TEST_CASE("scan filter: a real return between spikes stays (the nearest return past them agrees)") {
  // A wall 1.5 m ahead; beam 179 a spike at 1.07 m, beams 181-182 two agreeing spikes at
  // 0.57 / 0.54 m. Beam 180, the wall, agrees with neither neighbour: the spike rule alone
  // rejected it too, and the cell model then read a wall 0.55 m ahead where it was open.
  std::vector<float> r(360, 1.5f);
  r[179] = 1.069f;
  r[181] = 0.574f;
  r[182] = 0.535f;
  CHECK(text(filtered(r), 178, 183) == "150 - 150 57 54 150");
}
