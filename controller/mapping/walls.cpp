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

namespace {

// Whether a sub-cell on the robot's path from c's centre towards h, strictly between the
// centre and the band middle (none at K = 3), was observed more likely occupied than not.
bool path_blocked(const OccupancyGrid &grid, float initial_log_odds, Cell c, Heading h) {
  const int mid = grid.k() / 2;
  const LocalSubCell band = band_middle(h, grid.k());
  const int step_i = band.i > mid ? 1 : band.i < mid ? -1 : 0;
  const int step_j = band.j > mid ? 1 : band.j < mid ? -1 : 0;
  for (int n = 1; n < mid; ++n) {
    const float value = grid.at(c, LocalSubCell{mid + step_i * n, mid + step_j * n});
    if (observed(value, initial_log_odds) && value > 0.0f) return true;
  }
  return false;
}

}  // namespace

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
  const bool inside = grid.contains(n);
  if (inside) judge(grid.at(n, band_middle(opposite(h), grid.k())));
  if (!wall) {
    wall = path_blocked(grid, initial_log_odds, c, h) || (inside && path_blocked(grid, initial_log_odds, n, opposite(h)));
    seen = seen || wall;
  }
  if (!seen) return SideState::unknown;
  return wall ? SideState::wall : SideState::open;
}

}  // namespace mapping
