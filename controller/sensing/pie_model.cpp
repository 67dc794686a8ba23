// The IR pie-slice model (sensing/range_models.hpp).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

#include "common/angles.hpp"
#include "mapping/traversal.hpp"
#include "sensing/range_models.hpp"
#include "sensing/scan.hpp"

namespace sensing {

using namespace mapping;  // the grid types this model marks
namespace {

// Where one reading's slices lie, relative to its sensor: half-angle beta around the unit
// direction (dir_x, dir_y); the clear part reaches free_m (<= clear_m, the usable range), the
// contact part is (clear_m, outer_m]; the reading's arc has radius clear_m.
struct Slice {
  Point origin;
  double dir_x, dir_y;
  double beta;
  double free_m, clear_m, outer_m;
};

enum class Part { outside, clear, contact };

// Where point p lies (the spec's test of a corner or the centre).
Part part_of(const Slice &s, Point p) {
  const double ex = p.x_m - s.origin.x_m;
  const double ey = p.y_m - s.origin.y_m;
  const double distance = std::hypot(ex, ey);
  if (distance > s.outer_m) return Part::outside;
  if (distance > 0.0 &&
      std::abs(common::wrap_angle_rad(std::atan2(ey, ex) - std::atan2(s.dir_y, s.dir_x))) > s.beta) {
    return Part::outside;
  }
  if (distance <= s.free_m) return Part::clear;
  return distance <= s.clear_m ? Part::outside : Part::contact;
}

// A convex polygon relative to the sensor (x, y in m): a square clipped by two half-planes
// has at most 4 + 2 vertices.
struct Polygon {
  std::array<std::array<double, 2>, 8> v;
  std::size_t n = 0;
};

// Keeps the part of `poly` where n . p >= 0 (Sutherland-Hodgman against one half-plane).
Polygon clip(const Polygon &poly, double nx, double ny) {
  Polygon out;
  for (std::size_t i = 0; i < poly.n; ++i) {
    const auto &a = poly.v[i];
    const auto &b = poly.v[(i + 1) % poly.n];
    const double da = nx * a[0] + ny * a[1];
    const double db = nx * b[0] + ny * b[1];
    if (da >= 0.0) out.v[out.n++] = a;
    if ((da >= 0.0) != (db >= 0.0)) {
      const double t = da / (da - db);
      out.v[out.n++] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
    }
  }
  return out;
}

double area(const Polygon &poly) {
  double twice = 0.0;
  for (std::size_t i = 0; i < poly.n; ++i) {
    const auto &a = poly.v[i];
    const auto &b = poly.v[(i + 1) % poly.n];
    twice += a[0] * b[1] - a[1] * b[0];
  }
  return std::abs(twice) / 2.0;
}

// Distance from the origin to the segment ab.
double distance_to_segment(const std::array<double, 2> &a, const std::array<double, 2> &b) {
  const double ex = b[0] - a[0];
  const double ey = b[1] - a[1];
  const double length2 = ex * ex + ey * ey;
  const double t = length2 > 0.0 ? std::clamp(-(a[0] * ex + a[1] * ey) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(a[0] + t * ex, a[1] + t * ey);
}

// True when the reading's arcs - radii inner_m ... outer_m, across the slice - pass through
// the inside of the square [left, left + size] x [bottom, bottom + size]. The square clipped
// to the wedge (convex, beta < 90 deg) is a convex polygon; its distances from the sensor
// fill an interval [near, far], which overlaps (inner, outer) when an arc crosses.
bool crossed_by_arcs(const Slice &s, double inner_m, double outer_m, double left, double bottom, double size) {
  const double x0 = left - s.origin.x_m;
  const double y0 = bottom - s.origin.y_m;
  Polygon poly{{{{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}}}, 4};
  // The wedge's sides are the direction turned by -beta and by +beta; inside is to the left
  // of the first and to the right of the second.
  const double c = std::cos(s.beta);
  const double n = std::sin(s.beta);
  const double lx = s.dir_x * c + s.dir_y * n;
  const double ly = -s.dir_x * n + s.dir_y * c;
  const double rx = s.dir_x * c - s.dir_y * n;
  const double ry = s.dir_x * n + s.dir_y * c;
  poly = clip(poly, -ly, lx);
  poly = clip(poly, ry, -rx);
  if (poly.n < 3 || area(poly) <= 1e-9 * size * size) return false;
  double near = std::numeric_limits<double>::infinity();
  double far = 0.0;
  for (std::size_t i = 0; i < poly.n; ++i) {
    far = std::max(far, std::hypot(poly.v[i][0], poly.v[i][1]));
    near = std::min(near, distance_to_segment(poly.v[i], poly.v[(i + 1) % poly.n]));
  }
  return near < outer_m && inner_m < far;
}

// True when the slice's axis, between d (1 - 2 eps) and d (1 + 2 eps), comes within the
// slack of a cell side (a grid line): where a single wall surface the reading saw can be.
bool reaches_cell_side(const GridGeometry &g, const RangeReading &r, double margin) {
  const double slack = kPieSideSlack * g.cell_size_m;
  const double near_m = r.range_m * (1.0 - margin);
  const double far_m = r.range_m * (1.0 + margin);
  const auto crosses = [&](double origin, double direction, double grid_origin) {
    const double a = origin + near_m * direction - grid_origin;
    const double b = origin + far_m * direction - grid_origin;
    const double low = std::min(a, b) - slack;
    const double high = std::max(a, b) + slack;
    return std::floor(high / g.cell_size_m) * g.cell_size_m >= low;
  };
  return crosses(r.origin.x_m, std::cos(r.angle_rad), g.origin.x_m) ||
         crosses(r.origin.y_m, std::sin(r.angle_rad), g.origin.y_m);
}

void mark_one(const OccupancyGrid &grid, const RangeModelOptions &options, const RangeReading &r,
              LeveledUpdate &update) {
  // A contact only when the reading and a no-return reading lie more than kPieNoReturnErrors
  // of their own errors apart (the error is a fraction of the value).
  const double margin = kPieNoReturnErrors * r.range_error;
  const bool contacting = !is_no_return(r);
  // A contact no single wall can explain (rays averaged across a post's edge) is no information.
  if (contacting && !reaches_cell_side(grid.geometry(), r, margin)) return;
  // A clear reading frees up to what it measured, less its error: noise near max range
  // must not free a wall just short of max.
  const double clear_m = contacting ? std::max(r.range_m, 0.0)
                                    : std::min(r.range_m, r.max_range_m) * (1.0 - r.range_error);
  const double outer_m = contacting ? clear_m + options.pie_contact_m : clear_m;
  // The slice frees no farther than the usable range, where the slice is still narrow enough
  // to miss the side walls of a corridor and the far wall of the next cell.
  const double usable_m = options.pie_usable_fraction * r.max_range_m;
  const Slice slice{r.origin, std::cos(r.angle_rad), std::sin(r.angle_rad),
                    options.pie_half_angle_rad, std::min(clear_m, usable_m), clear_m, outer_m};
  // The obstacle lies within the reading's error either side of it (eps is a standard
  // deviation): every sub-cell the arcs of those radii cross is occupied.
  const double arc_inner_m = clear_m * (1.0 - margin);
  const double arc_outer_m = clear_m * (1.0 + margin);
  const GridGeometry &g = grid.geometry();
  const double size = g.subcell_size_m();
  const auto to_index = [&](double v, double origin) {
    return static_cast<int>(std::floor((v - origin) / size));
  };
  const double reach_m = std::max(outer_m, arc_outer_m);
  const int x0 = std::max(0, to_index(r.origin.x_m - reach_m, g.origin.x_m));
  const int x1 = std::min(g.width_subcells() - 1, to_index(r.origin.x_m + reach_m, g.origin.x_m));
  const int y0 = std::max(0, to_index(r.origin.y_m - reach_m, g.origin.y_m));
  const int y1 = std::min(g.height_subcells() - 1, to_index(r.origin.y_m + reach_m, g.origin.y_m));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double left = g.origin.x_m + x * size;
      const double bottom = g.origin.y_m + y * size;
      const Point points[] = {{left, bottom}, {left + size, bottom}, {left, bottom + size},
                              {left + size, bottom + size}, {left + size / 2, bottom + size / 2}};
      bool free = false;
      bool occupied = false;
      for (const Point p : points) {
        const Part part = part_of(slice, p);
        free = free || part == Part::clear;
        occupied = occupied || part == Part::contact;
      }
      occupied = occupied || (contacting && crossed_by_arcs(slice, arc_inner_m, arc_outer_m, left, bottom, size));
      if (occupied) {
        update.mark(grid, SubCell{x, y}, 0);
      } else if (free) {
        update.mark(grid, SubCell{x, y}, 1);
      }
    }
  }
}

}  // namespace

bool is_no_return(const RangeReading &r) {
  const double margin = kPieNoReturnErrors * r.range_error;
  return !(r.range_m * (1.0 + margin) < r.max_range_m * (1.0 - margin));
}

bool no_return_tells(const RangeReading &r) {
  if (!r.echo_can_be_lost) return true;
  const double quarter = std::numbers::pi / 2.0;
  const double off_axis = std::abs(r.angle_rad - quarter * std::round(r.angle_rad / quarter));
  return off_axis + r.aperture_rad / 2.0 < kSonarEchoIncidence_rad;
}

LeveledUpdate make_pie_update() { return LeveledUpdate({kPieOccupiedP, kPieFreeP}); }

void mark_pie(const OccupancyGrid &grid, const RangeModelOptions &options,
              std::span<const RangeReading> readings, LeveledUpdate &update) {
  for (const RangeReading &r : readings) mark_one(grid, options, r, update);
}

}  // namespace sensing
