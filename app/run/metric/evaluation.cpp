// A room run's score (app/run/metric/evaluation.hpp).

#include "app/run/metric/evaluation.hpp"

#include <fmt/format.h>

namespace app {

std::size_t score_metric_map(const sensing::MetricMap &map, const maze::TruthRaster &truth, double threshold,
                           MetricRunSummary &summary) {
  summary.cells_total = map.size();
  for (std::size_t n = 0; n < map.size(); ++n) {
    const bool says_occupied = map.log_odds_at(n) >= threshold;
    const bool right = says_occupied == (truth.occupied[n] != 0);
    summary.cells_right += right ? 1 : 0;
    if (!map.unobserved_at(n)) {
      ++summary.observed_cells;
      summary.observed_cells_right += right ? 1 : 0;
    }
  }
  std::size_t first_left = map.size();
  for (std::size_t n = 0; n < map.size(); ++n) {
    if (truth.reachable[n] == 0) continue;
    ++summary.reachable_free;
    if (!map.unobserved_at(n)) {
      ++summary.reachable_free_observed;
    } else if (first_left == map.size()) {
      first_left = n;
    }
  }
  return first_left;
}

void settle_frontier_ending(const sensing::MetricMap &map, std::size_t first_left, MetricRunSummary &summary) {
  const bool all_seen = summary.reachable_free_observed == summary.reachable_free;
  if (summary.ending == robot::MetricEnding::incomplete && all_seen) {
    // What the robot could not observe lies in obstacles or out of reach: the free space is mapped.
    summary.ending = robot::MetricEnding::done;
    summary.message += fmt::format(", none of them reachable free space: every one of the {} reachable free cells "
                                   "is observed", summary.reachable_free);
  }
  if (summary.ending == robot::MetricEnding::done && !all_seen) {
    // The controller found no frontier, yet reachable free space is unobserved: not done.
    const mapping::Point p = map.centre_of(map.cell_of_index(first_left));
    summary.ending = robot::MetricEnding::incomplete;
    summary.message = fmt::format("{} of {} reachable free cells never observed (the first at {:.2f}, {:.2f})",
                                  summary.reachable_free - summary.reachable_free_observed, summary.reachable_free,
                                  p.x_m, p.y_m);
  }
}

}  // namespace app
