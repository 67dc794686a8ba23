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
  const std::size_t size = scan.ranges.size();
  // No allocation once the filter has seen a scan this size.
  ranges_.resize(size);
  state_.resize(size);
  for (std::size_t i = 0; i < size; ++i) {
    const float r = scan.ranges[i];
    switch (scan.kind_of(r)) {
      case ReadingKind::invalid:
        ranges_[i] = kNoInformation;
        state_[i] = no_return_or_invalid;
        ++counts_.invalid;
        break;
      case ReadingKind::hit:
        ranges_[i] = r;
        state_[i] = trusted_return;
        break;
      case ReadingKind::no_return:
        ranges_[i] = r;
        state_[i] = no_return_or_invalid;
        break;
    }
  }
  if (size >= 3) {
    // Every rule's constants, once per scan (grazing_step takes a tangent).
    n_ = static_cast<int>(size);
    wrap_ = full_circle(scan);
    reach_ = std::min(options_.neighbour_reach, (n_ - 1) / 2);
    absolute_m_ = options_.spike_tolerance_m();
    relative_ = options_.grazing_step(scan.fov_rad / n_);
    max_range_m_ = scan.max_range_m;
    // A rejection takes a neighbour's support away: go again until nothing changes.
    for (int round = 0; round < kSpikeRounds; ++round) {
      const bool spikes = reject_spikes();
      const bool see_through = reject_see_through();
      if (!spikes && !see_through) break;
    }
    drop_dropouts();
  }
  LidarScan out = scan;
  out.ranges = ranges_;
  return out;
}

// Inline where the rules call it: most beams find their neighbour one beam away.
inline int ScanFilter::nearest_trusted(int i, int step) const {
  int j = i;
  for (int d = 1; d <= reach_; ++d) {
    j += step;
    if (j < 0 || j >= n_) {
      if (!wrap_) return -1;
      j = j < 0 ? j + n_ : j - n_;  // reach_ < n_: wrapped once at most
    }
    if (state_[static_cast<std::size_t>(j)] == trusted_return) return j;
  }
  return -1;
}

double ScanFilter::continued(int i, int step) const {
  const int a = nearest_trusted(i, step);
  const int b = a < 0 ? -1 : nearest_trusted(a, step);
  const int c = b < 0 ? -1 : nearest_trusted(b, step);
  if (c < 0 || b == i || c == i || c == a) return kNaNRange;
  const double ra = ranges_[static_cast<std::size_t>(a)];
  const double rb = ranges_[static_cast<std::size_t>(b)];
  const double rc = ranges_[static_cast<std::size_t>(c)];
  // Only a surface: the three returns must follow the same ratio, so a spike cannot lend
  // its jump as a trend.
  const double predicted_a = rb * rb / rc;
  const double tolerance = absolute_m_ + relative_ * std::min(ra, predicted_a);
  if (!(std::abs(ra - predicted_a) <= tolerance)) return kNaNRange;
  return ra * ra / rb;
}

bool ScanFilter::reject_spikes() {
  const double absolute_m = absolute_m_;
  const double relative = relative_;
  const auto range_of = [&](int j) {
    return j < 0 ? kNaNRange : static_cast<double>(ranges_[static_cast<std::size_t>(j)]);
  };
  rejected_.clear();
  for (int i = 0; i < n_; ++i) {
    if (state_[static_cast<std::size_t>(i)] != trusted_return) continue;
    const double r = ranges_[static_cast<std::size_t>(i)];
    // NaN compares false: a missing neighbour supports nothing.
    const auto near = [&](double other) { return std::abs(r - other) <= absolute_m + relative * std::min(r, other); };
    const double left = range_of(nearest_trusted(i, -1));
    if (near(left)) continue;  // most beams: the wall the one before hit
    const double right = range_of(nearest_trusted(i, +1));
    const bool between = std::min(left, right) - absolute_m <= r && r <= std::max(left, right) + absolute_m;
    if (near(right) || between) continue;
    if (near(continued(i, -1)) || near(continued(i, +1))) continue;
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

bool ScanFilter::reject_see_through() {
  const int n = n_;
  const double absolute_m = absolute_m_;
  const double relative = relative_;
  const auto trusted = [&](int i) { return i >= 0 && state_[static_cast<std::size_t>(i)] == trusted_return; };
  const auto range = [&](int i) { return static_cast<double>(ranges_[static_cast<std::size_t>(i)]); };
  const auto near = [&](double a, double b) { return std::abs(a - b) <= absolute_m + relative * std::min(a, b); };
  // The neighbouring beam, wrapped on a full circle; -1 past either end of a partial one.
  const auto previous_beam = [&](int i) { return i > 0 ? i - 1 : (wrap_ ? n - 1 : -1); };
  const auto next_beam = [&](int i) { return i < n - 1 ? i + 1 : (wrap_ ? 0 : -1); };
  // The nearest trusted return within reach of beam i going `towards`, or NaN.
  const auto bound = [&](int i, int step) {
    const int j = nearest_trusted(i, step);
    return j < 0 ? kNaNRange : range(j);
  };
  rejected_.clear();
  for (int i = 0; i < n; ++i) {
    // A cluster starts at a trusted return that does not continue the one before it.
    if (!trusted(i)) continue;
    const int before = previous_beam(i);
    if (trusted(before) && near(range(before), range(i))) continue;
    int last = i;
    double nearest_m = range(i);
    for (int size = 1; size < options_.max_see_through; ++size) {
      const int next = next_beam(last);
      if (!trusted(next) || !near(range(last), range(next)) || next == i) break;
      last = next;
      nearest_m = std::min(nearest_m, range(last));
    }
    const int after = next_beam(last);
    if (trusted(after) && near(range(last), range(after))) continue;  // longer than a few beams
    const double left = bound(i, -1);
    const double right = bound(last, +1);
    // Further than both sides (NaN compares false: a missing side clears it).
    if (nearest_m > left + absolute_m + relative * left && nearest_m > right + absolute_m + relative * right) {
      for (int j = i;; j = next_beam(j)) {
        rejected_.push_back(j);
        if (j == last) break;
      }
    }
  }
  return reject_collected();
}

void ScanFilter::drop_dropouts() {
  const int n = n_;
  // A beam that returned something, trusted or not, ends a run.
  const auto returned = [&](int i) { return state_[static_cast<std::size_t>(i)] != no_return_or_invalid; };
  // Beam `first` + offset, offset 0 ... n.
  const auto wrapped = [&](int i) { return i < n ? i : i - n; };
  // A trusted return so far away that the surface it lies on may go on past max range in
  // the next beam (a corridor's walls seen at a grazing angle): the run beside it may be a
  // real view past max range.
  const double absolute_m = absolute_m_;
  const double relative = relative_;
  const auto reaches_max_range = [&](int i, int away) {
    if (state_[static_cast<std::size_t>(i)] != trusted_return) return false;
    const double r = ranges_[static_cast<std::size_t>(i)];
    // The next beam's range if the surface recedes by the same ratio as from the return before.
    const int before = nearest_trusted(i, away);
    const double next_m = before < 0 ? kNaNRange : r * r / ranges_[static_cast<std::size_t>(before)];
    return r + absolute_m + relative * r >= max_range_m_ || next_m + absolute_m >= max_range_m_;
  };
  // Start at a return so that a run never wraps past the start unseen.
  int first = -1;
  for (int i = 0; i < n && first < 0; ++i) {
    if (returned(i)) first = i;
  }
  if (first < 0) return;  // no return at all: every no return stands
  // A partial field of view: the runs before the first return and after the last have a
  // return on one side only; they stand.
  const int span = wrap_ ? n : n - first;
  int run_start = -1;  // offset (from `first`) where the current run began
  for (int offset = 1; offset <= span; ++offset) {
    const int i = wrapped(first + offset);
    if (offset < span && !returned(i)) {
      if (run_start < 0) run_start = offset;
      continue;
    }
    const bool bounded = offset < span || wrap_;
    if (run_start >= 0 && bounded && offset - run_start <= options_.max_dropout_run &&
        !reaches_max_range(wrapped(first + run_start - 1), -1) && !reaches_max_range(i, +1)) {
      for (int o = run_start; o < offset; ++o) {
        float &r = ranges_[static_cast<std::size_t>(wrapped(first + o))];
        if (std::isnan(r)) continue;  // invalid: counted already
        r = kNoInformation;
        ++counts_.dropouts;
      }
    }
    run_start = -1;
  }
}

}  // namespace mapping
