#pragma once
// Frontier exploration over a metric map (sensing/metric/map.hpp), the room variant of the
// cell strategies' frontier (explore/strategies.hpp): which cell the robot drives to next to
// observe unobserved ground. The controller (robot/metric/controller.hpp) drives and looks.
//
//   frontier   a cell never observed beside one seen free (p < 0.5).
//   target     a cell reached from the robot within view_cells of a frontier cell (spread
//              over cells not seen occupied) that sees it: no cell seen occupied
//              (p >= free_below_p) on the line between the centres. Of those, the one of
//              least cost kPathWeight x steps - gain, explore_lite's rule (potential scale 3,
//              gain scale 1): the steps from the robot over the ground reached, the gain that
//              of the frontier cell's group (explore/metric/frontier_groups.hpp; none: 0), so
//              the nearest wins unless a farther one looks at a larger group.
//              Each visit that left its frontier cell unobserved halves the view it is aimed
//              at from (at least one cell), so the robot comes closer each time.
//   set aside  by itself, never with the rest: a frontier cell aimed at kMaxFrontierAttempts
//              times and still unobserved, or one that had no target in a round where no
//              frontier cell had one. It is aimed at again only when no other frontier cell
//              has a target and the map has progressed since it was set aside (MapProgress).
//
// Cost: O(cells) a round (one breadth-first spread, one sort of the candidates).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sensing/metric/map.hpp"

namespace explore {

// The cost of a target: kPathWeight cells of gain for each step of path.
inline constexpr int kPathWeight = 3;

// Visits to a frontier cell that leave it unobserved before it is set aside.
inline constexpr int kMaxFrontierAttempts = 3;

// How far the map has come: cells observed, and the most cells ever free for planning. Both
// only grow (the second is a high-water mark), so a run that waits for progress ends.
struct MapProgress {
  std::size_t observed = 0;
  std::size_t free_for_planning = 0;
  friend bool operator==(const MapProgress &, const MapProgress &) = default;
};

// The progress after a round whose planning map left `free_for_planning` cells open.
MapProgress progress_of(const sensing::MetricMap &map, std::size_t free_for_planning, const MapProgress &before);

// Whether cell n is a frontier cell (frontier_cells below says which).
bool is_frontier_cell(const sensing::MetricMap &map, std::size_t n, bool occupied_marks_are_echo_ends);

// Frontier cells: never observed, beside a cell seen free (p < 0.5), one flag a map cell.
// occupied_marks_are_echo_ends (the lidar: a cell it marks occupied holds a beam's end): beside
// a cell seen free that was never marked occupied (MetricMap::marked_occupied_at); a cell an
// obstacle's face crosses is free on balance when more beams graze it than end in it, and no
// beam crosses it into the cell behind the face.
std::vector<bool> frontier_cells(const sensing::MetricMap &map, bool occupied_marks_are_echo_ends);

// The visits aimed at each frontier cell, and the cells set aside (see above).
class FrontierVisits {
 public:
  explicit FrontierVisits(std::size_t cells) : attempts_(cells, 0), aside_(cells, false), aside_at_(cells) {}
  int attempts(std::size_t cell) const { return attempts_[cell]; }
  bool aside(std::size_t cell) const { return aside_[cell]; }
  // Set aside and the map has progressed since.
  bool retry(std::size_t cell, const MapProgress &now) const { return aside_[cell] && !(aside_at_[cell] == now); }
  // A visit aimed at `cell` ended; still_unobserved: it left the cell as it was.
  void visited(std::size_t cell, bool still_unobserved, const MapProgress &now);
  // The cell had no target: set aside until the map has progressed past `now`.
  void set_aside(std::size_t cell, const MapProgress &now);

 private:
  std::vector<std::uint8_t> attempts_;
  std::vector<bool> aside_;
  std::vector<MapProgress> aside_at_;
};

// A frontier cell to aim at and the cell to drive to for it.
struct FrontierTarget {
  std::size_t target = 0;  // the cell to drive to
  std::size_t aim = 0;     // the frontier cell it sees
};

// The target for the flagged frontier cells (`aims`), or nothing when none is in view of a
// cell reached. steps: from the robot per cell (-1 not reached); free_below_p: the planner's
// threshold; gain: per frontier cell, its group's (nullptr: none).
std::optional<FrontierTarget> frontier_target(const sensing::MetricMap &map, double free_below_p,
                                              const std::vector<bool> &aims, int view_cells,
                                              const FrontierVisits &visits, const std::vector<std::int32_t> &steps,
                                              const std::vector<std::int32_t> *gain = nullptr);

}  // namespace explore
