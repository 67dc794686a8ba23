#pragma once
// The wavefront planner on the learned sub-cell grid.
//
// A sub-cell is free when its probability is below free_below_p (0.6 by default, compared
// with a 1e-6 tolerance for the float storage; a
// never-observed sub-cell at the prior 0.5 counts as free); the others are obstacles, grown
// by `dilate` sub-cells in every direction (a square, Chebyshev distance). The wave spreads
// from the goal cell's centre sub-cell over free sub-cells, 4 neighbours, cost 1 a step;
// the path then descends the wave from the start cell's centre sub-cell (ties: N, E, S, W).
// Cost O(W K x H K) time and memory.

#include <optional>
#include <vector>

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"

namespace plan {

inline constexpr int kMaxDilate = 8;

struct WavefrontOptions {
  double free_below_p = 0.6;
  int dilate = 0;  // --dilate N, 0 ... kMaxDilate
  // Never-observed sub-cells (still at l(prior)) are obstacles too: a path only through
  // what was seen free (the speed run's choice).
  bool unknown_blocked = false;
};

// Throws common::InputError when dilate is outside 0 ... kMaxDilate or free_below_p
// outside (0, 1].
void validate(const WavefrontOptions &options);

struct Path {
  std::vector<mapping::SubCell> subcells;  // start's centre sub-cell first, goal's last
  int length_subcells = 0;                 // steps: subcells.size() - 1
  int length_cells = 0;                    // cell-to-cell crossings along the path
};

// The blocked mask (per flat grid index): obstacles after dilation.
std::vector<bool> obstacles(const mapping::OccupancyGrid &grid, const mapping::SensorModel &model,
                            const WavefrontOptions &options);

// The shortest 4-neighbour path from the centre of `from` to the centre of `to` (both inside
// the grid), or nothing when the goal is unreachable or either end is blocked.
std::optional<Path> wavefront(const mapping::OccupancyGrid &grid, const mapping::SensorModel &model,
                              mapping::Cell from, mapping::Cell to, const WavefrontOptions &options);

// A per-flat-index mask of the path's sub-cells (for render::MapStyle::path).
std::vector<bool> path_mask(const mapping::OccupancyGrid &grid, const Path &path);

}  // namespace plan
