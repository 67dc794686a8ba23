#include "app/report/grid_history.hpp"

#include <algorithm>
#include <span>

namespace app {

GridHistory::GridHistory(const mapping::GridGeometry &geometry, float initial_log_odds)
    : geometry_(geometry), initial_log_odds_(initial_log_odds),
      last_(static_cast<std::size_t>(geometry.width_subcells()) * static_cast<std::size_t>(geometry.height_subcells()),
            initial_log_odds) {}

void GridHistory::record(std::int64_t step, const mapping::OccupancyGrid &grid) {
  const std::span<const float> now = grid.values();
  for (std::size_t i = 0; i < now.size(); ++i) {
    if (now[i] == last_[i]) continue;
    last_[i] = now[i];
    changes_.push_back(Change{step, static_cast<std::uint32_t>(i), now[i]});
  }
}

void GridHistory::record(std::int64_t step, const mapping::OccupancyGrid &grid, std::vector<std::uint32_t> &written) {
  // Sorted, so that the changes of one call come in index order as the whole-grid compare gives them.
  std::sort(written.begin(), written.end());
  written.erase(std::unique(written.begin(), written.end()), written.end());
  for (const std::uint32_t i : written) {
    const float now = grid.at_index(i);
    if (now == last_[i]) continue;
    last_[i] = now;
    changes_.push_back(Change{step, i, now});
  }
  written.clear();
}

void GridHistory::arrived(std::int64_t step, mapping::Cell cell, mapping::Heading heading) {
  arrivals_.push_back(Arrival{step, cell, heading});
}

mapping::OccupancyGrid GridHistory::grid_at(std::int64_t step) const {
  mapping::OccupancyGrid grid(geometry_, initial_log_odds_);
  for (const Change &c : changes_) {
    if (c.step > step) break;
    grid.at_index(c.index) = c.value;
  }
  return grid;
}

std::vector<mapping::Cell> GridHistory::path_at(std::int64_t step) const {
  std::vector<mapping::Cell> path;
  for (const Arrival &a : arrivals_) {
    if (a.step > step) break;
    path.push_back(a.cell);
  }
  return path;
}

std::vector<std::int64_t> snapshot_steps(std::int64_t steps, int count) {
  std::vector<std::int64_t> at;
  for (int i = 1; i <= count; ++i) at.push_back(steps * i / count);
  return at;
}

}  // namespace app
