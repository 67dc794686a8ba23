#pragma once
// The frontier in groups, as ROS's explore_lite takes it (explore/metric/frontier.hpp gives the
// cells): which frontier cells are worth a look, and the information a look would gain.
//
//   group      frontier cells 8-connected (a frontier cell: never observed, beside one seen free).
//   region     unobserved cells 4-connected; its frontier, the frontier cells among them.
//   small      a group of fewer than min_cells cells: a gap in an obstacle's face that a beam
//              missed, a corner cell, not an opening onto ground.
//   enclosed   a group whose cells all lie in regions whose whole frontier is fewer than
//              min_cells: unobserved ground behind occupied cells all round save a gap narrower
//              than the minimum (an obstacle's inside seen through a gap in its face). A look
//              through the gap observes the gap's cells, not the inside.
//   no room    a group none of whose cells the body could cover: each cell and its eight
//              neighbours closed to the body (within its radius of a cell seen occupied, the
//              planner's closed cells): the unobserved inside of an obstacle behind a face, a
//              sliver between two faces. The judge counts a cell as reachable only where the
//              body clear of the occupied cells can cover it (from a centre in a neighbouring
//              cell at most), so a look there observes no reachable ground, whatever it finds.
//              A cell the body covers without standing on it (in a corner the arcs of a sonar
//              closed, on the grid's edge) has room.
//   beyond reach  a group a caller that plans finds none of whose cells lies beside a cell the
//              robot reaches (the metric controller sets none: without their probes the IR
//              set-ups ended short of the floor behind their arcs).
//   gain       what a look at a group is expected to observe: its cells, at most gain_cap cells.
//
// Small, enclosed and no-room groups are not targets. Cost: O(cells), two flood fills.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sensing/metric/map.hpp"

namespace explore {

struct FrontierGroups {
  std::vector<std::int32_t> group_of;  // per map cell: its group, -1 for a cell not on the frontier
  std::vector<std::size_t> cells;      // per group: its frontier cells
  std::vector<bool> small, enclosed, no_room;  // per group
  // Whether the group may be a target (not small, enclosed, or without room for the body).
  bool worth_a_look(std::size_t g) const { return !small[g] && !enclosed[g] && !no_room[g]; }
};

// closed_to_body: per map cell, whether the body centred there would touch a cell seen
// occupied (nullptr: no group lacks room).
FrontierGroups group_frontier(const sensing::MetricMap &map, const std::vector<bool> &frontier, std::size_t min_cells,
                              const std::vector<bool> *closed_to_body = nullptr);

// The frontier cells of groups worth a look (one flag a map cell).
std::vector<bool> cells_worth_a_look(const FrontierGroups &groups);

// Per map cell: the gain of its group (its cells, at most gain_cap), 0 off the frontier.
std::vector<std::int32_t> frontier_gain(const FrontierGroups &groups, std::int32_t gain_cap);

// The frontier groups set aside and why, for the summary.
struct FrontierSetAside {
  std::size_t small_groups = 0, small_cells = 0;
  std::size_t enclosed_groups = 0, enclosed_cells = 0;
  std::size_t no_room_groups = 0, no_room_cells = 0;
};
FrontierSetAside set_aside_of(const FrontierGroups &groups);

}  // namespace explore
