#include "maze/formats/geometry_text.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "common/error.hpp"
#include "maze/world/truth_raster.hpp"

namespace maze {

namespace {
constexpr int kDefaultCells = 60;
constexpr int kMaxDrawnCells = 2000;
}  // namespace

double default_arena_resolution_m(const Arena &arena) {
  const double side = std::max(arena.width_m(), arena.height_m());
  for (const double r : {0.05, 0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0}) {
    if (side / r <= kDefaultCells) return r;
  }
  return 100.0;
}

std::string draw_arena(const Arena &arena, double resolution_m) {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw common::InputError(fmt::format("--resolution must be a positive number of metres (got {})", resolution_m));
  }
  const double nx_real = arena.width_m() / resolution_m;
  const double ny_real = arena.height_m() / resolution_m;
  if (nx_real > kMaxDrawnCells || ny_real > kMaxDrawnCells) {
    throw common::InputError(fmt::format("--resolution {} m draws {:.0f} x {:.0f} cells; at most {} a side", resolution_m,
                                         std::ceil(nx_real), std::ceil(ny_real), kMaxDrawnCells));
  }
  const int nx = cells_along(arena.width_m(), resolution_m);
  const int ny = cells_along(arena.height_m(), resolution_m);
  const TruthRaster t = rasterise_truth(arena, nx, ny, 0.0);
  std::vector<std::string> cells(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  for (int y = 0; y < ny; ++y) {
    for (int x = 0; x < nx; ++x) cells[t.index(x, y)] = t.is_occupied(x, y) ? "##" : "  ";
  }
  const auto cell_of = [&](double px, double py) {
    const int x = std::clamp(static_cast<int>(std::floor((px - t.x_min_m) / t.cell_x_m)), 0, nx - 1);
    const int y = std::clamp(static_cast<int>(std::floor((py - t.y_min_m) / t.cell_y_m)), 0, ny - 1);
    return t.index(x, y);
  };
  if (!arena.starts.empty()) cells[cell_of(arena.starts[0].x_m, arena.starts[0].y_m)] = "S ";
  for (const ArenaPoint &g : arena.goals) cells[cell_of(g.x_m, g.y_m)] = "G ";
  std::string text = fmt::format("{} ({} x {} m): x {} to {} m, y {} to {} m; {} x {} cells of {} m, north up\n",
                                 arena.name, arena.width_m(), arena.height_m(), arena.x_min_m, arena.x_max_m,
                                 arena.y_min_m, arena.y_max_m, nx, ny, resolution_m);
  std::string frame(2 * static_cast<std::size_t>(nx) + 3, '-');
  frame.front() = '+';
  frame[frame.size() - 2] = '+';
  frame.back() = '\n';
  text += frame;
  for (int y = ny - 1; y >= 0; --y) {
    text += '|';
    for (int x = 0; x < nx; ++x) text += cells[t.index(x, y)];
    text += "|\n";
  }
  text += frame;
  return text;
}

}  // namespace maze
