#include "maze/sim/wall_grid.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>

#include "contact_tolerances.hpp"

namespace maze::sim {

namespace {

constexpr double kSmallestNormal = std::numeric_limits<double>::min();

// A ray (ox, oy) + t (dx, dy), with the inverses of its direction precomputed.
struct Ray {
  double ox, oy, dx, dy, inv_dx, inv_dy;
};

// Narrows [t_min, t_max] to where the ray is within [lo, hi] on one axis (origin o,
// direction d, 1/d); false when it never is (a ray parallel to the axis outside the slab).
bool clip_to_slab(double o, double d, double inv_d, double lo, double hi, double &t_min,
                  double &t_max) {
  if (d == 0.0) return o >= lo && o <= hi;
  double a = (lo - o) * inv_d;
  double c = (hi - o) * inv_d;
  if (a > c) std::swap(a, c);
  t_min = std::max(t_min, a);
  t_max = std::min(t_max, c);
  return true;
}

// Distance t >= 0 at which the ray enters the closed box, or +infinity.
double entry_distance(const Ray &r, double x_min, double y_min, double x_max, double y_max) {
  double t_min = 0.0;
  double t_max = kInfinity;
  if (!clip_to_slab(r.ox, r.dx, r.inv_dx, x_min, x_max, t_min, t_max)) return kInfinity;
  if (!clip_to_slab(r.oy, r.dy, r.inv_dy, y_min, y_max, t_min, t_max)) return kInfinity;
  return t_min <= t_max ? t_min : kInfinity;
}

// The point of the box nearest to (x, y).
void nearest_point(const Box &b, double x, double y, double &qx, double &qy) {
  qx = std::clamp(x, b.x_min_m, b.x_max_m);
  qy = std::clamp(y, b.y_min_m, b.y_max_m);
}

}  // namespace

WallGrid::WallGrid(const Maze &maze)
    : width_(maze.width()),
      height_(maze.height()),
      cell_size_m_(maze.cell_size_m()),
      half_thickness_m_(maze.wall_thickness_m() / 2.0),
      origin_x_m_(maze.origin_x_m()),
      origin_y_m_(maze.origin_y_m()),
      flags_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0) {
  // A grid vertex is solid when any of the (up to four) walls meeting there is present.
  const auto vertex_solid = [&maze](int vx, int vy) {
    bool solid = false;
    if (vx > 0 && vy > 0) {
      solid = solid || maze.has_wall({vx - 1, vy - 1}, Side::north) ||
              maze.has_wall({vx - 1, vy - 1}, Side::east);
    }
    if (vx < maze.width() && vy < maze.height()) {
      solid = solid || maze.has_wall({vx, vy}, Side::south) || maze.has_wall({vx, vy}, Side::west);
    }
    if (vx > 0 && vy < maze.height()) {
      solid = solid || maze.has_wall({vx - 1, vy}, Side::south);
    }
    if (vx < maze.width() && vy > 0) {
      solid = solid || maze.has_wall({vx, vy - 1}, Side::west);
    }
    return solid;
  };
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      std::uint8_t f = 0;
      if (maze.has_wall({x, y}, Side::north)) f |= kNorth;
      if (maze.has_wall({x, y}, Side::east)) f |= kEast;
      if (maze.has_wall({x, y}, Side::south)) f |= kSouth;
      if (maze.has_wall({x, y}, Side::west)) f |= kWest;
      // A corner square already inside one of this cell's strips needs no box of its own.
      if (!(f & (kNorth | kEast)) && vertex_solid(x + 1, y + 1)) f |= kCornerNE;
      if (!(f & (kNorth | kWest)) && vertex_solid(x, y + 1)) f |= kCornerNW;
      if (!(f & (kSouth | kWest)) && vertex_solid(x, y)) f |= kCornerSW;
      if (!(f & (kSouth | kEast)) && vertex_solid(x + 1, y)) f |= kCornerSE;
      flags_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
             static_cast<std::size_t>(x)] = f;
    }
  }
}

bool WallGrid::inside_maze(double x_m, double y_m) const {
  const double lx = x_m - origin_x_m_;
  const double ly = y_m - origin_y_m_;
  return lx >= 0.0 && ly >= 0.0 && lx <= width_ * cell_size_m_ && ly <= height_ * cell_size_m_;
}

template <typename Visit>
void WallGrid::for_each_box(int cx, int cy, std::uint8_t mask, Visit &&visit) const {
  const std::uint8_t f = flags(cx, cy) & mask;
  if (f == 0) return;
  const double s = cell_size_m_;
  const double h = half_thickness_m_;
  const double x0 = origin_x_m_ + cx * s;
  const double y0 = origin_y_m_ + cy * s;
  const double x1 = x0 + s;
  const double y1 = y0 + s;
  if (f & kNorth) visit(Box{x0, y1 - h, x1, y1});
  if (f & kSouth) visit(Box{x0, y0, x1, y0 + h});
  if (f & kEast) visit(Box{x1 - h, y0, x1, y1});
  if (f & kWest) visit(Box{x0, y0, x0 + h, y1});
  if (f & kCornerNE) visit(Box{x1 - h, y1 - h, x1, y1});
  if (f & kCornerNW) visit(Box{x0, y1 - h, x0 + h, y1});
  if (f & kCornerSW) visit(Box{x0, y0, x0 + h, y0 + h});
  if (f & kCornerSE) visit(Box{x1 - h, y0, x1, y0 + h});
}

template <typename Visit>
void WallGrid::for_each_box_near(double x_m, double y_m, double reach_m, Visit &&visit) const {
  const double s = cell_size_m_;
  const auto cell_of = [s](double v, int n) {
    return std::clamp(static_cast<int>(std::floor(v / s)), 0, n - 1);
  };
  const double lx = x_m - origin_x_m_;
  const double ly = y_m - origin_y_m_;
  const int x_lo = cell_of(lx - reach_m, width_);
  const int x_hi = cell_of(lx + reach_m, width_);
  const int y_lo = cell_of(ly - reach_m, height_);
  const int y_hi = cell_of(ly + reach_m, height_);
  for (int cy = y_lo; cy <= y_hi; ++cy) {
    for (int cx = x_lo; cx <= x_hi; ++cx) for_each_box(cx, cy, 0xff, visit);
  }
}

bool WallGrid::inside_wall(double x_m, double y_m) const {
  bool inside = false;
  for_each_box_near(x_m, y_m, 0.0, [&](const Box &b) {
    inside = inside || (x_m >= b.x_min_m && x_m <= b.x_max_m && y_m >= b.y_min_m && y_m <= b.y_max_m);
  });
  return inside;
}

double WallGrid::cast(double x_m, double y_m, double angle_rad, double max_range_m) const {
  return cast_direction(x_m, y_m, std::cos(angle_rad), std::sin(angle_rad), max_range_m);
}

WallGrid::CastOrigin WallGrid::cast_origin(double x_m, double y_m) const {
  CastOrigin o;
  o.x_m = x_m;
  o.y_m = y_m;
  o.inside = inside_maze(x_m, y_m);
  o.local_x_m = x_m - origin_x_m_;
  o.local_y_m = y_m - origin_y_m_;
  o.cell_x = o.inside ? std::min(static_cast<int>(o.local_x_m / cell_size_m_), width_ - 1) : 0;
  o.cell_y = o.inside ? std::min(static_cast<int>(o.local_y_m / cell_size_m_), height_ - 1) : 0;
  return o;
}

double WallGrid::cast_direction(double x_m, double y_m, double dx, double dy,
                                double max_range_m) const {
  return cast_from(cast_origin(x_m, y_m), dx, dy, max_range_m);
}

double WallGrid::cast_from(const CastOrigin &origin, double dx, double dy,
                           double max_range_m) const {
  return cast_with_inverses(origin, dx, dy, 1.0 / dx, 1.0 / dy, max_range_m);
}

double WallGrid::cast_with_inverses(const CastOrigin &origin, double dx, double dy, double inv_dx, double inv_dy,
                                    double max_range_m) const {
  // A ray along an axis has slabs it never crosses: the reference handles those exactly. So
  // does it a ray with a subnormal component, whose inverse overflows to infinity (an origin
  // on a box edge then makes 0 * infinity, and the quadrant walk's order of max and min
  // would turn that NaN into another answer than the reference's).
  if (std::abs(dx) < kSmallestNormal || std::abs(dy) < kSmallestNormal || !(std::isfinite(dx) && std::isfinite(dy))) {
    return cast_reference(origin.x_m, origin.y_m, dx, dy, max_range_m);
  }
  if (!origin.inside) return kInfinity;
  if (dx > 0.0) {
    return dy > 0.0 ? cast_quadrant<true, true>(origin, inv_dx, inv_dy, max_range_m)
                    : cast_quadrant<true, false>(origin, inv_dx, inv_dy, max_range_m);
  }
  return dy > 0.0 ? cast_quadrant<false, true>(origin, inv_dx, inv_dy, max_range_m)
                  : cast_quadrant<false, false>(origin, inv_dx, inv_dy, max_range_m);
}

void WallGrid::cast_fan(const CastOrigin &origin, std::span<const double> dx, std::span<const double> dy,
                        double max_range_m, std::span<double> ranges) const {
  assert(dy.size() == dx.size() && ranges.size() == dx.size());
  constexpr std::size_t kBlock = 64;
  double inv_dx[kBlock], inv_dy[kBlock];
  for (std::size_t start = 0; start < dx.size(); start += kBlock) {
    const std::size_t n = std::min(kBlock, dx.size() - start);
    for (std::size_t k = 0; k < n; ++k) {
      inv_dx[k] = 1.0 / dx[start + k];
      inv_dy[k] = 1.0 / dy[start + k];
    }
    for (std::size_t k = 0; k < n; ++k) {
      const double x = dx[start + k], y = dy[start + k];
      // cast_with_inverses, its four walks inlined here: a fan's beams share the origin's loads.
      if (!origin.inside || !(std::abs(x) >= kSmallestNormal) || !(std::abs(y) >= kSmallestNormal) ||
          !(std::isfinite(x) && std::isfinite(y))) {
        ranges[start + k] = cast_with_inverses(origin, x, y, inv_dx[k], inv_dy[k], max_range_m);
      } else if (x > 0.0) {
        ranges[start + k] = y > 0.0 ? cast_quadrant<true, true>(origin, inv_dx[k], inv_dy[k], max_range_m)
                                    : cast_quadrant<true, false>(origin, inv_dx[k], inv_dy[k], max_range_m);
      } else {
        ranges[start + k] = y > 0.0 ? cast_quadrant<false, true>(origin, inv_dx[k], inv_dy[k], max_range_m)
                                    : cast_quadrant<false, false>(origin, inv_dx[k], inv_dy[k], max_range_m);
      }
    }
  }
}

template <bool kEastward, bool kNorthward>
double WallGrid::entry_in_cell(std::uint8_t f, int cx, int cy, const CastOrigin &origin, double inv_dx,
                               double inv_dy) const {
  const double s = cell_size_m_;
  const double h = half_thickness_m_;
  const double ox = origin.local_x_m;
  const double oy = origin.local_y_m;
  constexpr std::uint8_t mask = static_cast<std::uint8_t>(
      (kEastward ? kEast | kCornerNE | kCornerSE : kWest | kCornerNW | kCornerSW) |
      (kNorthward ? kNorth | kCornerNE | kCornerNW : kSouth | kCornerSW | kCornerSE));
  // The same slab arithmetic as entry_distance, (edge - origin) / direction for each of
  // the cell's four x and four y box edges: 0 the west (south) side, 1 h inside it,
  // 2 h inside the east (north) side, 3 that side.
  const double x0 = cx * s;
  const double y0 = cy * s;
  const double x1 = x0 + s;
  const double y1 = y0 + s;
  const auto tx = [&](int edge) {
    switch (edge) {
      case 0: return (x0 - ox) * inv_dx;
      case 1: return (x0 + h - ox) * inv_dx;
      case 2: return (x1 - h - ox) * inv_dx;
      default: return (x1 - ox) * inv_dx;
    }
  };
  const auto ty = [&](int edge) {
    switch (edge) {
      case 0: return (y0 - oy) * inv_dy;
      case 1: return (y0 + h - oy) * inv_dy;
      case 2: return (y1 - h - oy) * inv_dy;
      default: return (y1 - oy) * inv_dy;
    }
  };
  // The box spanning edges [xl, xh] x [yl, yh]: entered at the later of its two slab
  // entries (and not before 0), left at the earlier of the exits.
  double best = kInfinity;
  const auto box = [&](int xl, int xh, int yl, int yh) {
    const double in_x = kEastward ? tx(xl) : tx(xh);
    const double out_x = kEastward ? tx(xh) : tx(xl);
    const double in_y = kNorthward ? ty(yl) : ty(yh);
    const double out_y = kNorthward ? ty(yh) : ty(yl);
    const double t_in = std::max(std::max(0.0, in_x), in_y);
    const double t_out = std::min(out_x, out_y);
    if (t_in <= t_out) best = std::min(best, t_in);
  };
  if ((mask & kNorth) && (f & kNorth)) box(0, 3, 2, 3);
  if ((mask & kSouth) && (f & kSouth)) box(0, 3, 0, 1);
  if ((mask & kEast) && (f & kEast)) box(2, 3, 0, 3);
  if ((mask & kWest) && (f & kWest)) box(0, 1, 0, 3);
  if ((mask & kCornerNE) && (f & kCornerNE)) box(2, 3, 2, 3);
  if ((mask & kCornerNW) && (f & kCornerNW)) box(0, 1, 2, 3);
  if ((mask & kCornerSW) && (f & kCornerSW)) box(0, 1, 0, 1);
  if ((mask & kCornerSE) && (f & kCornerSE)) box(2, 3, 0, 1);
  return best;
}

template <bool kEastward, bool kNorthward>
double WallGrid::cast_quadrant(const CastOrigin &origin, double inv_dx, double inv_dy,
                               double max_range_m) const {
  const double s = cell_size_m_;
  const double ox = origin.local_x_m;
  const double oy = origin.local_y_m;
  int cx = origin.cell_x;
  int cy = origin.cell_y;
  // The boxes with a face turned towards the ray, as in cast_reference.
  constexpr std::uint8_t mask = static_cast<std::uint8_t>(
      (kEastward ? kEast | kCornerNE | kCornerSE : kWest | kCornerNW | kCornerSW) |
      (kNorthward ? kNorth | kCornerNE | kCornerNW : kSouth | kCornerSW | kCornerSE));
  constexpr int step_x = kEastward ? 1 : -1;
  constexpr int step_y = kNorthward ? 1 : -1;
  const double t_delta_x = s * std::abs(inv_dx);
  const double t_delta_y = s * std::abs(inv_dy);
  double t_max_x = ((cx + (kEastward ? 1 : 0)) * s - ox) * inv_dx;
  double t_max_y = ((cy + (kNorthward ? 1 : 0)) * s - oy) * inv_dy;
  const double clear_x = half_thickness_m_ * std::abs(inv_dx) + kClearPass_cells * (t_delta_x + t_delta_y);
  const double clear_y = half_thickness_m_ * std::abs(inv_dy) + kClearPass_cells * (t_delta_x + t_delta_y);
  constexpr auto pass_y = static_cast<std::uint8_t>(~(kNorthward ? kNorth | kCornerNE | kCornerNW : kSouth | kCornerSW | kCornerSE));
  constexpr auto pass_x = static_cast<std::uint8_t>(~(kEastward ? kEast | kCornerNE | kCornerSE : kWest | kCornerNW | kCornerSW));
  for (;;) {
    std::uint8_t f = flags(cx, cy) & mask;
    if (f != 0 && t_max_y - t_max_x > clear_y) f &= pass_y;  // leaving across the far x side
    else if (f != 0 && t_max_x - t_max_y > clear_x) f &= pass_x;
    if (f != 0) {
      const double best = entry_in_cell<kEastward, kNorthward>(f, cx, cy, origin, inv_dx, inv_dy);
      if (best < kInfinity) return best <= max_range_m ? best : kInfinity;
    }
    if (std::min(t_max_x, t_max_y) > max_range_m) return kInfinity;
    if (t_max_x < t_max_y) {
      cx += step_x;
      t_max_x += t_delta_x;
    } else {
      cy += step_y;
      t_max_y += t_delta_y;
    }
    if (cx < 0 || cy < 0 || cx >= width_ || cy >= height_) return kInfinity;
  }
}

double WallGrid::cast_reference(double x_m, double y_m, double dx, double dy,
                                double max_range_m) const {
  if (!inside_maze(x_m, y_m)) return kInfinity;
  const double s = cell_size_m_;
  const Ray ray{x_m - origin_x_m_, y_m - origin_y_m_, dx, dy, 1.0 / dx, 1.0 / dy};
  int cx = std::min(static_cast<int>(ray.ox / s), width_ - 1);
  int cy = std::min(static_cast<int>(ray.oy / s), height_ - 1);

  // Only boxes with a face turned towards the ray can be entered from inside a cell; the
  // others are continued by a solid box of the cell the ray came from.
  std::uint8_t mask = 0;
  if (dx > 0.0) mask |= kEast | kCornerNE | kCornerSE;
  if (dx < 0.0) mask |= kWest | kCornerNW | kCornerSW;
  if (dy > 0.0) mask |= kNorth | kCornerNE | kCornerNW;
  if (dy < 0.0) mask |= kSouth | kCornerSW | kCornerSE;

  const int step_x = dx > 0.0 ? 1 : -1;
  const int step_y = dy > 0.0 ? 1 : -1;
  const double t_delta_x = dx != 0.0 ? s * std::abs(ray.inv_dx) : kInfinity;
  const double t_delta_y = dy != 0.0 ? s * std::abs(ray.inv_dy) : kInfinity;
  double t_max_x = dx != 0.0 ? ((cx + (dx > 0.0 ? 1 : 0)) * s - ray.ox) * ray.inv_dx : kInfinity;
  double t_max_y = dy != 0.0 ? ((cy + (dy > 0.0 ? 1 : 0)) * s - ray.oy) * ray.inv_dy : kInfinity;

  const double h = half_thickness_m_;
  for (;;) {
    const std::uint8_t f = flags(cx, cy) & mask;
    if (f != 0) {
      const double x0 = cx * s;
      const double y0 = cy * s;
      const double x1 = x0 + s;
      const double y1 = y0 + s;
      double best = kInfinity;
      if (f & kNorth) best = std::min(best, entry_distance(ray, x0, y1 - h, x1, y1));
      if (f & kSouth) best = std::min(best, entry_distance(ray, x0, y0, x1, y0 + h));
      if (f & kEast) best = std::min(best, entry_distance(ray, x1 - h, y0, x1, y1));
      if (f & kWest) best = std::min(best, entry_distance(ray, x0, y0, x0 + h, y1));
      if (f & kCornerNE) best = std::min(best, entry_distance(ray, x1 - h, y1 - h, x1, y1));
      if (f & kCornerNW) best = std::min(best, entry_distance(ray, x0, y1 - h, x0 + h, y1));
      if (f & kCornerSW) best = std::min(best, entry_distance(ray, x0, y0, x0 + h, y0 + h));
      if (f & kCornerSE) best = std::min(best, entry_distance(ray, x1 - h, y0, x1, y0 + h));
      if (best < kInfinity) return best <= max_range_m ? best : kInfinity;
    }
    if (std::min(t_max_x, t_max_y) > max_range_m) return kInfinity;
    if (t_max_x < t_max_y) {
      cx += step_x;
      t_max_x += t_delta_x;
    } else {
      cy += step_y;
      t_max_y += t_delta_y;
    }
    if (cx < 0 || cy < 0 || cx >= width_ || cy >= height_) return kInfinity;
  }
}

std::optional<Box> WallGrid::free_centres(double x_m, double y_m, double radius_m) const {
  const double s = cell_size_m_;
  const double lx = x_m - origin_x_m_;
  const double ly = y_m - origin_y_m_;
  const double fx = std::floor(lx / s);
  const double fy = std::floor(ly / s);
  if (!(fx >= 0.0 && fy >= 0.0 && fx < width_ && fy < height_)) return std::nullopt;
  // Every solid box of this cell lies within h of its sides, every other cell's box outside
  // it; the margin keeps the answer on the safe side of rounding.
  const double reach = radius_m + half_thickness_m_ + kCoreMargin_m;
  if (2.0 * reach >= s) return std::nullopt;
  const double x0 = origin_x_m_ + fx * s;
  const double y0 = origin_y_m_ + fy * s;
  Box core{x0 + reach, y0 + reach, x0 + s - reach, y0 + s - reach};
  // Near an open side, the box reaches on through it to the far side of the neighbour: the
  // solid boxes of two cells sharing an open side all lie within h of the pair's outer sides
  // or at the ends of the shared side, so the pair's core is clear too. A body driving from
  // cell to cell then stays inside one box all the way.
  const int cx = static_cast<int>(fx);
  const int cy = static_cast<int>(fy);
  const std::uint8_t f = flags(cx, cy);
  const bool within_x = x_m > core.x_min_m && x_m < core.x_max_m;
  const bool within_y = y_m > core.y_min_m && y_m < core.y_max_m;
  if (within_y && x_m >= core.x_max_m && !(f & kEast) && cx + 1 < width_) core.x_max_m += s;
  if (within_y && x_m <= core.x_min_m && !(f & kWest) && cx > 0) core.x_min_m -= s;
  if (within_x && y_m >= core.y_max_m && !(f & kNorth) && cy + 1 < height_) core.y_max_m += s;
  if (within_x && y_m <= core.y_min_m && !(f & kSouth) && cy > 0) core.y_min_m -= s;
  return core;
}

bool WallGrid::push_out(double &x_m, double &y_m, double radius_m) const {
  bool moved = false;
  for (int pass = 0; pass < 4; ++pass) {
    bool moved_this_pass = false;
    // The boxes near where the pass starts (the position moves during the pass).
    for_each_box_near(x_m, y_m, radius_m, [&](const Box &b) {
      double qx = 0.0, qy = 0.0;
      nearest_point(b, x_m, y_m, qx, qy);
      const double ex = x_m - qx;
      const double ey = y_m - qy;
      // hypot(ex, ey) >= max(|ex|, |ey|): a box that far away needs no hypot.
      if (std::max(std::abs(ex), std::abs(ey)) >= radius_m - kSlop_m) return;
      const double d = std::hypot(ex, ey);
      if (d >= radius_m - kSlop_m) return;
      if (d > 0.0) {
        x_m += ex / d * (radius_m - d);
        y_m += ey / d * (radius_m - d);
      } else {
        // The centre is inside the box: leave through the nearest face.
        const double left = x_m - b.x_min_m, right = b.x_max_m - x_m;
        const double down = y_m - b.y_min_m, up = b.y_max_m - y_m;
        const double least = std::min({left, right, down, up});
        if (least == left) x_m = b.x_min_m - radius_m;
        else if (least == right) x_m = b.x_max_m + radius_m;
        else if (least == down) y_m = b.y_min_m - radius_m;
        else y_m = b.y_max_m + radius_m;
      }
      moved_this_pass = true;
    });
    if (!moved_this_pass) break;
    moved = true;
  }
  return moved;
}

std::vector<Contact> WallGrid::contacts(double x_m, double y_m, double reach_m) const {
  std::vector<Contact> out;
  for_each_box_near(x_m, y_m, reach_m, [&](const Box &b) {
    double qx = 0.0, qy = 0.0;
    nearest_point(b, x_m, y_m, qx, qy);
    const double d = std::hypot(x_m - qx, y_m - qy);
    if (d <= reach_m) out.push_back({qx, qy, d});
  });
  return out;
}

}  // namespace maze::sim
