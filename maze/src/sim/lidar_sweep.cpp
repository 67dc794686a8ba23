#include "maze/sim/lidar_sweep.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace maze::sim {

namespace {

// std::floor and std::ceil for the sweep's revolution counts (0 <= x < 2^53), inline: the
// library calls were a sixth of the lidar's time. Exact: truncation is floor there.
double floor_of_non_negative(double x) { return static_cast<double>(static_cast<std::int64_t>(x)); }
double ceil_of_positive(double x) {
  const double t = floor_of_non_negative(x);
  return t < x ? t + 1.0 : t;
}

// The first index in [lo, hi) where the predicate, false then true along the range, holds
// (hi when nowhere).
template <typename Predicate>
std::size_t first_true(std::size_t lo, std::size_t hi, Predicate holds) {
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (holds(mid)) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return lo;
}

}  // namespace

LidarSweep::LidarSweep(const LidarModel &model, double revolutions_per_step, double start_revolutions)
    : revolutions_per_step_(revolutions_per_step) {
  assert(revolutions_per_step > 0.0);
  const int n = model.spec().horizontal_resolution;
  for (int i = 0; i < n; ++i) {
    const double u = model.sweep_phase(i) - start_revolutions;
    phase_.push_back(u - std::floor(u));
  }
  by_phase_.resize(static_cast<std::size_t>(n));
  std::iota(by_phase_.begin(), by_phase_.end(), 0);
  std::stable_sort(by_phase_.begin(), by_phase_.end(), [&](int a, int b) {
    return phase_[static_cast<std::size_t>(a)] < phase_[static_cast<std::size_t>(b)];
  });
}

std::int64_t LidarSweep::pass_index(double turned, int i) const {
  const double u = phase_[static_cast<std::size_t>(i)];
  if (turned < u) return -1;
  return static_cast<std::int64_t>(floor_of_non_negative(turned - u));
}

std::int64_t LidarSweep::last_pass_step(std::int64_t steps_enabled, int i) const {
  const double r = revolutions_per_step_;
  const double u = phase_[static_cast<std::size_t>(i)];
  const double turned = static_cast<double>(steps_enabled) * r;
  if (turned < u) return 0;  // not passed yet
  const double k = floor_of_non_negative(turned - u);
  const double last_pass = u + k;  // the last pass at or before now, in revolutions
  if (last_pass <= 0.0) return 0;
  return std::clamp(static_cast<std::int64_t>(ceil_of_positive(last_pass / r)), std::int64_t{1}, steps_enabled);
}

void LidarSweep::last_pass_steps(std::int64_t steps_enabled, std::span<std::int64_t> out) const {
  assert(out.size() == phase_.size());
  const std::size_t n = by_phase_.size();
  if (n == 0) return;
  const double turned = static_cast<double>(steps_enabled) * revolutions_per_step_;
  const auto beam = [&](std::size_t j) { return by_phase_[j]; };
  const auto step_at = [&](std::size_t j) { return last_pass_step(steps_enabled, beam(j)); };
  // pass_index is non-increasing along the phase order and takes at most two values.
  const std::int64_t first_run = pass_index(turned, beam(0));
  const std::size_t split = first_true(0, n, [&](std::size_t j) { return pass_index(turned, beam(j)) != first_run; });
  for (const auto &[lo, hi] : {std::pair{std::size_t{0}, split}, std::pair{split, n}}) {
    for (std::size_t j = lo; j < hi;) {
      const std::int64_t s = step_at(j);
      const std::size_t end = first_true(j + 1, hi, [&](std::size_t m) { return step_at(m) != s; });
      for (std::size_t m = j; m < end; ++m) out[static_cast<std::size_t>(beam(m))] = s;
      j = end;
    }
  }
}

}  // namespace maze::sim
