// The frontier in groups (explore/metric/frontier_groups.hpp).

#include "explore/metric/frontier_groups.hpp"

#include <algorithm>
#include <utility>

namespace explore {
namespace {

using sensing::MetricCell;

constexpr std::pair<int, int> kFour[] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};
constexpr std::pair<int, int> kEight[] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};

// Labels the components of the cells `in` says belong, joined through `moves`; -1 elsewhere.
// Returns the number of components.
template <std::size_t N>
std::size_t label(const sensing::MetricMap &map, const std::vector<bool> &in, const std::pair<int, int> (&moves)[N],
                  std::vector<std::int32_t> &labels) {
  labels.assign(map.size(), -1);
  std::vector<std::size_t> stack;
  std::int32_t next = 0;
  for (std::size_t seed = 0; seed < map.size(); ++seed) {
    if (!in[seed] || labels[seed] >= 0) continue;
    labels[seed] = next;
    stack.push_back(seed);
    while (!stack.empty()) {
      const MetricCell c = map.cell_of_index(stack.back());
      stack.pop_back();
      for (const auto &d : moves) {
        const MetricCell nb{c.i + d.first, c.j + d.second};
        if (!map.contains(nb)) continue;
        const std::size_t k = map.index(nb);
        if (!in[k] || labels[k] >= 0) continue;
        labels[k] = next;
        stack.push_back(k);
      }
    }
    ++next;
  }
  return static_cast<std::size_t>(next);
}

// Whether a body centred on a cell open to it (not closed_to_body) could cover cell n: n is
// one, or beside one (8-neighbours: within the body's radius and half a cell's diagonal of its
// centre, as the judge's reach has it).
bool body_covers(const sensing::MetricMap &map, const std::vector<bool> &closed_to_body, std::size_t n) {
  if (!closed_to_body[n]) return true;
  const MetricCell c = map.cell_of_index(n);
  for (const auto &d : kEight) {
    const MetricCell nb{c.i + d.first, c.j + d.second};
    if (map.contains(nb) && !closed_to_body[map.index(nb)]) return true;
  }
  return false;
}

}  // namespace

FrontierGroups group_frontier(const sensing::MetricMap &map, const std::vector<bool> &frontier, std::size_t min_cells,
                              const std::vector<bool> *closed_to_body) {
  FrontierGroups g;
  const std::size_t groups = label(map, frontier, kEight, g.group_of);
  std::vector<bool> unobserved(map.size());
  for (std::size_t n = 0; n < map.size(); ++n) unobserved[n] = map.unobserved_at(n);
  std::vector<std::int32_t> region_of;
  const std::size_t regions = label(map, unobserved, kFour, region_of);
  std::vector<std::size_t> region_frontier(regions, 0);
  g.cells.assign(groups, 0);
  for (std::size_t n = 0; n < map.size(); ++n) {
    if (!frontier[n]) continue;
    ++g.cells[static_cast<std::size_t>(g.group_of[n])];
    ++region_frontier[static_cast<std::size_t>(region_of[n])];
  }
  g.small.assign(groups, false);
  g.enclosed.assign(groups, true);
  g.no_room.assign(groups, closed_to_body != nullptr);
  for (std::size_t k = 0; k < groups; ++k) g.small[k] = g.cells[k] < min_cells;
  for (std::size_t n = 0; n < map.size(); ++n) {
    if (!frontier[n]) continue;
    const auto k = static_cast<std::size_t>(g.group_of[n]);
    if (region_frontier[static_cast<std::size_t>(region_of[n])] >= min_cells) g.enclosed[k] = false;
    if (closed_to_body != nullptr && body_covers(map, *closed_to_body, n)) g.no_room[k] = false;
  }
  return g;
}

std::vector<bool> cells_worth_a_look(const FrontierGroups &groups) {
  std::vector<bool> cells(groups.group_of.size(), false);
  for (std::size_t n = 0; n < cells.size(); ++n) {
    const std::int32_t k = groups.group_of[n];
    cells[n] = k >= 0 && groups.worth_a_look(static_cast<std::size_t>(k));
  }
  return cells;
}

std::vector<std::int32_t> frontier_gain(const FrontierGroups &groups, std::int32_t gain_cap) {
  std::vector<std::int32_t> gain(groups.group_of.size(), 0);
  for (std::size_t n = 0; n < gain.size(); ++n) {
    const std::int32_t k = groups.group_of[n];
    if (k < 0) continue;
    gain[n] = static_cast<std::int32_t>(std::min<std::size_t>(groups.cells[static_cast<std::size_t>(k)],
                                                              static_cast<std::size_t>(gain_cap)));
  }
  return gain;
}

FrontierSetAside set_aside_of(const FrontierGroups &groups) {
  FrontierSetAside a;
  for (std::size_t k = 0; k < groups.cells.size(); ++k) {
    if (groups.small[k]) {
      ++a.small_groups;
      a.small_cells += groups.cells[k];
    } else if (groups.enclosed[k]) {
      ++a.enclosed_groups;
      a.enclosed_cells += groups.cells[k];
    } else if (groups.no_room[k]) {
      ++a.no_room_groups;
      a.no_room_cells += groups.cells[k];
    }
  }
  return a;
}

}  // namespace explore
