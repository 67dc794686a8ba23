// The sonar/IR cone model (sensing/range_models.hpp).

#include <algorithm>
#include <cmath>

#include "sensing/range_models.hpp"

namespace sensing {

using namespace mapping;  // the grid types this model marks
namespace {

constexpr int kOccupied = 0;
constexpr int kFree = 1;

// Marks the beam at range r_m across its width: the width is cut into an odd number of
// equal angular bins no wider than half a sub-cell's angular size at that range (one bin
// centred on the axis), and each bin's centre is marked with range_weight times the
// Moravec-Elfes angular weight 1 - (offset / half-width)^2: full on the axis, fading to
// nothing at the edges.
void sweep_arc(const OccupancyGrid &grid, const RangeReading &r, double r_m, int level,
               double range_weight, LeveledUpdate &update) {
  const double half = r.aperture_rad / 2.0;
  const double size = grid.geometry().subcell_size_m();
  const double steps_per_half = half * r_m / (0.5 * size);  // half-width / angular step
  const int n = steps_per_half > 0.5 ? 2 * static_cast<int>(std::ceil(steps_per_half - 0.5)) + 1 : 1;
  for (int k = 0; k < n; ++k) {
    const double offset = -half + 2.0 * half * (k + 0.5) / n;
    const double a = r.angle_rad + offset;
    const double angular = half > 0.0 ? 1.0 - (offset / half) * (offset / half) : 1.0;
    update.mark(grid, Point{r.origin.x_m + r_m * std::cos(a), r.origin.y_m + r_m * std::sin(a)},
                level, range_weight * angular);
  }
}

// The radial steps (half a sub-cell, both ends included) from r0_m to r1_m.
int radial_steps(const OccupancyGrid &grid, double r0_m, double r1_m) {
  const double step = grid.geometry().subcell_size_m() / 2.0;
  return std::max(1, static_cast<int>(std::ceil((r1_m - r0_m) / step)));
}

// The free cone from the sensor to end_m, with Elfes's range weight 1 - (r / end)^2.
void sweep_free(const OccupancyGrid &grid, const RangeReading &r, double end_m,
                LeveledUpdate &update) {
  const int n = radial_steps(grid, 0.0, end_m);
  for (int k = 0; k <= n; ++k) {
    const double f = static_cast<double>(k) / n;
    sweep_arc(grid, r, end_m * f, kFree, 1.0 - f * f, update);
  }
}

// The occupied arc from r0_m to r1_m, at full range weight.
void sweep_occupied(const OccupancyGrid &grid, const RangeReading &r, double r0_m, double r1_m,
                    LeveledUpdate &update) {
  const int n = radial_steps(grid, r0_m, r1_m);
  for (int k = 0; k <= n; ++k) sweep_arc(grid, r, r0_m + (r1_m - r0_m) * k / n, kOccupied, 1.0, update);
}

}  // namespace

LeveledUpdate make_cone_update(const SensorModelOptions &sensor) {
  return LeveledUpdate({sensor.p_occ, sensor.p_free});
}

void mark_cone(const OccupancyGrid &grid, std::span<const RangeReading> readings,
               LeveledUpdate &update) {
  const double error_limit_m = kConeUsableError * grid.geometry().cell_size_m;
  for (const RangeReading &r : readings) {
    if (!(r.range_m >= 0.0)) continue;
    // A sonar at a slant to the grid that heard no echo may have met a wall: nothing to mark.
    if (is_no_return(r) && !no_return_tells(r)) continue;
    // The usable range: where the distance error eps d still tells one cell side from the
    // next. Beyond it no arc is marked and the free cone stops there.
    const double usable_m =
        r.range_error > 0.0 ? std::min(r.max_range_m, error_limit_m / r.range_error) : r.max_range_m;
    // A reading within its errors of max range saw nothing (is_no_return), as for the pie,
    // and frees no farther than kConeNoReturnReach of max: a wall just short of max reads
    // as nothing seen too.
    const bool nothing_seen = is_no_return(r);
    const bool hit = !nothing_seen && r.range_m <= usable_m;
    const double reach_m = nothing_seen ? std::min(usable_m, kConeNoReturnReach * r.max_range_m) : usable_m;
    const double d = hit ? r.range_m : std::min(r.range_m, reach_m);
    // eps is the table's noise, a standard deviation: the arc spans kConeArcErrors of them
    // either side of the reading, so the wall lies in it (95 % of readings at 2).
    const double spread = kConeArcErrors * r.range_error;
    const double near_m = d * (1.0 - spread);
    if (near_m > 0.0) sweep_free(grid, r, near_m, update);
    if (hit) sweep_occupied(grid, r, near_m, d * (1.0 + spread), update);
  }
}

}  // namespace sensing
