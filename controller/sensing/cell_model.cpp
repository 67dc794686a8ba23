#include "sensing/cell_model.hpp"

#include <cassert>
#include <limits>
#include <numbers>

namespace sensing {

using namespace mapping;  // the grid types this model marks
namespace {

// The cell model reads each side through the median of the beams within 2.5 degrees of it
// (5 beams of a 1-degree lidar), so a lone dropped or spiked beam cannot flip a wall.
constexpr double kCellModelHalfWindow_rad = 2.5 * std::numbers::pi / 180.0;

// Row/column steps of local sub-cell coordinates (i from the north, j from the west).
constexpr int di(Heading h) { return -dy(h); }
constexpr int dj(Heading h) { return dx(h); }

// Distance (m) from point p to side h of cell c, along h.
double distance_to_side(const OccupancyGrid &grid, Point p, Cell c, Heading h) {
  const GridGeometry &g = grid.geometry();
  const Point centre = grid.centre_of(c);
  const double half = g.cell_size_m / 2.0;
  switch (h) {
    case Heading::north: return centre.y_m + half - p.y_m;
    case Heading::south: return p.y_m - (centre.y_m - half);
    case Heading::east: return centre.x_m + half - p.x_m;
    case Heading::west: return p.x_m - (centre.x_m - half);
  }
  return half;
}

void mark_cell_side(const OccupancyGrid &grid, Cell c, Heading h, bool wall, ScanUpdate &update) {
  const int k = grid.k();
  const int mid = k / 2;
  const LocalSubCell band_middle{mid + di(h) * mid, mid + dj(h) * mid};
  for (int n = 1; n < mid; ++n) {
    update.mark_free(grid.index(c, LocalSubCell{mid + di(h) * n, mid + dj(h) * n}));
  }
  if (!wall) {
    update.mark_free(grid.index(c, band_middle));
    return;
  }
  // The whole band: the middle and every sub-cell left and right of it (the lab report's
  // rule, which at K = 3 is the middle and the two corners).
  const bool along_j = di(h) != 0;  // a north/south band runs along j, east/west along i
  for (int n = 0; n < k; ++n) {
    const LocalSubCell band = along_j ? LocalSubCell{band_middle.i, n} : LocalSubCell{n, band_middle.j};
    update.mark_occupied(grid.index(c, band));
  }
}

// The side's reading by the medians along h; no return counts as open when reach_m (the
// lidar's reach, infinite for the robot's own cell) passes the side plus the margin.
SideState read_side(const ModelOptions &options, const OccupancyGrid &grid, const LidarScan &scan, Cell c, Heading h,
                    double reach_m) {
  const auto beam = scan.beam_towards(yaw_rad(h));
  if (!beam) return SideState::unknown;
  const auto medians = scan.medians(*beam, kCellModelHalfWindow_rad);
  if (!medians) return SideState::unknown;
  const double limit_m = distance_to_side(grid, scan.origin, c, h) + options.wall_margin * grid.geometry().cell_size_m;
  const auto wall = [&](float range) { return scan.kind_of(range) == ReadingKind::hit && range < limit_m; };
  // An even split (two short returns, two long: a pair of spikes beside a dropped beam)
  // says nothing either way: the side stays unknown, and the robot looks again.
  if (wall(medians->lower) != wall(medians->upper)) return SideState::unknown;
  if (wall(medians->lower)) return SideState::wall;
  const auto beyond_reach = [&](float range) { return scan.kind_of(range) != ReadingKind::hit && reach_m < limit_m; };
  if (beyond_reach(medians->lower) || beyond_reach(medians->upper)) return SideState::unknown;
  return SideState::open;
}

}  // namespace

SideState read_cell_side(const ModelOptions &options, const OccupancyGrid &grid, const LidarScan &scan,
                         Cell c, Heading h) {
  return read_side(options, grid, scan, c, h, std::numeric_limits<double>::infinity());
}

SideState read_side_ahead(const ModelOptions &options, const OccupancyGrid &grid, const LidarScan &scan,
                          Cell c, Heading h) {
  return read_side(options, grid, scan, c, h, scan.max_range_m);
}

void mark_cell_model(const ModelOptions &options, const OccupancyGrid &grid,
                     const LidarScan &scan, Cell c, ScanUpdate &update) {
  assert(grid.contains(c));
  const int mid = grid.k() / 2;
  update.mark_free(grid.index(c, LocalSubCell{mid, mid}));
  for (const Heading h : kHeadings) {
    const SideState side = read_cell_side(options, grid, scan, c, h);
    if (side != SideState::unknown) mark_cell_side(grid, c, h, side == SideState::wall, update);
  }
}

}  // namespace sensing
