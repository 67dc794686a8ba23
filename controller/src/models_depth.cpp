// The depth-ray model (mapping/range_models.hpp).

#include <cmath>

#include "mapping/models.hpp"
#include "mapping/range_models.hpp"

namespace mapping {

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

}  // namespace mapping
