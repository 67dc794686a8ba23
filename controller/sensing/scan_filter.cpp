#include "sensing/scan_filter.hpp"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <cmath>
#include <string_view>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "common/error.hpp"

namespace sensing {
namespace {

constexpr float kNoInformation = std::numeric_limits<float>::quiet_NaN();
constexpr double kNaNRange = std::numeric_limits<double>::quiet_NaN();
// Rounds of spike rejection: a rejection can only leave a neighbour's neighbour without
// support, so a few rounds settle any cluster of spikes a 1 % fault rate makes.
constexpr int kSpikeRounds = 4;

// Per beam. A trusted return either continues the trusted return of the beam before it
// (agrees with it) or starts a stretch: only those can be spikes or see-through clusters,
// so each round looks at them alone. Trusted states have bit 1 set.
enum BeamState : unsigned char {
  no_return_or_invalid = 0,
  rejected_return = 1,
  trusted_start = 2,
  trusted_continuing = 3,
  spike_candidate = 4,  // within reject_spikes only: not trusted while the candidates are looked at again
};

bool full_circle(const LidarScan &scan) { return scan.fov_rad >= 2.0 * std::numbers::pi - 1e-9; }

// "scan filter: WHAT must be LOW to HIGH beams (got N)" for a count outside its range.
void require_beams(int beams, int low, int high, std::string_view what) {
  if (beams >= low && beams <= high) return;
  throw common::InputError(fmt::format("scan filter: {} must be {} to {} beams (got {})", what, low, high, beams));
}

// "scan filter: WHAT must be a finite number of m >= 0 (got X)" for a length that is not.
void require_metres(double length_m, std::string_view what) {
  if (length_m >= 0.0 && std::isfinite(length_m)) return;
  throw common::InputError(fmt::format("scan filter: {} must be a finite number of m >= 0 (got {})", what, length_m));
}

}  // namespace

void validate(const ScanFilterOptions &options) {
  require_metres(options.range_noise_m, "range noise");
  require_beams(options.neighbour_reach, 1, 10, "neighbour reach");
  require_beams(options.max_see_through, 1, 8, "see-through cluster");
  if (!(options.max_grazing_rad >= 0.0 && options.max_grazing_rad < std::numbers::pi / 2.0)) {
    throw common::InputError(fmt::format("scan filter: grazing angle must be at least 0 and below pi/2 rad (got {})",
                                         options.max_grazing_rad));
  }
  require_beams(options.max_dropout_run, 0, 32, "dropout run");
  require_beams(options.min_repeated_view, 1, 32, "repeated view");
  require_metres(options.same_pose_m, "same-pose distance");
}

// What every rule reads, in locals for the rules' loops: the beams as they stand in a round
// (states change only between rounds) and the scan's constants.
struct ScanFilter::Beams {
  const float *range_m;
  const unsigned char *state;
  int n;          // beams (at least 3 for the rules)
  int reach;      // neighbour reach, 1 ... (n - 1) / 2 beams for the rules
  bool wrap;      // a full circle: beam 0 follows beam n - 1
  double absolute_m;  // spike tolerance, m
  double relative;    // its growth per metre of range between neighbouring beams

  bool trusted(int i) const { return i >= 0 && (state[i] & trusted_start) != 0; }
  double range(int i) const { return range_m[i]; }
  // The range of beam i, or NaN for -1.
  double range_or_nan(int i) const { return i < 0 ? kNaNRange : static_cast<double>(range_m[i]); }
  // Whether two returns agree: within the tolerance, which grows with range.
  bool near(double a, double b) const { return std::abs(a - b) <= absolute_m + relative * std::min(a, b); }
  // The next and previous beams, wrapped on a full circle; -1 past the ends of a partial one.
  int next(int i) const { return i < n - 1 ? i + 1 : (wrap ? 0 : -1); }
  int previous(int i) const { return i > 0 ? i - 1 : (wrap ? n - 1 : -1); }
  // Beam i read no return (not an invalid reading, not a return).
  bool no_return(int i) const { return i >= 0 && state[i] == no_return_or_invalid && !std::isnan(range_m[i]); }
  // A return with no return on both sides: a real one whose neighbours were both dropped,
  // or a spike in a view past max range. Only a neighbouring return that is not lone itself
  // vouches for it: two spikes a few beams apart in a view must not vouch for each other.
  bool lone_return(int i) const { return no_return(previous(i)) && no_return(next(i)); }

  // The nearest trusted return within reach of beam i going `step` (-1 or +1), or -1.
  int nearest_trusted(int i, int step) const {
    int j = i;
    for (int d = 1; d <= reach; ++d) {
      j += step;
      if (j < 0 || j >= n) {
        if (!wrap) return -1;
        j = j < 0 ? j + n : j - n;  // reach < n: wrapped once at most
      }
      if ((state[j] & trusted_start) != 0) return j;
    }
    return -1;
  }

  // Beam i's range as the two nearest trusted returns going `step` predict it, a surface
  // receding by a steady ratio a beam (a wall seen at a grazing angle), m; NaN without them
  // or when a third return does not follow the same ratio.
  double continued(int i, int step) const {
    const int a = nearest_trusted(i, step);
    const int b = a < 0 ? -1 : nearest_trusted(a, step);
    const int c = b < 0 ? -1 : nearest_trusted(b, step);
    if (c < 0 || b == i || c == i || c == a) return kNaNRange;
    const double ra = range(a);
    const double rb = range(b);
    const double rc = range(c);
    // Only a surface: the three returns must follow the same ratio, so a spike cannot lend
    // its jump as a trend.
    const double predicted_a = rb * rb / rc;
    const double tolerance = absolute_m + relative * std::min(ra, predicted_a);
    if (!(std::abs(ra - predicted_a) <= tolerance)) return kNaNRange;
    return ra * ra / rb;
  }
};

ScanFilter::ScanFilter(const ScanFilterOptions &options) : options_((validate(options), options)) {}

LidarScan ScanFilter::apply(const LidarScan &scan) { return filter(scan, nullptr); }

LidarScan ScanFilter::apply(const LidarScan &scan, const LidarScan &before) {
  return filter(scan, same_pose(scan, before) ? &before : nullptr);
}

bool ScanFilter::same_pose(const LidarScan &scan, const LidarScan &before) const {
  const int n = scan.beam_count();
  if (n == 0 || before.beam_count() != n || before.fov_rad != scan.fov_rad) return false;
  const double quarter_step_rad = scan.fov_rad / n / 4.0;
  const double turned_rad = std::remainder(scan.yaw_rad - before.yaw_rad, 2.0 * std::numbers::pi);
  return std::hypot(scan.origin.x_m - before.origin.x_m, scan.origin.y_m - before.origin.y_m) <= options_.same_pose_m &&
         std::abs(turned_rad) <= quarter_step_rad;
}

LidarScan ScanFilter::filter(const LidarScan &scan, const LidarScan *before) {
  counts_ = {};
  const std::size_t size = scan.ranges.size();
  const int n = static_cast<int>(size);
  // Every rule's constants, once per scan (grazing_step takes a tangent).
  wrap_ = full_circle(scan);
  reach_ = std::min(options_.neighbour_reach, (n - 1) / 2);
  absolute_m_ = options_.spike_tolerance_m();
  relative_ = size > 0 ? options_.grazing_step(scan.fov_rad / n) : 0.0;
  // No allocation once the filter has seen a scan this size.
  ranges_.resize(size);
  state_.resize(size);
  starts_.clear();
  starts_.reserve(size);
  rejected_.reserve(size);
  float *range_m = ranges_.data();
  unsigned char *state = state_.data();
  const Beams b = beams();
  // One pass: each reading's kind, and whether a return continues the one before it.
  std::size_t returns = 0;
  bool previous_trusted = false;
  double previous_m = 0.0;
  for (std::size_t i = 0; i < size; ++i) {
    const float r = scan.ranges[i];
    const ReadingKind kind = scan.kind_of(r);
    if (kind == ReadingKind::hit) {
      range_m[i] = r;
      if (previous_trusted && b.near(previous_m, r)) {
        state[i] = trusted_continuing;
      } else {
        state[i] = trusted_start;
        starts_.push_back(static_cast<int>(i));
      }
      previous_trusted = true;
      previous_m = r;
      ++returns;
      continue;
    }
    previous_trusted = false;
    state[i] = no_return_or_invalid;
    if (kind == ReadingKind::invalid) {
      range_m[i] = kNoInformation;
      ++counts_.invalid;
    } else {
      range_m[i] = r;
    }
  }
  if (size >= 3) {
    // On a full circle beam 0 continues the last beam.
    if (wrap_ && state[0] == trusted_start && b.trusted(n - 1) && b.near(b.range(n - 1), b.range(0))) {
      state[0] = trusted_continuing;
      starts_.erase(starts_.begin());
    }
    // A rejection takes a neighbour's support away: go again until nothing changes.
    for (int round = 0; round < kSpikeRounds; ++round) {
      const bool spikes = reject_spikes();
      const bool see_through = reject_see_through();
      if (!spikes && !see_through) break;
    }
    // Rejections keep a beam a return: every beam returned, nothing to drop.
    if (returns < size) drop_dropouts(before);
  }
  LidarScan out = scan;
  out.ranges = ranges_;
  return out;
}

ScanFilter::Beams ScanFilter::beams() const {
  return {ranges_.data(), state_.data(), static_cast<int>(ranges_.size()), reach_, wrap_, absolute_m_, relative_};
}

bool ScanFilter::reject_spikes() {
  const Beams b = beams();
  rejected_.clear();
  for (const int i : starts_) {
    // A beam that continues the one before (the nearest trusted return before it) agrees
    // with it: not a spike.
    if (b.state[i] != trusted_start) continue;
    if (b.lone_return(i)) {
      // Only a return that is not lone itself vouches for a lone one.
      const auto vouches = [&](int j) { return j >= 0 && !b.lone_return(j) && b.near(b.range(i), b.range(j)); };
      if (!vouches(b.nearest_trusted(i, -1)) && !vouches(b.nearest_trusted(i, +1))) rejected_.push_back(i);
      continue;
    }
    const double r = b.range(i);
    // NaN compares false: a missing neighbour supports nothing.
    const auto near = [&](double other) { return b.near(r, other); };
    const double left = b.range_or_nan(b.nearest_trusted(i, -1));
    const double right = b.range_or_nan(b.nearest_trusted(i, +1));
    const bool between = std::min(left, right) - b.absolute_m <= r && r <= std::max(left, right) + b.absolute_m;
    if (near(left) || near(right) || between) continue;
    if (near(b.continued(i, -1)) || near(b.continued(i, +1))) continue;
    rejected_.push_back(i);
  }
  keep_vouched_candidates();
  return reject_collected();
}

void ScanFilter::keep_vouched_candidates() {
  if (rejected_.empty()) return;
  for (const int i : rejected_) state_[static_cast<std::size_t>(i)] = spike_candidate;
  const Beams b = beams();
  // The nearest trusted returns now skip every candidate.
  const auto vouched = [&](int i) {
    for (const int step : {-1, +1}) {
      const int j = b.nearest_trusted(i, step);
      if (j >= 0 && b.near(b.range(i), b.range(j)) && !(b.lone_return(i) && b.lone_return(j))) return true;
    }
    return false;
  };
  std::vector<int> &kept = starts_scratch_;
  kept.clear();
  std::erase_if(rejected_, [&](int i) {
    const bool keep = vouched(i);
    if (keep) kept.push_back(i);
    return keep;
  });
  for (const int i : kept) state_[static_cast<std::size_t>(i)] = trusted_start;
}

bool ScanFilter::reject_collected() {
  if (rejected_.empty()) return false;
  const Beams b = beams();
  for (const int i : rejected_) {
    state_[static_cast<std::size_t>(i)] = rejected_return;
    ranges_[static_cast<std::size_t>(i)] = kNoInformation;
    ++counts_.spikes;
  }
  // The beam after a rejected one never continued it: a spike agrees with neither
  // neighbour, and a see-through cluster ends where the next beam disagrees.
  for (const int i : rejected_) {
    const int after = b.next(i);
    assert(after < 0 || state_[static_cast<std::size_t>(after)] != trusted_continuing);
    static_cast<void>(after);
  }
  std::erase_if(starts_, [&](int i) { return state_[static_cast<std::size_t>(i)] != trusted_start; });
  return true;
}

bool ScanFilter::reject_see_through() {
  const Beams b = beams();
  const int widest = options_.max_see_through;
  rejected_.clear();
  for (const int i : starts_) {
    // A cluster starts at a trusted return that does not continue the one before it.
    if (b.state[i] != trusted_start) continue;
    int last = i;
    double nearest_m = b.range(i);
    for (int size = 1; size < widest; ++size) {
      const int next = b.next(last);
      if (!b.trusted(next) || !b.near(b.range(last), b.range(next)) || next == i) break;
      last = next;
      nearest_m = std::min(nearest_m, b.range(last));
    }
    const int after = b.next(last);
    if (b.trusted(after) && b.near(b.range(last), b.range(after))) continue;  // longer than a few beams
    // The nearest trusted returns on both sides, or NaN.
    const double left = b.range_or_nan(b.nearest_trusted(i, -1));
    const double right = b.range_or_nan(b.nearest_trusted(last, +1));
    // Further than both sides (NaN compares false: a missing side clears it).
    if (nearest_m > left + b.absolute_m + b.relative * left && nearest_m > right + b.absolute_m + b.relative * right) {
      for (int j = i;; j = b.next(j)) {
        rejected_.push_back(j);
        if (j == last) break;
      }
    }
  }
  return reject_collected();
}

void ScanFilter::drop_dropouts(const LidarScan *before) {
  const Beams b = beams();
  const int n = b.n;
  // A beam that returned something, trusted or not, ends a run.
  const auto returned = [&](int i) { return b.state[i] != no_return_or_invalid; };
  // Beam `first` + offset, offset 0 ... n.
  const auto wrapped = [&](int i) { return i < n ? i : i - n; };
  // The first offset from `from` to `to` (beams `first` + offset) without a return, or `to`.
  const auto next_no_return = [&](int first, int from, int to) {
    for (int o = from; o < to;) {
      const int i = wrapped(first + o);
      const int length = std::min(to - o, n - i);  // up to the end of the beams
      const void *found = std::memchr(b.state + i, no_return_or_invalid, static_cast<std::size_t>(length));
      if (found != nullptr) return o + static_cast<int>(static_cast<const unsigned char *>(found) - (b.state + i));
      o += length;
    }
    return to;
  };
  // A run (offsets [from, to) from `first`) that the scan before read without a return on
  // every beam: a view past max range seen again.
  const auto repeated_view = [&](int first, int from, int to) {
    if (before == nullptr || to - from < options_.min_repeated_view) return false;
    for (int o = from; o < to; ++o) {
      if (before->kind(wrapped(first + o)) != ReadingKind::no_return) return false;
    }
    return true;
  };
  // Start at a return so that a run never wraps past the start unseen.
  int first = -1;
  for (int i = 0; i < n && first < 0; ++i) {
    if (returned(i)) first = i;
  }
  if (first < 0) return;  // no return at all: every no return stands
  // A partial field of view: the runs before the first return and after the last have a
  // return on one side only; they stand.
  const int span = b.wrap ? n : n - first;
  // Each run of beams without a return, offsets [run_start, end) from `first`, ended by the
  // return at offset `end` (the start again on a full circle) or by the last beam.
  for (int run_start = next_no_return(first, 1, span); run_start < span;) {
    int end = run_start + 1;
    while (end < span && !returned(wrapped(first + end))) ++end;
    const bool bounded = end < span || b.wrap;
    if (bounded && end - run_start <= options_.max_dropout_run && !repeated_view(first, run_start, end)) {
      for (int o = run_start; o < end; ++o) {
        float &r = ranges_[static_cast<std::size_t>(wrapped(first + o))];
        if (std::isnan(r)) continue;  // invalid: counted already
        r = kNoInformation;
        ++counts_.dropouts;
      }
    }
    run_start = end + 1 < span ? next_no_return(first, end + 1, span) : span;
  }
}

}  // namespace sensing
