#include "plan/cell/wavefront.hpp"

#include <cassert>
#include <cmath>
#include <cstdint>
#include <deque>

#include <fmt/format.h>

#include "common/error.hpp"

namespace plan {
namespace {

// Grid values are floats: l(0.6) stored and read back is p = 0.59999997, which must still
// count as "not below 0.6" (one observation with the default p_occ is an obstacle).
constexpr double kProbabilityTolerance = 1e-6;

}  // namespace

using mapping::Cell;
using mapping::SubCell;

void validate(const WavefrontOptions &options) {
  if (options.dilate < 0 || options.dilate > kMaxDilate) {
    throw common::InputError(
        fmt::format("--dilate must be between 0 and {} sub-cells (got {})", kMaxDilate, options.dilate));
  }
  if (!(options.free_below_p > 0.0 && options.free_below_p <= 1.0)) {
    throw common::InputError(
        fmt::format("the free threshold must be in (0, 1] (got {})", options.free_below_p));
  }
}

std::vector<bool> obstacles(const mapping::OccupancyGrid &grid, const mapping::SensorModel &model,
                            const WavefrontOptions &options) {
  const int w = grid.geometry().width_subcells();
  const int h = grid.geometry().height_subcells();
  std::vector<bool> blocked(grid.size(), false);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float value = grid.at(SubCell{x, y});
      const bool unknown = value == static_cast<float>(model.prior_log_odds());
      if (!(options.unknown_blocked && unknown) &&
          model.probability_of(value) < options.free_below_p - kProbabilityTolerance) {
        continue;
      }
      const int n = options.dilate;
      for (int yy = std::max(0, y - n); yy <= std::min(h - 1, y + n); ++yy) {
        for (int xx = std::max(0, x - n); xx <= std::min(w - 1, x + n); ++xx) {
          blocked[grid.index(SubCell{xx, yy})] = true;
        }
      }
    }
  }
  return blocked;
}

std::optional<Path> wavefront(const mapping::OccupancyGrid &grid, const mapping::SensorModel &model,
                              Cell from, Cell to, const WavefrontOptions &options) {
  assert(grid.contains(from) && grid.contains(to));
  const int k = grid.k();
  const SubCell start = mapping::to_global(from, {k / 2, k / 2}, k);
  const SubCell goal = mapping::to_global(to, {k / 2, k / 2}, k);
  const std::vector<bool> blocked = obstacles(grid, model, options);
  if (blocked[grid.index(start)] || blocked[grid.index(goal)]) return std::nullopt;
  constexpr std::int32_t kUnset = -1;
  std::vector<std::int32_t> wave(grid.size(), kUnset);
  constexpr int step_x[] = {0, 1, 0, -1};  // N, E, S, W
  constexpr int step_y[] = {1, 0, -1, 0};
  std::deque<SubCell> queue{goal};
  wave[grid.index(goal)] = 0;
  while (!queue.empty() && wave[grid.index(start)] == kUnset) {
    const SubCell s = queue.front();
    queue.pop_front();
    const std::int32_t next = wave[grid.index(s)] + 1;
    for (int d = 0; d < 4; ++d) {
      const SubCell n{s.x + step_x[d], s.y + step_y[d]};
      if (!grid.contains(n)) continue;
      const std::size_t i = grid.index(n);
      if (blocked[i] || wave[i] != kUnset) continue;
      wave[i] = next;
      queue.push_back(n);
    }
  }
  if (wave[grid.index(start)] == kUnset) return std::nullopt;
  Path path;
  path.subcells.push_back(start);
  SubCell s = start;
  while (wave[grid.index(s)] > 0) {
    for (int d = 0; d < 4; ++d) {
      const SubCell n{s.x + step_x[d], s.y + step_y[d]};
      if (grid.contains(n) && wave[grid.index(n)] == wave[grid.index(s)] - 1) {
        if (mapping::cell_of(n, k) != mapping::cell_of(s, k)) ++path.length_cells;
        s = n;
        break;
      }
    }
    path.subcells.push_back(s);
  }
  path.length_subcells = static_cast<int>(path.subcells.size()) - 1;
  return path;
}

std::vector<bool> path_mask(const mapping::OccupancyGrid &grid, const Path &path) {
  std::vector<bool> mask(grid.size(), false);
  for (const SubCell s : path.subcells) mask[grid.index(s)] = true;
  return mask;
}

}  // namespace plan
