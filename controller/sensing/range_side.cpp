// What one set of range readings says about a side of the robot's cell (sensing/range_models.hpp).

#include <cmath>

#include "common/angles.hpp"
#include "sensing/range_models.hpp"

namespace sensing {

mapping::SideState read_range_side(const mapping::OccupancyGrid &grid, std::span<const RangeReading> readings,
                                   mapping::Cell c, mapping::Heading h) {
  const mapping::GridGeometry &g = grid.geometry();
  const mapping::Point centre = grid.centre_of(c);
  const double side_x = centre.x_m + mapping::dx(h) * g.cell_size_m / 2.0;
  const double side_y = centre.y_m + mapping::dy(h) * g.cell_size_m / 2.0;
  mapping::SideState state = mapping::SideState::unknown;
  for (const RangeReading &r : readings) {
    if (!(r.range_m >= 0.0)) continue;
    if (std::abs(common::wrap_angle_rad(r.angle_rad - mapping::yaw_rad(h))) > kFacingSide_rad) continue;
    if (is_no_return(r) && !no_return_tells(r)) continue;
    // The side's line, ahead along the axis.
    const double to_side_m = mapping::dx(h) != 0 ? std::abs(side_x - r.origin.x_m) : std::abs(side_y - r.origin.y_m);
    if (r.range_m < to_side_m + kRangeSideMargin * g.cell_size_m) return mapping::SideState::wall;
    state = mapping::SideState::open;
  }
  return state;
}

}  // namespace sensing
