#include "maze/sim/solid_geometry.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "contact_tolerances.hpp"

namespace maze::sim {

namespace {

constexpr int kMaxBucketsPerSide = 64;
constexpr double kMinBucket_m = 0.1;

// Narrows [t_in, t_out] to where o + t d is within [lo, hi]; records whether this slab set
// t_in. False when the ray is parallel to the slab and outside it.
bool clip(double o, double d, double lo, double hi, double &t_in, double &t_out, bool &entered_here) {
  entered_here = false;
  if (d == 0.0) return o >= lo && o <= hi;
  const double inv = 1.0 / d;
  double a = (lo - o) * inv;
  double b = (hi - o) * inv;
  if (a > b) std::swap(a, b);
  if (a > t_in) {
    t_in = a;
    entered_here = true;
  }
  t_out = std::min(t_out, b);
  return true;
}

// Whether the closed box [x0, x1] x [y0, y1] touches the closed obstacle (separating axes).
bool touches(const Obstacle &o, double x0, double y0, double x1, double y1) {
  const auto b = o.bounds();
  if (b[0] > x1 || b[2] < x0 || b[1] > y1 || b[3] < y0) return false;
  if (o.axis_aligned()) return true;
  const auto corners = o.corners();
  const double c = std::cos(o.angle_rad);
  const double s = std::sin(o.angle_rad);
  const ArenaPoint box[] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  for (const ArenaPoint axis : {ArenaPoint{c, s}, ArenaPoint{-s, c}}) {
    double olo = kInfinity, ohi = -kInfinity, blo = kInfinity, bhi = -kInfinity;
    for (const ArenaPoint &p : corners) {
      const double d = p.x_m * axis.x_m + p.y_m * axis.y_m;
      olo = std::min(olo, d);
      ohi = std::max(ohi, d);
    }
    for (const ArenaPoint &p : box) {
      const double d = p.x_m * axis.x_m + p.y_m * axis.y_m;
      blo = std::min(blo, d);
      bhi = std::max(bhi, d);
    }
    // A little slack: listing an obstacle in one bucket too many costs a test, one too few a miss.
    if (olo > bhi + 1e-9 || blo > ohi + 1e-9) return false;
  }
  return true;
}

}  // namespace

SolidGeometry::SolidGeometry(const Arena &arena)
    : x_min_m_(arena.x_min_m), y_min_m_(arena.y_min_m), x_max_m_(arena.x_max_m), y_max_m_(arena.y_max_m),
      walled_(arena.boundary_walled) {
  assert(x_max_m_ > x_min_m_ && y_max_m_ > y_min_m_);
  const double side = std::max(x_max_m_ - x_min_m_, y_max_m_ - y_min_m_);
  bucket_m_ = std::max(side / kMaxBucketsPerSide, kMinBucket_m);
  nx_ = std::clamp(static_cast<int>(std::ceil((x_max_m_ - x_min_m_) / bucket_m_)), 1, kMaxBucketsPerSide);
  ny_ = std::clamp(static_cast<int>(std::ceil((y_max_m_ - y_min_m_) / bucket_m_)), 1, kMaxBucketsPerSide);
  for (const Obstacle &o : arena.obstacles) {
    const auto b = o.bounds();
    solids_.push_back({o.centre_x_m, o.centre_y_m, std::cos(o.angle_rad), std::sin(o.angle_rad), o.half_length_m,
                       o.half_width_m, b[0], b[1], b[2], b[3], o.axis_aligned()});
  }
  for (const ArenaDisc &d : arena.discs) {
    const double r = d.radius_m;
    solids_.push_back({d.centre_x_m, d.centre_y_m, 1.0, 0.0, 0.0, 0.0, d.centre_x_m - r, d.centre_y_m - r,
                       d.centre_x_m + r, d.centre_y_m + r, false, r, true});
  }
  // Two passes: count each bucket's solids, then fill (compressed rows). A disc is listed in
  // every bucket its bounding box meets (a test too many at worst).
  std::vector<std::vector<std::uint32_t>> lists(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_));
  for (std::size_t k = 0; k < solids_.size(); ++k) {
    const Solid &sd = solids_[k];
    if (sd.x1 < x_min_m_ || sd.x0 > x_max_m_ || sd.y1 < y_min_m_ || sd.y0 > y_max_m_) continue;
    for (int by = bucket_of_y(sd.y0); by <= bucket_of_y(sd.y1); ++by) {
      for (int bx = bucket_of_x(sd.x0); bx <= bucket_of_x(sd.x1); ++bx) {
        const double x0 = x_min_m_ + bx * bucket_m_;
        const double y0 = y_min_m_ + by * bucket_m_;
        if (sd.disc || touches(arena.obstacles[k], x0, y0, x0 + bucket_m_, y0 + bucket_m_)) {
          lists[bucket_index(bx, by)].push_back(static_cast<std::uint32_t>(k));
        }
      }
    }
  }
  first_.push_back(0);
  for (const auto &l : lists) {
    items_.insert(items_.end(), l.begin(), l.end());
    first_.push_back(static_cast<std::uint32_t>(items_.size()));
  }
}

int SolidGeometry::bucket_of_x(double x_m) const {
  return std::clamp(static_cast<int>(std::floor((x_m - x_min_m_) / bucket_m_)), 0, nx_ - 1);
}

int SolidGeometry::bucket_of_y(double y_m) const {
  return std::clamp(static_cast<int>(std::floor((y_m - y_min_m_) / bucket_m_)), 0, ny_ - 1);
}

bool SolidGeometry::inside_bounds(double x_m, double y_m) const {
  return x_m >= x_min_m_ && x_m <= x_max_m_ && y_m >= y_min_m_ && y_m <= y_max_m_;
}

bool SolidGeometry::inside_solid(double x_m, double y_m) const {
  if (!inside_bounds(x_m, y_m)) return walled_;
  const std::size_t b = bucket_index(bucket_of_x(x_m), bucket_of_y(y_m));
  for (std::uint32_t i = first_[b]; i < first_[b + 1]; ++i) {
    const Solid &k = solids_[items_[i]];
    if (k.disc) {
      if (std::hypot(x_m - k.cx, y_m - k.cy) <= k.r) return true;
      continue;
    }
    if (k.aligned) {
      if (x_m >= k.x0 && x_m <= k.x1 && y_m >= k.y0 && y_m <= k.y1) return true;
      continue;
    }
    const double dx = x_m - k.cx;
    const double dy = y_m - k.cy;
    if (std::abs(k.c * dx + k.s * dy) <= k.hl && std::abs(-k.s * dx + k.c * dy) <= k.hw) return true;
  }
  return false;
}

SolidGeometry::CastOrigin SolidGeometry::cast_origin(double x_m, double y_m) const {
  return {x_m, y_m, bucket_of_x(x_m), bucket_of_y(y_m), inside_bounds(x_m, y_m)};
}

double SolidGeometry::disc_entry(const Solid &k, double ox, double oy, double dx, double dy, double &nx,
                                 double &ny) {
  const double px = ox - k.cx;
  const double py = oy - k.cy;
  const double c = px * px + py * py - k.r * k.r;
  if (c <= 0.0) {  // from inside or on the surface: 0, the normal away from the centre
    const double d = std::hypot(px, py);
    nx = d > 0.0 ? px / d : -dx;
    ny = d > 0.0 ? py / d : -dy;
    return 0.0;
  }
  const double b = px * dx + py * dy;
  const double discriminant = b * b - c;
  if (b > 0.0 || discriminant < 0.0) return kInfinity;
  const double t = -b - std::sqrt(discriminant);
  nx = (px + t * dx) / k.r;
  ny = (py + t * dy) / k.r;
  return t;
}

double SolidGeometry::entry(const Solid &k, double ox, double oy, double dx, double dy, double &nx,
                            double &ny) const {
  if (k.disc) return disc_entry(k, ox, oy, dx, dy, nx, ny);
  double t_in = 0.0;
  double t_out = kInfinity;
  bool first_axis = false;
  bool second_axis = false;
  if (k.aligned) {
    if (!clip(ox, dx, k.x0, k.x1, t_in, t_out, first_axis)) return kInfinity;
    if (!clip(oy, dy, k.y0, k.y1, t_in, t_out, second_axis)) return kInfinity;
    if (t_in > t_out) return kInfinity;
    if (second_axis) {
      nx = 0.0;
      ny = dy > 0.0 ? -1.0 : 1.0;
    } else {
      nx = dx > 0.0 ? -1.0 : dx < 0.0 ? 1.0 : 0.0;
      ny = 0.0;
      if (!first_axis) {  // from inside or on the surface: the nearer face's normal
        const double to_x = std::min(ox - k.x0, k.x1 - ox);
        const double to_y = std::min(oy - k.y0, k.y1 - oy);
        if (to_y < to_x) {
          nx = 0.0;
          ny = oy - k.y0 < k.y1 - oy ? -1.0 : 1.0;
        } else {
          nx = ox - k.x0 < k.x1 - ox ? -1.0 : 1.0;
        }
      }
    }
    return t_in;
  }
  const double px = ox - k.cx;
  const double py = oy - k.cy;
  const double u = k.c * px + k.s * py;
  const double v = -k.s * px + k.c * py;
  const double du = k.c * dx + k.s * dy;
  const double dv = -k.s * dx + k.c * dy;
  if (!clip(u, du, -k.hl, k.hl, t_in, t_out, first_axis)) return kInfinity;
  if (!clip(v, dv, -k.hw, k.hw, t_in, t_out, second_axis)) return kInfinity;
  if (t_in > t_out) return kInfinity;
  double lu = 0.0;
  double lv = 0.0;
  if (second_axis) {
    lv = dv > 0.0 ? -1.0 : 1.0;
  } else if (first_axis) {
    lu = du > 0.0 ? -1.0 : 1.0;
  } else if (k.hl - std::abs(u) < k.hw - std::abs(v)) {
    lu = u < 0.0 ? -1.0 : 1.0;
  } else {
    lv = v < 0.0 ? -1.0 : 1.0;
  }
  nx = k.c * lu - k.s * lv;
  ny = k.s * lu + k.c * lv;
  return t_in;
}

double SolidGeometry::cast_from(const CastOrigin &origin, double dx, double dy, double max_range_m,
                                double *normal_x, double *normal_y) const {
  double nx = 0.0;
  double ny = 0.0;
  const auto answer = [&](double t) {
    const bool hit = t <= max_range_m;
    if (normal_x != nullptr) *normal_x = hit ? nx : 0.0;
    if (normal_y != nullptr) *normal_y = hit ? ny : 0.0;
    return hit ? t : kInfinity;
  };
  if (!origin.inside || !(std::isfinite(dx) && std::isfinite(dy))) return answer(kInfinity);
  const double ox = origin.x_m;
  const double oy = origin.y_m;
  // The boundary, met from inside at the nearer of its exits.
  const double exit_x = dx > 0.0 ? (x_max_m_ - ox) / dx : dx < 0.0 ? (x_min_m_ - ox) / dx : kInfinity;
  const double exit_y = dy > 0.0 ? (y_max_m_ - oy) / dy : dy < 0.0 ? (y_min_m_ - oy) / dy : kInfinity;
  const double boundary_t = std::min(exit_x, exit_y);
  // The buckets along the ray.
  int bx = origin.bucket_x;
  int by = origin.bucket_y;
  const int step_x = dx > 0.0 ? 1 : -1;
  const int step_y = dy > 0.0 ? 1 : -1;
  const double t_delta_x = dx != 0.0 ? bucket_m_ / std::abs(dx) : kInfinity;
  const double t_delta_y = dy != 0.0 ? bucket_m_ / std::abs(dy) : kInfinity;
  double t_max_x = dx != 0.0 ? (x_min_m_ + (bx + (dx > 0.0 ? 1 : 0)) * bucket_m_ - ox) / dx : kInfinity;
  double t_max_y = dy != 0.0 ? (y_min_m_ + (by + (dy > 0.0 ? 1 : 0)) * bucket_m_ - oy) / dy : kInfinity;
  const double limit = std::min(boundary_t, max_range_m);
  double best = kInfinity;
  for (;;) {
    const std::size_t b = bucket_index(bx, by);
    for (std::uint32_t i = first_[b]; i < first_[b + 1]; ++i) {
      double hx = 0.0;
      double hy = 0.0;
      const double t = entry(solids_[items_[i]], ox, oy, dx, dy, hx, hy);
      if (t < best) {
        best = t;
        nx = hx;
        ny = hy;
      }
    }
    const double bucket_exit = std::min(t_max_x, t_max_y);
    if (best <= bucket_exit || bucket_exit > limit) break;
    if (t_max_x < t_max_y) {
      bx += step_x;
      t_max_x += t_delta_x;
    } else {
      by += step_y;
      t_max_y += t_delta_y;
    }
    if (bx < 0 || by < 0 || bx >= nx_ || by >= ny_) break;
  }
  if (best <= boundary_t || !walled_) return answer(best);
  nx = exit_x <= exit_y ? (dx > 0.0 ? -1.0 : 1.0) : 0.0;
  ny = exit_x <= exit_y ? 0.0 : (dy > 0.0 ? -1.0 : 1.0);
  return answer(boundary_t);
}

double SolidGeometry::cast_direction(double x_m, double y_m, double dx, double dy, double max_range_m) const {
  return cast_from(cast_origin(x_m, y_m), dx, dy, max_range_m);
}

double SolidGeometry::cast(double x_m, double y_m, double angle_rad, double max_range_m) const {
  return cast_direction(x_m, y_m, std::cos(angle_rad), std::sin(angle_rad), max_range_m);
}

double SolidGeometry::cast_brute_force(double x_m, double y_m, double dx, double dy, double max_range_m) const {
  if (!inside_bounds(x_m, y_m)) return kInfinity;
  const double exit_x = dx > 0.0 ? (x_max_m_ - x_m) / dx : dx < 0.0 ? (x_min_m_ - x_m) / dx : kInfinity;
  const double exit_y = dy > 0.0 ? (y_max_m_ - y_m) / dy : dy < 0.0 ? (y_min_m_ - y_m) / dy : kInfinity;
  double best = walled_ ? std::min(exit_x, exit_y) : kInfinity;
  for (const Solid &k : solids_) {
    double hx = 0.0;
    double hy = 0.0;
    best = std::min(best, entry(k, x_m, y_m, dx, dy, hx, hy));
  }
  return best <= max_range_m ? best : kInfinity;
}

std::vector<std::uint32_t> SolidGeometry::near(double x0, double y0, double x1, double y1) const {
  std::vector<std::uint32_t> found;
  for (int by = bucket_of_y(y0); by <= bucket_of_y(y1); ++by) {
    for (int bx = bucket_of_x(x0); bx <= bucket_of_x(x1); ++bx) {
      const std::size_t b = bucket_index(bx, by);
      found.insert(found.end(), items_.begin() + first_[b], items_.begin() + first_[b + 1]);
    }
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

namespace {

struct Near {
  double qx, qy;   // the nearest point of the solid
  bool inside;     // the centre is inside it
};

}  // namespace

bool SolidGeometry::push_out(double &x_m, double &y_m, double radius_m) const {
  bool moved = false;
  for (int pass = 0; pass < 4; ++pass) {
    bool moved_this_pass = false;
    for (const std::uint32_t index : near(x_m - radius_m, y_m - radius_m, x_m + radius_m, y_m + radius_m)) {
      const Solid &k = solids_[index];
      const double px = x_m - k.cx;
      const double py = y_m - k.cy;
      if (k.disc) {
        const double d = std::hypot(px, py);
        const double reach = radius_m + k.r;
        if (d >= reach - kSlop_m) continue;
        x_m = d > 0.0 ? k.cx + px / d * reach : k.cx + reach;
        y_m = d > 0.0 ? k.cy + py / d * reach : k.cy;
        moved_this_pass = true;
        continue;
      }
      const double u = k.aligned ? px : k.c * px + k.s * py;
      const double v = k.aligned ? py : -k.s * px + k.c * py;
      const double hu = k.aligned ? (k.x1 - k.x0) / 2.0 : k.hl;
      const double hv = k.aligned ? (k.y1 - k.y0) / 2.0 : k.hw;
      const double cu = std::clamp(u, -hu, hu);
      const double cv = std::clamp(v, -hv, hv);
      const double eu = u - cu;
      const double ev = v - cv;
      if (std::max(std::abs(eu), std::abs(ev)) >= radius_m - kSlop_m) continue;
      const double d = std::hypot(eu, ev);
      if (d >= radius_m - kSlop_m) continue;
      double mu = 0.0;
      double mv = 0.0;
      if (d > 0.0) {
        mu = eu / d * (radius_m - d);
        mv = ev / d * (radius_m - d);
      } else {
        // The centre is inside: leave through the nearest face.
        const double to_u = hu - std::abs(u);
        const double to_v = hv - std::abs(v);
        if (to_u <= to_v) {
          mu = (u < 0.0 ? -1.0 : 1.0) * (to_u + radius_m);
        } else {
          mv = (v < 0.0 ? -1.0 : 1.0) * (to_v + radius_m);
        }
      }
      x_m += k.aligned ? mu : k.c * mu - k.s * mv;
      y_m += k.aligned ? mv : k.s * mu + k.c * mv;
      moved_this_pass = true;
    }
    const double cx = walled_ ? std::clamp(x_m, x_min_m_ + radius_m, x_max_m_ - radius_m) : x_m;
    const double cy = walled_ ? std::clamp(y_m, y_min_m_ + radius_m, y_max_m_ - radius_m) : y_m;
    if (std::abs(cx - x_m) > kSlop_m || std::abs(cy - y_m) > kSlop_m) {
      x_m = cx;
      y_m = cy;
      moved_this_pass = true;
    }
    if (!moved_this_pass) break;
    moved = true;
  }
  return moved;
}

std::optional<Box> SolidGeometry::free_centres(double x_m, double y_m, double radius_m) const {
  if (!inside_bounds(x_m, y_m)) return std::nullopt;
  const int bx = bucket_of_x(x_m);
  const int by = bucket_of_y(y_m);
  const auto empty = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= nx_ || y >= ny_) return true;
    const std::size_t b = bucket_index(x, y);
    return first_[b] == first_[b + 1];
  };
  if (!empty(bx, by)) return std::nullopt;
  bool ring_empty = true;
  for (int y = by - 1; y <= by + 1; ++y) {
    for (int x = bx - 1; x <= bx + 1; ++x) ring_empty = ring_empty && empty(x, y);
  }
  const int reach = ring_empty ? 1 : 0;
  const double m = radius_m + kCoreMargin_m;
  Box box{std::max(x_min_m_, x_min_m_ + (bx - reach) * bucket_m_) + m,
          std::max(y_min_m_, y_min_m_ + (by - reach) * bucket_m_) + m,
          std::min(x_max_m_, x_min_m_ + (bx + 1 + reach) * bucket_m_) - m,
          std::min(y_max_m_, y_min_m_ + (by + 1 + reach) * bucket_m_) - m};
  if (!(box.x_min_m < box.x_max_m && box.y_min_m < box.y_max_m)) return std::nullopt;
  return box;
}

std::vector<Contact> SolidGeometry::contacts(double x_m, double y_m, double reach_m) const {
  std::vector<Contact> out;
  for (const std::uint32_t index : near(x_m - reach_m, y_m - reach_m, x_m + reach_m, y_m + reach_m)) {
    const Solid &k = solids_[index];
    double qx = 0.0;
    double qy = 0.0;
    if (k.disc) {
      const double d = std::hypot(x_m - k.cx, y_m - k.cy);
      qx = d > k.r ? k.cx + (x_m - k.cx) / d * k.r : x_m;
      qy = d > k.r ? k.cy + (y_m - k.cy) / d * k.r : y_m;
    } else if (k.aligned) {
      qx = std::clamp(x_m, k.x0, k.x1);
      qy = std::clamp(y_m, k.y0, k.y1);
    } else {
      const double px = x_m - k.cx;
      const double py = y_m - k.cy;
      const double u = std::clamp(k.c * px + k.s * py, -k.hl, k.hl);
      const double v = std::clamp(-k.s * px + k.c * py, -k.hw, k.hw);
      qx = k.cx + k.c * u - k.s * v;
      qy = k.cy + k.s * u + k.c * v;
    }
    const double d = std::hypot(x_m - qx, y_m - qy);
    if (d <= reach_m) out.push_back({qx, qy, d});
  }
  const auto side = [&](double qx, double qy) {
    const double d = std::hypot(x_m - qx, y_m - qy);
    if (walled_ && d <= reach_m) out.push_back({qx, qy, d});
  };
  const double cx = std::clamp(x_m, x_min_m_, x_max_m_);
  const double cy = std::clamp(y_m, y_min_m_, y_max_m_);
  side(x_min_m_, cy);
  side(x_max_m_, cy);
  side(cx, y_min_m_);
  side(cx, y_max_m_);
  return out;
}

}  // namespace maze::sim
