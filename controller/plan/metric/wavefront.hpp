#pragma once
// The wavefront on a plain grid of cells (the room map's: sensing/metric/map.hpp), as the
// wavefront labs grade it: the blocked cells (obstacles, grown by `dilate` cells in every
// direction: a square, Chebyshev distance) are 1, the goal 2, and the wave spreads from the
// goal over free cells, 4 neighbours, each cell one more than the cell it came from; a free
// cell the wave never reaches stays 0. The path descends the wave from the start, one cell a
// step (ties: N, E, S, W). Cells are flat indices j * cells_x + i, row 0 the south row.
// Cost O(cells) time and memory (the dilation O(cells (2 dilate + 1))).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace plan {

inline constexpr std::int32_t kWaveBlocked = 1;
inline constexpr std::int32_t kWaveGoal = 2;
inline constexpr std::int32_t kWaveUnreached = 0;

struct FlatGrid {
  int cells_x = 0;
  int cells_y = 0;
  std::size_t size() const { return static_cast<std::size_t>(cells_x) * static_cast<std::size_t>(cells_y); }
};

// The obstacles grown by `dilate` cells (0: as they are).
std::vector<bool> dilated(const FlatGrid &grid, const std::vector<bool> &obstacles, int dilate);

// The wave's numbers per cell (kWaveBlocked, kWaveGoal and up, kWaveUnreached). A goal on a
// blocked cell leaves every cell blocked or unreached.
std::vector<std::int32_t> wave_from(const FlatGrid &grid, const std::vector<bool> &blocked, std::size_t goal);

// The path from start to the goal down the wave, start first, goal last; nothing when the
// start is blocked or the wave did not reach it.
std::optional<std::vector<std::size_t>> descend(const FlatGrid &grid, const std::vector<std::int32_t> &wave,
                                                std::size_t start);

// The cells reachable from `start` over cells not blocked (4 neighbours): per cell, its
// number of steps from start, or -1. For frontier search and the reachable-area truth.
std::vector<std::int32_t> steps_from(const FlatGrid &grid, const std::vector<bool> &blocked, std::size_t start);

}  // namespace plan
