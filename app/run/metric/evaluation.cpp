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
  const bool ended_by_frontier =
      summary.ending == robot::MetricEnding::done || summary.ending == robot::MetricEnding::incomplete;
  if (!ended_by_frontier) return;
  std::string detail = summary.message;
  // The truth decides: done when every reachable free cell is observed, whatever frontier
  // cells the controller left (in obstacles or out of reach); incomplete otherwise.
  summary.ending = all_seen ? robot::MetricEnding::done : robot::MetricEnding::incomplete;
  if (!all_seen) {
    const mapping::Point p = map.centre_of(map.cell_of_index(first_left));
    detail += fmt::format("; {} of {} reachable free cells never observed (the first at {:.2f}, {:.2f})",
                          summary.reachable_free - summary.reachable_free_observed, summary.reachable_free, p.x_m,
                          p.y_m);
  }
  summary.message = fmt::format("{:.2f} % of the reachable free cells observed", 100.0 * summary.observed_share());
  if (summary.frontier) summary.frontier->detail = detail;
}

}  // namespace app
