// The sonar/IR cone model (mapping/range_models.hpp).

#include <algorithm>
#include <cmath>

#include "mapping/range_models.hpp"

namespace mapping {
namespace {

// Marks the points of the beam at range r_m, across [-half, +half] around the direction, at
// an angular step of half a sub-cell's angular size at that range.
void sweep_arc(const OccupancyGrid &grid, const RangeReading &r, double r_m, int level,
               LeveledUpdate &update) {
  const double half = r.aperture_rad / 2.0;
  const double size = grid.geometry().subcell_size_m();
  const double step = r_m > 0.0 ? 0.5 * size / r_m : half + 1.0;
  const int n = static_cast<int>(std::ceil(2.0 * half / step));
  for (int k = 0; k <= n; ++k) {
    const double a = r.angle_rad - half + (n == 0 ? half : 2.0 * half * k / n);
    update.mark(grid, Point{r.origin.x_m + r_m * std::cos(a), r.origin.y_m + r_m * std::sin(a)}, level);
  }
}

// Sweeps arcs from r0_m to r1_m at radial steps of half a sub-cell (both ends included).
void sweep_band(const OccupancyGrid &grid, const RangeReading &r, double r0_m, double r1_m,
                int level, LeveledUpdate &update) {
  const double step = grid.geometry().subcell_size_m() / 2.0;
  const int n = std::max(1, static_cast<int>(std::ceil((r1_m - r0_m) / step)));
  for (int k = 0; k <= n; ++k) sweep_arc(grid, r, r0_m + (r1_m - r0_m) * k / n, level, update);
}

}  // namespace

LeveledUpdate make_cone_update(const SensorModelOptions &sensor) {
  return LeveledUpdate({sensor.p_occ, sensor.p_free});
}

void mark_cone(const OccupancyGrid &grid, std::span<const RangeReading> readings,
               LeveledUpdate &update) {
  for (const RangeReading &r : readings) {
    if (!(r.range_m >= 0.0)) continue;
    const bool hit = r.range_m < r.max_range_m;
    const double d = hit ? r.range_m : r.max_range_m;
    const double near_m = d * (1.0 - r.range_error);
    if (near_m > 0.0) sweep_band(grid, r, 0.0, near_m, 1, update);
    if (hit) sweep_band(grid, r, near_m, d * (1.0 + r.range_error), 0, update);
  }
}

}  // namespace mapping
