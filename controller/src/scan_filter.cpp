#include "mapping/scan_filter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "common/error.hpp"

namespace mapping {
namespace {

constexpr float kNoInformation = std::numeric_limits<float>::quiet_NaN();
constexpr double kNaNRange = std::numeric_limits<double>::quiet_NaN();
// Rounds of spike rejection: a rejection can only leave a neighbour's neighbour without
// support, so a few rounds settle any cluster of spikes a 1 % fault rate makes.
constexpr int kSpikeRounds = 4;

enum BeamState : unsigned char { no_return_or_invalid, trusted_return, rejected_return };

bool full_circle(const LidarScan &scan) { return scan.fov_rad >= 2.0 * std::numbers::pi - 1e-9; }

// Beam i + offset, wrapped on a full circle; -1 past either end of a partial one.
int neighbour_index(int i, int offset, int n, bool wrap) {
  const int j = i + offset;
  if (wrap) {
    // Offsets are a few beams: one compare instead of two integer divisions (per beam,
    // per rule, per round, this was a fifth of a whole run).
    if (j >= 0 && j < n) return j;
    if (j < 0 && j >= -n) return j + n;
    if (j >= n && j < 2 * n) return j - n;
    return ((j % n) + n) % n;
  }
  return j < 0 || j >= n ? -1 : j;
}

}  // namespace

void validate(const ScanFilterOptions &options) {
  if (!(options.range_noise_m >= 0.0 && std::isfinite(options.range_noise_m))) {
    throw common::InputError(fmt::format("scan filter: range noise must be a finite number of m >= 0 (got {})",
                                         options.range_noise_m));
  }
  if (options.neighbour_reach < 1 || options.neighbour_reach > 10) {
    throw common::InputError(fmt::format("scan filter: neighbour reach must be 1 to 10 beams (got {})",
                                         options.neighbour_reach));
  }
  if (options.max_see_through < 1 || options.max_see_through > 8) {
    throw common::InputError(fmt::format("scan filter: see-through cluster must be 1 to 8 beams (got {})",
                                         options.max_see_through));
  }
  if (!(options.max_grazing_rad >= 0.0 && options.max_grazing_rad < std::numbers::pi / 2.0)) {
    throw common::InputError(fmt::format("scan filter: grazing angle must be at least 0 and below pi/2 rad (got {})",
                                         options.max_grazing_rad));
  }
  if (options.max_dropout_run < 0 || options.max_dropout_run > 32) {
    throw common::InputError(fmt::format("scan filter: dropout run must be 0 to 32 beams (got {})",
                                         options.max_dropout_run));
  }
}

ScanFilter::ScanFilter(const ScanFilterOptions &options) : options_((validate(options), options)) {}

LidarScan ScanFilter::apply(const LidarScan &scan) {
  counts_ = {};
  ranges_.assign(scan.ranges.begin(), scan.ranges.end());
  state_.assign(ranges_.size(), no_return_or_invalid);
  for (std::size_t i = 0; i < ranges_.size(); ++i) {
    switch (scan.kind_of(ranges_[i])) {
      case ReadingKind::invalid:
        ranges_[i] = kNoInformation;
        ++counts_.invalid;
        break;
      case ReadingKind::hit: state_[i] = trusted_return; break;
      case ReadingKind::no_return: break;
    }
  }
  if (ranges_.size() >= 3) {
    // A rejection takes a neighbour's support away: go again until nothing changes.
    for (int round = 0; round < kSpikeRounds; ++round) {
      const bool spikes = reject_spikes(scan);
      const bool see_through = reject_see_through(scan);
      if (!spikes && !see_through) break;
    }
    drop_dropouts(scan);
  }
  LidarScan out = scan;
  out.ranges = ranges_;
  return out;
}

int ScanFilter::nearest_trusted(const LidarScan &scan, int i, int step) const {
  const int n = static_cast<int>(ranges_.size());
  const bool wrap = full_circle(scan);
  const int reach = std::min(options_.neighbour_reach, (n - 1) / 2);
  for (int d = 1; d <= reach; ++d) {
    const int j = neighbour_index(i, step * d, n, wrap);
    if (j < 0) break;
    if (state_[static_cast<std::size_t>(j)] == trusted_return) return j;
  }
  return -1;
}

double ScanFilter::continued(const LidarScan &scan, int i, int step) const {
  const int a = nearest_trusted(scan, i, step);
  const int b = a < 0 ? -1 : nearest_trusted(scan, a, step);
  const int c = b < 0 ? -1 : nearest_trusted(scan, b, step);
  if (c < 0 || b == i || c == i || c == a) return kNaNRange;
  const double ra = ranges_[static_cast<std::size_t>(a)];
  const double rb = ranges_[static_cast<std::size_t>(b)];
  const double rc = ranges_[static_cast<std::size_t>(c)];
  // Only a surface: the three returns must follow the same ratio, so a spike cannot lend
  // its jump as a trend.
  const double predicted_a = rb * rb / rc;
  const double tolerance = options_.spike_tolerance_m() + options_.grazing_step(scan.fov_rad / static_cast<double>(ranges_.size())) * std::min(ra, predicted_a);
  if (!(std::abs(ra - predicted_a) <= tolerance)) return kNaNRange;
  return ra * ra / rb;
}

bool ScanFilter::reject_spikes(const LidarScan &scan) {
  const int n = static_cast<int>(ranges_.size());
  const double absolute_m = options_.spike_tolerance_m();
  const double relative = options_.grazing_step(scan.fov_rad / n);
  const auto range_of = [&](int j) {
    return j < 0 ? kNaNRange : static_cast<double>(ranges_[static_cast<std::size_t>(j)]);
  };
  rejected_.clear();
  for (int i = 0; i < n; ++i) {
    if (state_[static_cast<std::size_t>(i)] != trusted_return) continue;
    const double r = ranges_[static_cast<std::size_t>(i)];
    const double left = range_of(nearest_trusted(scan, i, -1));
    const double right = range_of(nearest_trusted(scan, i, +1));
    // NaN compares false: a missing neighbour supports nothing.
    const auto near = [&](double other) { return std::abs(r - other) <= absolute_m + relative * std::min(r, other); };
    const bool between = std::min(left, right) - absolute_m <= r && r <= std::max(left, right) + absolute_m;
    if (near(left) || near(right) || between) continue;
    if (near(continued(scan, i, -1)) || near(continued(scan, i, +1))) continue;
    rejected_.push_back(i);
  }
  return reject_collected();
}

bool ScanFilter::reject_collected() {
  for (const int i : rejected_) {
    state_[static_cast<std::size_t>(i)] = rejected_return;
    ranges_[static_cast<std::size_t>(i)] = kNoInformation;
    ++counts_.spikes;
  }
  return !rejected_.empty();
}

bool ScanFilter::reject_see_through(const LidarScan &scan) {
  const int n = static_cast<int>(ranges_.size());
  const bool wrap = full_circle(scan);
  const int reach = std::min(options_.neighbour_reach, (n - 1) / 2);
  const double absolute_m = options_.spike_tolerance_m();
  const double relative = options_.grazing_step(scan.fov_rad / n);
  const auto trusted = [&](int i) { return i >= 0 && state_[static_cast<std::size_t>(i)] == trusted_return; };
  const auto range = [&](int i) { return static_cast<double>(ranges_[static_cast<std::size_t>(i)]); };
  const auto near = [&](double a, double b) { return std::abs(a - b) <= absolute_m + relative * std::min(a, b); };
  // The nearest trusted return beyond beam `edge` going `step`, or NaN.
  const auto bound = [&](int edge, int step) {
    for (int d = 1; d <= reach; ++d) {
      const int j = neighbour_index(edge, step * d, n, wrap);
      if (j < 0) break;
      if (trusted(j)) return range(j);
    }
    return std::numeric_limits<double>::quiet_NaN();
  };
  rejected_.clear();
  for (int i = 0; i < n; ++i) {
    // A cluster starts at a trusted return that does not continue the one before it.
    const int before = neighbour_index(i, -1, n, wrap);
    if (!trusted(i) || (trusted(before) && near(range(before), range(i)))) continue;
    int last = i;
    double nearest_m = range(i);
    for (int size = 1; size < options_.max_see_through; ++size) {
      const int next = neighbour_index(last, 1, n, wrap);
      if (!trusted(next) || !near(range(last), range(next)) || next == i) break;
      last = next;
      nearest_m = std::min(nearest_m, range(last));
    }
    const int after = neighbour_index(last, 1, n, wrap);
    if (trusted(after) && near(range(last), range(after))) continue;  // longer than a few beams
    const double left = bound(i, -1);
    const double right = bound(last, +1);
    // Further than both sides (NaN compares false: a missing side clears it).
    if (nearest_m > left + absolute_m + relative * left && nearest_m > right + absolute_m + relative * right) {
      for (int j = i;; j = neighbour_index(j, 1, n, wrap)) {
        rejected_.push_back(j);
        if (j == last) break;
      }
    }
  }
  return reject_collected();
}

void ScanFilter::drop_dropouts(const LidarScan &scan) {
  const int n = static_cast<int>(ranges_.size());
  const bool wrap = full_circle(scan);
  // A beam that returned something, trusted or not, ends a run.
  const auto returned = [&](int i) { return state_[static_cast<std::size_t>(i)] != no_return_or_invalid; };
  // A trusted return so far away that the surface it lies on may go on past max range in
  // the next beam (a corridor's walls seen at a grazing angle): the run beside it may be a
  // real view past max range.
  const double absolute_m = options_.spike_tolerance_m();
  const double relative = options_.grazing_step(scan.fov_rad / n);
  const auto reaches_max_range = [&](int i, int away) {
    if (state_[static_cast<std::size_t>(i)] != trusted_return) return false;
    const double r = ranges_[static_cast<std::size_t>(i)];
    // The next beam's range if the surface recedes by the same ratio as from the return before.
    const int before = nearest_trusted(scan, i, away);
    const double next_m = before < 0 ? kNaNRange : r * r / ranges_[static_cast<std::size_t>(before)];
    return r + absolute_m + relative * r >= scan.max_range_m || next_m + absolute_m >= scan.max_range_m;
  };
  // Start at a return so that a run never wraps past the start unseen.
  int first = -1;
  for (int i = 0; i < n && first < 0; ++i) {
    if (returned(i)) first = i;
  }
  if (first < 0) return;  // no return at all: every no return stands
  // A partial field of view: the runs before the first return and after the last have a
  // return on one side only; they stand.
  const int span = wrap ? n : n - first;
  int run_start = -1;  // offset (from `first`) where the current run began
  for (int offset = 1; offset <= span; ++offset) {
    const int i = (first + offset) % n;
    if (offset < span && !returned(i)) {
      if (run_start < 0) run_start = offset;
      continue;
    }
    const bool bounded = offset < span || wrap;
    if (run_start >= 0 && bounded && offset - run_start <= options_.max_dropout_run &&
        !reaches_max_range((first + run_start - 1) % n, -1) && !reaches_max_range(i, +1)) {
      for (int o = run_start; o < offset; ++o) {
        float &r = ranges_[static_cast<std::size_t>((first + o) % n)];
        if (std::isnan(r)) continue;  // invalid: counted already
        r = kNoInformation;
        ++counts_.dropouts;
      }
    }
    run_start = -1;
  }
}

}  // namespace mapping
