#pragma once
// The run as it went, for pictures part-way through it (--snapshots) and the replay
// (replay.html): the sub-cells each recorded step changed, and the cells the robot arrived
// in with its heading there, so that the grid and the path after any step can be rebuilt
// when the run is over.
//
// record() compares the grid with its own copy of the last recorded state: O(W * H * K * K)
// a call; given the grid's change log (OccupancyGrid::set_change_log) it compares only the
// sub-cells written since, so that a run's history costs in proportion to what changed, not
// to the area times the steps. 16 bytes kept a changed sub-cell, in blocks (a deque: the log
// grows without being copied, which on a 256 x 256 run cost more than the recording). A change is dated by the
// call that first sees it, so the run calls it after every step that may have changed the grid.

#include <cstdint>
#include <deque>
#include <vector>

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"

namespace app {

class GridHistory {
 public:
  // Starts from a grid of this geometry with every sub-cell at initial_log_odds, as the
  // controller's is before the first step.
  GridHistory(const mapping::GridGeometry &geometry, float initial_log_odds);

  // Notes the sub-cells that differ from the last recorded state, as changed at `step`.
  void record(std::int64_t step, const mapping::OccupancyGrid &grid);
  // The same, looking only at the sub-cells in `written` (the grid's change log since the
  // last call, every write there), which it empties.
  void record(std::int64_t step, const mapping::OccupancyGrid &grid, std::vector<std::uint32_t> &written);
  // Notes that the robot arrived in `cell` at `step` (the start at step 0 or its first step),
  // facing `heading`.
  void arrived(std::int64_t step, mapping::Cell cell, mapping::Heading heading = mapping::Heading::north);

  // The grid as it was after `step`: every change recorded at a step <= `step`.
  mapping::OccupancyGrid grid_at(std::int64_t step) const;
  // The cells arrived in up to `step`, in order.
  std::vector<mapping::Cell> path_at(std::int64_t step) const;

  std::size_t changes() const { return changes_.size(); }

  // A sub-cell (flat grid index, OccupancyGrid::at_index) that took `value` at `step`.
  struct Change {
    std::int64_t step;
    std::uint32_t index;
    float value;
  };
  struct Arrival {
    std::int64_t step;
    mapping::Cell cell;
    mapping::Heading heading;
  };
  // Everything recorded, in order of step.
  const std::deque<Change> &change_log() const { return changes_; }
  const std::vector<Arrival> &arrivals() const { return arrivals_; }
  const mapping::GridGeometry &geometry() const { return geometry_; }
  float initial_log_odds() const { return initial_log_odds_; }

 private:
  mapping::GridGeometry geometry_;
  float initial_log_odds_;
  std::vector<float> last_;
  std::deque<Change> changes_;
  std::vector<Arrival> arrivals_;
};

// The steps of N snapshots at equal fractions of a run of `steps` steps: i * steps / N
// rounded down, for i = 1 ... N, the last one `steps` itself (N = 3 gives 1/3, 2/3, end).
std::vector<std::int64_t> snapshot_steps(std::int64_t steps, int count);

}  // namespace app
