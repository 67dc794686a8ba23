#pragma once
// The tolerances the simulator's two geometries share (WallGrid for a maze's walls,
// SolidGeometry for an arena's rectangles and segments), so a body touches a wall the same
// way in both. Private to maze/src/sim.

#include <limits>

namespace maze::sim {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
// An overlap smaller than this is rounding, not a collision.
inline constexpr double kSlop_m = 1e-12;
// disc_in_free_core's safety margin: far above rounding, far below any wall thickness.
inline constexpr double kCoreMargin_m = 1e-9;

}  // namespace maze::sim
