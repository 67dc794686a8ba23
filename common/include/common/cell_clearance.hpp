#pragma once
// Clearance on a grid of square cells: the cells where a round body of a given radius cannot
// stand with its centre at the cell's centre, because the body would overlap an occupied
// cell (any point of its square) or reach past the grid's edge. An occupied cell of a map may
// hold its obstacle anywhere inside it, so this is the rule a robot can defend on the map:
// a centre not blocked keeps the whole body off every occupied cell. The room frontier plans
// with it and the room's judge rasterises "reachable" with it, so both call the same gaps
// passable at the map's resolution. At 0.1 m cells and a 0.09 m radius it blocks the 8
// neighbours of each occupied cell (the growth by one cell); at 0.05 m, a disc of 21 cells.
// Cost O(cells + occupied cells x the disc's cells).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace common {

// The offsets (di, dj) of the cells whose square comes closer than radius_m to a cell's centre
// (touching is clear), the cell itself always among them.
inline std::vector<std::pair<int, int>> clearance_disc(double cell_m, double radius_m) {
  const int reach = static_cast<int>(std::ceil(radius_m / cell_m + 0.5));
  std::vector<std::pair<int, int>> disc;
  for (int dj = -reach; dj <= reach; ++dj) {
    for (int di = -reach; di <= reach; ++di) {
      const double gx = std::max(0.0, std::abs(di) - 0.5) * cell_m;
      const double gy = std::max(0.0, std::abs(dj) - 0.5) * cell_m;
      if ((di == 0 && dj == 0) || std::hypot(gx, gy) < radius_m) disc.emplace_back(di, dj);
    }
  }
  return disc;
}

// blocked[j * cells_x + i] = 1 when a body of radius_m centred on cell (i, j)'s centre would
// overlap an occupied cell (occupied(flat) says which) or reach past the grid's edge.
template <typename Occupied>
std::vector<std::uint8_t> cells_without_clearance(int cells_x, int cells_y, double cell_m, double radius_m,
                                                  Occupied &&occupied) {
  const std::size_t nx = static_cast<std::size_t>(cells_x);
  std::vector<std::uint8_t> blocked(nx * static_cast<std::size_t>(cells_y), 0);
  const std::vector<std::pair<int, int>> disc = clearance_disc(cell_m, radius_m);
  for (int j = 0; j < cells_y; ++j) {
    for (int i = 0; i < cells_x; ++i) {
      const std::size_t flat = static_cast<std::size_t>(j) * nx + static_cast<std::size_t>(i);
      const int edge_cells = std::min({i, cells_x - 1 - i, j, cells_y - 1 - j});
      if ((edge_cells + 0.5) * cell_m < radius_m) blocked[flat] = 1;
      if (!occupied(flat)) continue;
      for (const auto &d : disc) {
        const int ni = i + d.first;
        const int nj = j + d.second;
        if (ni < 0 || nj < 0 || ni >= cells_x || nj >= cells_y) continue;
        blocked[static_cast<std::size_t>(nj) * nx + static_cast<std::size_t>(ni)] = 1;
      }
    }
  }
  return blocked;
}

}  // namespace common
