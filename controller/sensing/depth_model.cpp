// The depth-ray model (sensing/range_models.hpp).

#include <cmath>

#include "mapping/traversal.hpp"
#include "sensing/range_models.hpp"

namespace sensing {

using namespace mapping;  // the grid types this model marks

LeveledUpdate make_depth_update() {
  return LeveledUpdate({kDepthHitP, kDepthRobotP, kDepthRayP});
}

void mark_depth(const OccupancyGrid &grid, Point robot, std::span<const RangeReading> rays,
                LeveledUpdate &update) {
  update.mark(grid, robot, 1);
  for (const RangeReading &r : rays) {
    if (!(r.range_m > 0.0 && r.range_m < r.max_range_m)) continue;  // 0 or max: ignored
    const double dir_x = std::cos(r.angle_rad);
    const double dir_y = std::sin(r.angle_rad);
    trace_ray(grid.geometry(), r.origin, dir_x, dir_y, [&](SubCell s, double exit_m) {
      if (exit_m < r.range_m) {
        update.mark(grid, s, 2);
        return true;
      }
      update.mark(grid, s, 0);
      return false;
    });
  }
}

}  // namespace sensing
