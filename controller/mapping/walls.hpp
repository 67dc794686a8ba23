#pragma once
// Walls for decisions, read from the grid only (docs/models.md): never from the true maze.
//
// The side of cell c towards h is judged on two sub-cells: the middle of c's band h and the
// middle of the neighbour's opposite band (the two halves of the wall, either side of the
// boundary; the neighbour's only when it is inside the grid).
//   unknown  neither sub-cell was ever updated (its value is still the initial l(prior)),
//            and no sub-cell of the path below holds a solid
//   wall     an observed one is more likely occupied than not: log-odds > 0, i.e. p > 0.5;
//            or a solid stands on the robot's path across the side: an observed sub-cell
//            strictly between either cell's centre and its band middle, along the middle
//            row or column (none at K = 3), has log-odds > 0 (p > 0.5 whatever
//            --threshold: the classroom threshold calls a sub-cell seen free once occupied,
//            and every path sub-cell of a visited cell is)
//   open     observed, and none is above 0
// The threshold is absolute (p > 0.5), whatever the prior: with a prior other than 0.5 an
// unobserved sub-cell is "unknown", not a wall or an opening, and one update from the
// classroom rule l <- l + l(inv) - l(prior) gives exactly l(p_occ) > 0 or l(p_free) < 0.
// Either half may decide "wall" because a hit lands on whichever side of the boundary the
// measured range puts it, while the beam frees the half it passed through. The band's
// corners are not used: they are shared with the perpendicular bands.

#include <cstdint>
#include <optional>

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"

namespace mapping {

enum class SideState : std::uint8_t { unknown, open, wall };

char to_char(SideState s);  // '?', 'o', 'W'

// The middle sub-cell of band h: north (0, K/2), east (K/2, K-1), south (K-1, K/2), west (K/2, 0).
LocalSubCell band_middle(Heading h, int k);

// A sub-cell value still equal to the grid's initial value has never been observed.
inline bool observed(float value, float initial_log_odds) { return value != initial_log_odds; }

// The state of side h of cell c (c inside the grid). initial_log_odds is the value the grid
// was created with (SensorModel::prior_log_odds() as a float).
SideState side_state(const OccupancyGrid &grid, float initial_log_odds, Cell c, Heading h);

// The binary map's rule: occupied when log-odds > 0, or >= threshold when one is given
// (--threshold L; the course's -0.5 in base 10 calls a sub-cell occupied unless it was seen
// free more than once: better wrongly occupied than wrongly free).
inline bool is_occupied(float value, std::optional<float> threshold) {
  return threshold ? value >= *threshold : value > 0.0f;
}

// side_state with the binary map's threshold instead of p > 0.5.
SideState side_state(const OccupancyGrid &grid, float initial_log_odds, Cell c, Heading h,
                     std::optional<float> threshold);

}  // namespace mapping
