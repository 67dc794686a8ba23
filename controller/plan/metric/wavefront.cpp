// The wavefront on a plain grid (plan/metric/wavefront.hpp).

#include "plan/metric/wavefront.hpp"

#include <algorithm>
#include <deque>

namespace plan {
namespace {

// N, E, S, W as (di, dj).
constexpr int kSteps[4][2] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};

template <typename Visit>
void for_neighbours(const FlatGrid &g, std::size_t flat, Visit &&visit) {
  const int i = static_cast<int>(flat % static_cast<std::size_t>(g.cells_x));
  const int j = static_cast<int>(flat / static_cast<std::size_t>(g.cells_x));
  for (const auto &s : kSteps) {
    const int ni = i + s[0];
    const int nj = j + s[1];
    if (ni < 0 || nj < 0 || ni >= g.cells_x || nj >= g.cells_y) continue;
    visit(static_cast<std::size_t>(nj) * static_cast<std::size_t>(g.cells_x) + static_cast<std::size_t>(ni));
  }
}

// One line of the running window: the `count` cells `stride` apart from `first` are set in
// `out` when a set cell of `in` on the line lies within `dilate` cells of them.
void dilate_line(const std::vector<bool> &in, std::vector<bool> &out, std::size_t first, std::size_t stride, int count,
                 int dilate) {
  std::vector<int> next(static_cast<std::size_t>(count));  // the nearest set cell at or after each
  int upcoming = 1'000'000;
  for (int k = count - 1; k >= 0; --k) {
    if (in[first + static_cast<std::size_t>(k) * stride]) upcoming = k;
    next[static_cast<std::size_t>(k)] = upcoming;
  }
  int last = -1'000'000;  // the last set cell before
  for (int k = 0; k < count; ++k) {
    const std::size_t flat = first + static_cast<std::size_t>(k) * stride;
    if (in[flat]) last = k;
    out[flat] = k - last <= dilate || next[static_cast<std::size_t>(k)] - k <= dilate;
  }
}

}  // namespace

std::vector<bool> dilated(const FlatGrid &g, const std::vector<bool> &obstacles, int dilate) {
  if (dilate <= 0) return obstacles;
  // Two passes of a running window: along rows, then along columns (a square grown by dilate).
  const auto x = static_cast<std::size_t>(g.cells_x);
  std::vector<bool> rows(g.size(), false);
  for (std::size_t j = 0; j < static_cast<std::size_t>(g.cells_y); ++j) dilate_line(obstacles, rows, j * x, 1, g.cells_x, dilate);
  std::vector<bool> out(g.size(), false);
  for (std::size_t i = 0; i < x; ++i) dilate_line(rows, out, i, x, g.cells_y, dilate);
  return out;
}

std::vector<std::int32_t> wave_from(const FlatGrid &g, const std::vector<bool> &blocked, std::size_t goal) {
  std::vector<std::int32_t> wave(g.size(), kWaveUnreached);
  for (std::size_t n = 0; n < g.size(); ++n) {
    if (blocked[n]) wave[n] = kWaveBlocked;
  }
  if (goal >= g.size() || blocked[goal]) return wave;
  wave[goal] = kWaveGoal;
  std::deque<std::size_t> queue{goal};
  while (!queue.empty()) {
    const std::size_t c = queue.front();
    queue.pop_front();
    for_neighbours(g, c, [&](std::size_t n) {
      if (wave[n] != kWaveUnreached) return;
      wave[n] = wave[c] + 1;
      queue.push_back(n);
    });
  }
  return wave;
}

std::optional<std::vector<std::size_t>> descend(const FlatGrid &g, const std::vector<std::int32_t> &wave,
                                                std::size_t start) {
  if (start >= g.size() || wave[start] < kWaveGoal) return std::nullopt;
  std::vector<std::size_t> path{start};
  std::size_t c = start;
  while (wave[c] != kWaveGoal) {
    std::size_t best = c;
    for_neighbours(g, c, [&](std::size_t n) {
      if (wave[n] >= kWaveGoal && wave[n] < wave[best]) best = n;
    });
    if (best == c) return std::nullopt;  // cannot happen on a wave; guards the loop
    c = best;
    path.push_back(c);
  }
  return path;
}

std::vector<std::int32_t> steps_from(const FlatGrid &g, const std::vector<bool> &blocked, std::size_t start) {
  std::vector<std::int32_t> steps(g.size(), -1);
  if (start >= g.size() || blocked[start]) return steps;
  steps[start] = 0;
  std::deque<std::size_t> queue{start};
  while (!queue.empty()) {
    const std::size_t c = queue.front();
    queue.pop_front();
    for_neighbours(g, c, [&](std::size_t n) {
      if (steps[n] >= 0 || blocked[n]) return;
      steps[n] = steps[c] + 1;
      queue.push_back(n);
    });
  }
  return steps;
}

}  // namespace plan
