#include "mapping/traversal.hpp"

#include <cmath>

namespace mapping {

std::vector<SubCell> subcells_on_segment(const GridGeometry &g, Point from, Point to) {
  const double ex = to.x_m - from.x_m;
  const double ey = to.y_m - from.y_m;
  const double length = std::hypot(ex, ey);
  std::vector<SubCell> out;
  if (length == 0.0) {
    trace_ray(g, from, 1.0, 0.0, [&](SubCell s, double) {
      out.push_back(s);
      return false;
    });
    return out;
  }
  trace_ray(g, from, ex / length, ey / length, [&](SubCell s, double exit_m) {
    out.push_back(s);
    return exit_m < length;
  });
  return out;
}

}  // namespace mapping
