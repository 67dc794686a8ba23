// The body sweep over a metric map (explore/metric/sweep.hpp).

#include "explore/metric/sweep.hpp"

#include <algorithm>
#include <cmath>

namespace explore {
namespace {

using mapping::Point;
using sensing::MetricCell;

// How much nearer than the body's radius the centre comes to the centre of a frontier cell it
// cannot stand on (the edge of the grid or a cell seen occupied beyond it).
constexpr double kCoverMargin_m = 0.015;

constexpr std::pair<int, int> kSteps[] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};

int reach_cells(const sensing::MetricMap &map) { return static_cast<int>(std::floor(kSweepReach_m / map.cell_m())); }

// The last cell from c on, a step d at a time, while `on` holds and the body clears the edge.
MetricCell run_end(const BodyView &view, MetricCell c, std::pair<int, int> d, const std::function<bool(std::size_t)> &on) {
  const sensing::MetricMap &map = view.map;
  for (int k = 0; k < reach_cells(map); ++k) {
    const MetricCell next{c.i + d.first, c.j + d.second};
    if (!map.contains(next) || !body_clear_at_edge(view, map.centre_of(next)) || !on(map.index(next))) break;
    c = next;
  }
  return c;
}

// From the edge cell t of the ground reached, a step d at a time over cells the map closes, to
// the first unobserved cell within reach; none when there is none.
std::optional<MetricCell> first_unobserved_past(const BodyView &view, MetricCell t, std::pair<int, int> d,
                                                const std::vector<std::int32_t> &steps) {
  const sensing::MetricMap &map = view.map;
  MetricCell c{t.i + d.first, t.j + d.second};
  if (!map.contains(c) || steps[map.index(c)] >= 0) return std::nullopt;
  for (int k = 0; k < reach_cells(map) && map.contains(c) && body_clear_at_edge(view, map.centre_of(c)); ++k) {
    if (map.unobserved_at(map.index(c))) return c;
    c = {c.i + d.first, c.j + d.second};
  }
  return std::nullopt;
}

// Whether `holds` holds for every cell a body centred at p overlaps (a cell off the grid: no).
bool all_cells_under(const BodyView &view, Point p, const std::function<bool(std::size_t)> &holds) {
  const double r = view.body_radius_m;
  const sensing::MetricMap &map = view.map;
  const auto lo = map.cell_at({p.x_m - r, p.y_m - r});
  const auto hi = map.cell_at({p.x_m + r, p.y_m + r});
  if (!lo || !hi) return false;
  for (int j = lo->j; j <= hi->j; ++j) {
    for (int i = lo->i; i <= hi->i; ++i) {
      const Point c = map.centre_of({i, j});
      const double h = map.cell_m() / 2;
      const double gx = std::max(0.0, std::abs(p.x_m - c.x_m) - h);
      const double gy = std::max(0.0, std::abs(p.y_m - c.y_m) - h);
      if (std::hypot(gx, gy) >= r) continue;  // the square is out of the body's reach
      if (!holds(map.index({i, j}))) return false;
    }
  }
  return true;
}

}  // namespace

bool body_clear_at_edge(const BodyView &view, Point p) {
  const double r = view.body_radius_m;
  const sensing::MetricMap &map = view.map;
  const auto &b = map.spec().boundary;
  const double x_end = b.x_start_m + map.cells_x() * map.cell_m();
  const double y_end = b.y_start_m + map.cells_y() * map.cell_m();
  return p.x_m - r >= b.x_start_m && p.y_m - r >= b.y_start_m && p.x_m + r <= x_end && p.y_m + r <= y_end;
}

bool body_clear_at(const BodyView &view, Point p) {
  return body_clear_at_edge(view, p) && all_cells_under(view, p, [&](std::size_t n) { return !view.seen_occupied(n); });
}

bool body_path_adds_nothing(const BodyView &view, Point from, Point to) {
  const double length_m = std::hypot(to.x_m - from.x_m, to.y_m - from.y_m);
  const int samples = 1 + static_cast<int>(std::ceil(length_m / (view.map.cell_m() / 2)));
  for (int k = 0; k <= samples; ++k) {
    const double t = static_cast<double>(k) / samples;
    const Point p{from.x_m + t * (to.x_m - from.x_m), from.y_m + t * (to.y_m - from.y_m)};
    const auto c = view.map.cell_at(p);
    if (!c || !view.covered_or_seen_free(view.map.index(*c))) return false;
    if (!all_cells_under(view, p, [&](std::size_t n) { return !view.map.unobserved_at(n); })) return false;
  }
  return true;
}

std::optional<SweepLeg> sweep_leg(const BodyView &view, const std::vector<bool> &grown,
                                  const std::vector<std::int32_t> &steps, const std::vector<bool> &swept) {
  const sensing::MetricMap &map = view.map;
  std::optional<SweepLeg> best;
  std::int32_t best_steps = -1;
  for (std::size_t n = 0; n < map.size(); ++n) {
    if (swept[n] || !map.unobserved_at(n)) continue;
    const MetricCell f = map.cell_of_index(n);
    for (const auto &d : kSteps) {
      const MetricCell t{f.i - d.first, f.j - d.second};
      if (!map.contains(t)) continue;
      const std::size_t from = map.index(t);
      if (steps[from] < 0 || (best && steps[from] >= best_steps) || !view.covered_or_seen_free(from)) continue;
      const Point a = map.centre_of(t);
      Point end = map.centre_of(f);
      if (grown[n]) {
        // The body cannot stand on it: come as near as covers its centre.
        const double s = std::max(0.0, map.cell_m() - view.body_radius_m + kCoverMargin_m);
        end = {a.x_m + s * d.first, a.y_m + s * d.second};
        if (s >= map.cell_m() || !body_clear_at(view, end)) continue;
      } else {
        // Stand on it, and go on straight over unobserved ground the body clears.
        end = map.centre_of(run_end(view, f, d, [&](std::size_t m) { return map.unobserved_at(m) && !grown[m]; }));
      }
      best = SweepLeg{from, n, end};
      best_steps = steps[from];
    }
  }
  return best;
}

std::optional<SweepLeg> probe_leg(const BodyView &view, const std::vector<std::int32_t> &steps,
                                  const std::vector<bool> &swept) {
  const sensing::MetricMap &map = view.map;
  std::optional<SweepLeg> best;
  std::int32_t best_steps = -1;
  for (std::size_t from = 0; from < map.size(); ++from) {
    if (steps[from] < 0 || (best && steps[from] >= best_steps) || !view.covered_or_seen_free(from)) continue;
    for (const auto &d : kSteps) {
      const std::optional<MetricCell> c = first_unobserved_past(view, map.cell_of_index(from), d, steps);
      if (!c || swept[map.index(*c)]) continue;
      const MetricCell last = run_end(view, *c, d, [&](std::size_t m) { return map.unobserved_at(m); });
      best = SweepLeg{from, map.index(*c), map.centre_of(last)};
      best_steps = steps[from];
    }
  }
  return best;
}

}  // namespace explore
