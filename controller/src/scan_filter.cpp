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

// Far enough from any beam that no beam finds it within reach.
constexpr int kNowhere = std::numeric_limits<int>::max() / 4;

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
  before_.resize(size);
  after_.resize(size);
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
    const int n = static_cast<int>(size);
    // Every rule's constants, once per scan (grazing_step takes a tangent).
    wrap_ = full_circle(scan);
    reach_ = std::min(options_.neighbour_reach, (n - 1) / 2);
    absolute_m_ = options_.spike_tolerance_m();
    relative_ = options_.grazing_step(scan.fov_rad / n);
    max_range_m_ = scan.max_range_m;
    neighbours_current_ = false;
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

void ScanFilter::find_neighbours() {
  if (neighbours_current_) return;
  const int n = static_cast<int>(ranges_.size());
  const auto trusted = [&](int beam) { return state_[static_cast<std::size_t>(beam)] == trusted_return; };
  // Beams k past either end (virtual indices) are beam k -+ n on a full circle; reach_ < n.
  int nearest = kNowhere;  // the nearest trusted return after beam k so far
  for (int k = wrap_ ? n - 1 + reach_ : n - 1; k >= 0; --k) {
    if (k < n) after_[static_cast<std::size_t>(k)] = nearest - k <= reach_ ? (nearest >= n ? nearest - n : nearest) : -1;
    if (trusted(k >= n ? k - n : k)) nearest = k;
  }
  nearest = -kNowhere;  // the nearest trusted return before beam k so far
  for (int k = wrap_ ? -reach_ : 0; k < n; ++k) {
    if (k >= 0) before_[static_cast<std::size_t>(k)] = k - nearest <= reach_ ? (nearest < 0 ? nearest + n : nearest) : -1;
    if (trusted(k < 0 ? k + n : k)) nearest = k;
  }
  neighbours_current_ = true;
}

double ScanFilter::continued(int i, int step) const {
  const std::vector<int> &towards = step < 0 ? before_ : after_;
  const int a = towards[static_cast<std::size_t>(i)];
  const int b = a < 0 ? -1 : towards[static_cast<std::size_t>(a)];
  const int c = b < 0 ? -1 : towards[static_cast<std::size_t>(b)];
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
  find_neighbours();
  const std::size_t size = ranges_.size();
  const double absolute_m = absolute_m_;
  const double relative = relative_;
  const auto range_of = [&](int j) {
    return j < 0 ? kNaNRange : static_cast<double>(ranges_[static_cast<std::size_t>(j)]);
  };
  rejected_.clear();
  for (std::size_t i = 0; i < size; ++i) {
    if (state_[i] != trusted_return) continue;
    const double r = ranges_[i];
    const double left = range_of(before_[i]);
    const double right = range_of(after_[i]);
    // NaN compares false: a missing neighbour supports nothing.
    const auto near = [&](double other) { return std::abs(r - other) <= absolute_m + relative * std::min(r, other); };
    if (near(left) || near(right)) continue;
    const bool between = std::min(left, right) - absolute_m <= r && r <= std::max(left, right) + absolute_m;
    if (between) continue;
    const int beam = static_cast<int>(i);
    if (near(continued(beam, -1)) || near(continued(beam, +1))) continue;
    rejected_.push_back(beam);
  }
  return reject_collected();
}

bool ScanFilter::reject_collected() {
  for (const int i : rejected_) {
    state_[static_cast<std::size_t>(i)] = rejected_return;
    ranges_[static_cast<std::size_t>(i)] = kNoInformation;
    ++counts_.spikes;
  }
  if (rejected_.empty()) return false;
  neighbours_current_ = false;
  return true;
}

bool ScanFilter::reject_see_through() {
  find_neighbours();
  const int n = static_cast<int>(ranges_.size());
  const double absolute_m = absolute_m_;
  const double relative = relative_;
  const auto trusted = [&](int i) { return i >= 0 && state_[static_cast<std::size_t>(i)] == trusted_return; };
  const auto range = [&](int i) { return static_cast<double>(ranges_[static_cast<std::size_t>(i)]); };
  const auto near = [&](double a, double b) { return std::abs(a - b) <= absolute_m + relative * std::min(a, b); };
  // The neighbouring beam, wrapped on a full circle; -1 past either end of a partial one.
  const auto previous_beam = [&](int i) { return i > 0 ? i - 1 : (wrap_ ? n - 1 : -1); };
  const auto next_beam = [&](int i) { return i < n - 1 ? i + 1 : (wrap_ ? 0 : -1); };
  // The nearest trusted return within reach of beam i going `towards`, or NaN.
  const auto bound = [&](const std::vector<int> &towards, int i) {
    const int j = towards[static_cast<std::size_t>(i)];
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
    const double left = bound(before_, i);
    const double right = bound(after_, last);
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
  const int n = static_cast<int>(ranges_.size());
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
    find_neighbours();
    const int before = (away < 0 ? before_ : after_)[static_cast<std::size_t>(i)];
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
