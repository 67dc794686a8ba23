// The IR pie-slice model (mapping/range_models.hpp).

#include <algorithm>
#include <cmath>

#include "mapping/models.hpp"
#include "mapping/range_models.hpp"
#include "mapping/scan.hpp"

namespace mapping {
namespace {

enum class Part { outside, clear, contact };

// Where point p lies relative to the slices of one reading.
Part part_of(const RangeReading &r, double beta, double clear_m, double contact_m, Point p) {
  const double ex = p.x_m - r.origin.x_m;
  const double ey = p.y_m - r.origin.y_m;
  const double distance = std::hypot(ex, ey);
  if (distance > contact_m) return Part::outside;
  if (distance > 0.0 && std::abs(wrap_angle_rad(std::atan2(ey, ex) - r.angle_rad)) > beta) {
    return Part::outside;
  }
  return distance <= clear_m ? Part::clear : Part::contact;
}

void mark_one(const OccupancyGrid &grid, const RangeModelOptions &options, const RangeReading &r,
              LeveledUpdate &update) {
  const bool contacting = r.range_m < r.max_range_m * (1.0 - r.range_error);
  // A clear reading frees up to what it measured, less its error: noise near max range
  // must not free a wall just short of max.
  const double clear_m = contacting ? std::max(r.range_m, 0.0)
                                    : std::min(r.range_m, r.max_range_m) * (1.0 - r.range_error);
  const double outer_m = contacting ? clear_m + options.pie_contact_m : clear_m;
  const GridGeometry &g = grid.geometry();
  const double size = g.subcell_size_m();
  const auto to_index = [&](double v, double origin) {
    return static_cast<int>(std::floor((v - origin) / size));
  };
  const int x0 = std::max(0, to_index(r.origin.x_m - outer_m, g.origin.x_m));
  const int x1 = std::min(g.width_subcells() - 1, to_index(r.origin.x_m + outer_m, g.origin.x_m));
  const int y0 = std::max(0, to_index(r.origin.y_m - outer_m, g.origin.y_m));
  const int y1 = std::min(g.height_subcells() - 1, to_index(r.origin.y_m + outer_m, g.origin.y_m));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double left = g.origin.x_m + x * size;
      const double bottom = g.origin.y_m + y * size;
      const Point points[] = {{left, bottom}, {left + size, bottom}, {left, bottom + size},
                              {left + size, bottom + size}, {left + size / 2, bottom + size / 2}};
      bool free = false;
      bool occupied = false;
      for (const Point p : points) {
        const Part part = part_of(r, options.pie_half_angle_rad, clear_m, outer_m, p);
        free = free || part == Part::clear;
        occupied = occupied || part == Part::contact;
      }
      if (occupied) {
        update.mark(grid, SubCell{x, y}, 0);
      } else if (free) {
        update.mark(grid, SubCell{x, y}, 1);
      }
    }
  }
}

}  // namespace

LeveledUpdate make_pie_update() { return LeveledUpdate({kPieOccupiedP, kPieFreeP}); }

void mark_pie(const OccupancyGrid &grid, const RangeModelOptions &options,
              std::span<const RangeReading> readings, LeveledUpdate &update) {
  for (const RangeReading &r : readings) mark_one(grid, options, r, update);
}

}  // namespace mapping
