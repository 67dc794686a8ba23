#include "mapping/walls.hpp"

#include <cassert>

namespace mapping {

char to_char(SideState s) {
  switch (s) {
    case SideState::unknown: return '?';
    case SideState::open: return 'o';
    case SideState::wall: return 'W';
  }
  return '?';
}

LocalSubCell band_middle(Heading h, int k) {
  const int mid = k / 2;
  switch (h) {
    case Heading::north: return {0, mid};
    case Heading::east: return {mid, k - 1};
    case Heading::south: return {k - 1, mid};
    case Heading::west: return {mid, 0};
  }
  return {mid, mid};
}

SideState side_state(const OccupancyGrid &grid, float initial_log_odds, Cell c, Heading h) {
  return side_state(grid, initial_log_odds, c, h, std::nullopt);
}

SideState side_state(const OccupancyGrid &grid, float initial_log_odds, Cell c, Heading h,
                     std::optional<float> threshold) {
  assert(grid.contains(c));
  bool seen = false;
  bool wall = false;
  const auto judge = [&](float value) {
    if (!observed(value, initial_log_odds)) return;
    seen = true;
    wall = wall || is_occupied(value, threshold);
  };
  judge(grid.at(c, band_middle(h, grid.k())));
  const Cell n = neighbour(c, h);
  if (grid.contains(n)) judge(grid.at(n, band_middle(opposite(h), grid.k())));
  if (!seen) return SideState::unknown;
  return wall ? SideState::wall : SideState::open;
}

}  // namespace mapping
