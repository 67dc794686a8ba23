// Frontier exploration over a metric map (explore/metric/frontier.hpp).

#include "explore/metric/frontier.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <utility>

namespace explore {
namespace {

using sensing::MetricCell;

constexpr std::pair<int, int> kNeighbours[] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};

bool seen_free(const sensing::MetricMap &map, std::size_t n) {
  return !map.unobserved_at(n) && map.probability_at(n) < 0.5;
}

// Seen free and never marked occupied: a beam may cross it into the cell beside it.
bool seen_clear(const sensing::MetricMap &map, std::size_t n) {
  return seen_free(map, n) && !map.marked_occupied_at(n);
}

// Cells within view_cells steps (over cells not seen occupied) of a frontier cell: their
// steps (-1 beyond), and the frontier cell each is nearest.
struct FrontierView {
  std::vector<std::int32_t> steps;
  std::vector<std::size_t> nearest;
};

FrontierView spread_view(const sensing::MetricMap &map, double free_below_p, const std::vector<bool> &aims,
                         int view_cells) {
  FrontierView view{std::vector<std::int32_t>(map.size(), -1), std::vector<std::size_t>(map.size(), 0)};
  std::deque<std::size_t> queue;
  for (std::size_t n = 0; n < map.size(); ++n) {
    if (!aims[n]) continue;
    view.steps[n] = 0;
    view.nearest[n] = n;
    queue.push_back(n);
  }
  while (!queue.empty()) {
    const std::size_t c = queue.front();
    queue.pop_front();
    if (view.steps[c] >= view_cells) continue;
    const MetricCell rc = map.cell_of_index(c);
    for (const auto &d : kNeighbours) {
      const MetricCell nb{rc.i + d.first, rc.j + d.second};
      if (!map.contains(nb)) continue;
      const std::size_t k = map.index(nb);
      if (view.steps[k] >= 0 || map.probability_at(k) >= free_below_p - 1e-9) continue;
      view.steps[k] = view.steps[c] + 1;
      view.nearest[k] = view.nearest[c];
      queue.push_back(k);
    }
  }
  return view;
}

// Whether the line between two cells' centres crosses no cell seen occupied (besides `to`).
bool sees(const sensing::MetricMap &map, double free_below_p, std::size_t from, std::size_t to) {
  const mapping::Point a = map.centre_of(map.cell_of_index(from));
  const mapping::Point b = map.centre_of(map.cell_of_index(to));
  const double length = std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
  const int samples = static_cast<int>(std::ceil(length / (map.cell_m() / 4)));
  for (int k = 1; k < samples; ++k) {
    const double f = static_cast<double>(k) / samples;
    const auto c = map.cell_at({a.x_m + f * (b.x_m - a.x_m), a.y_m + f * (b.y_m - a.y_m)});
    if (!c) return false;
    const std::size_t n = map.index(*c);
    if (n != to && map.probability_at(n) >= free_below_p - 1e-9) return false;
  }
  return true;
}

}  // namespace

MapProgress progress_of(const sensing::MetricMap &map, std::size_t free_for_planning, const MapProgress &before) {
  MapProgress now;
  for (std::size_t n = 0; n < map.size(); ++n) now.observed += map.unobserved_at(n) ? 0U : 1U;
  now.observed = std::max(now.observed, before.observed);
  now.free_for_planning = std::max(free_for_planning, before.free_for_planning);
  return now;
}

bool is_frontier_cell(const sensing::MetricMap &map, std::size_t n, bool occupied_marks_are_echo_ends) {
  if (!map.unobserved_at(n)) return false;
  const MetricCell c = map.cell_of_index(n);
  for (const auto &d : kNeighbours) {
    const MetricCell nb{c.i + d.first, c.j + d.second};
    if (!map.contains(nb)) continue;
    const std::size_t k = map.index(nb);
    if (occupied_marks_are_echo_ends ? seen_clear(map, k) : seen_free(map, k)) return true;
  }
  return false;
}

std::vector<bool> frontier_cells(const sensing::MetricMap &map, bool occupied_marks_are_echo_ends) {
  std::vector<bool> cells(map.size(), false);
  for (std::size_t n = 0; n < map.size(); ++n) cells[n] = is_frontier_cell(map, n, occupied_marks_are_echo_ends);
  return cells;
}

void FrontierVisits::visited(std::size_t cell, bool still_unobserved, const MapProgress &now) {
  attempts_[cell] = static_cast<std::uint8_t>(std::min(attempts_[cell] + 1, 255));
  if (still_unobserved && attempts_[cell] >= kMaxFrontierAttempts) set_aside(cell, now);
}

void FrontierVisits::set_aside(std::size_t cell, const MapProgress &now) {
  aside_[cell] = true;
  aside_at_[cell] = now;
}

std::optional<FrontierTarget> frontier_target(const sensing::MetricMap &map, double free_below_p,
                                              const std::vector<bool> &aims, int view_cells,
                                              const FrontierVisits &visits, const std::vector<std::int32_t> &steps,
                                              const std::vector<std::int32_t> *gain) {
  const FrontierView view = spread_view(map, free_below_p, aims, view_cells);
  std::vector<std::size_t> candidates;
  for (std::size_t n = 0; n < map.size(); ++n) {
    if (steps[n] < 0 || view.steps[n] < 0) continue;
    // Each visit that left its frontier cell unobserved brings the next one nearer to it.
    const int halvings = std::min(visits.attempts(view.nearest[n]), kMaxFrontierAttempts);
    if (view.steps[n] <= std::max(1, view_cells >> halvings)) candidates.push_back(n);
  }
  const auto cost = [&](std::size_t n) {
    return std::int64_t{kPathWeight} * steps[n] - (gain != nullptr ? (*gain)[view.nearest[n]] : 0);
  };
  std::stable_sort(candidates.begin(), candidates.end(), [&cost](std::size_t a, std::size_t b) { return cost(a) < cost(b); });
  for (const std::size_t n : candidates) {
    if (sees(map, free_below_p, n, view.nearest[n])) return FrontierTarget{n, view.nearest[n]};
  }
  return std::nullopt;
}

}  // namespace explore
