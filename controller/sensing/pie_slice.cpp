// The IR pie-slice update on a square grid (sensing/pie_slice.hpp).

#include "sensing/pie_slice.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "common/angles.hpp"
#include "common/error.hpp"
#include "mapping/log_odds.hpp"

namespace sensing {
namespace {

constexpr double kMaxCellsPerSide = 2000.0;
constexpr double kMaxPoseCells = 1e6;  // the pose's distance from 0,0, in cells
// A point this close to the sensor is at it (a cell corner i * r computed a rounding error
// from the robot's x).
constexpr double kAtSensor_m = 1e-9;

void require_finite(double value, const char *what) {
  common::require_input(std::isfinite(value), fmt::format("{} must be a finite number (got {})", what, value));
}

using Part = PieVerdict;

// Where point (px, py) lies with respect to one sensor's slices.
Part part_of(const PieSlice &s, double beta_rad, double px, double py) {
  const double ex = px - s.x_m;
  const double ey = py - s.y_m;
  const double distance = std::hypot(ex, ey);
  const double reach = s.contact ? s.contact_m : s.clear_m;
  if (distance > reach) return Part::outside;
  if (distance > kAtSensor_m &&
      std::abs(common::wrap_angle_rad(std::atan2(ey, ex) - s.heading_deg * common::kRadPerDeg)) > beta_rad) {
    return Part::outside;
  }
  return distance <= s.clear_m ? Part::clear : Part::contact;
}

}  // namespace

PieVerdict pie_slice_verdict(const PieSlice &s, double beta_rad, double x0, double y0, double r) {
  const double points[5][2] = {{x0, y0}, {x0 + r, y0}, {x0, y0 + r}, {x0 + r, y0 + r}, {x0 + r / 2, y0 + r / 2}};
  bool clear = false;
  for (const auto &p : points) {
    const Part part = part_of(s, beta_rad, p[0], p[1]);
    if (part == Part::contact) return Part::contact;
    clear = clear || part == Part::clear;
  }
  return clear ? Part::clear : Part::outside;
}

namespace {

// The verdict of one sensor on the cell [i r, (i+1) r] x [j r, (j+1) r].
Part verdict(const PieSlice &s, double beta_rad, double r, int i, int j) {
  return pie_slice_verdict(s, beta_rad, i * r, j * r, r);
}

}  // namespace

void validate(const PieSliceOptions &o) {
  for (const auto &[value, what] : {std::pair{o.x_m, "the robot's x"}, std::pair{o.y_m, "the robot's y"},
                                    std::pair{o.heading_deg, "the robot's heading"},
                                    std::pair{o.half_angle_deg, "--beta"}, std::pair{o.contact_m, "--alpha"},
                                    std::pair{o.resolution_m, "--resolution"},
                                    std::pair{o.max_range_m, "--max-range"}}) {
    require_finite(value, what);
  }
  common::require_input(!o.readings_m.empty(), "--readings needs at least one reading");
  common::require_input(
      o.readings_m.size() == o.mounts_deg.size(),
      fmt::format("--readings has {} values but --mounts has {}", o.readings_m.size(), o.mounts_deg.size()));
  for (std::size_t n = 0; n < o.readings_m.size(); ++n) {
    common::require_input(
        std::isfinite(o.readings_m[n]) && o.readings_m[n] >= 0.0,
        fmt::format("--readings item {} must be a finite number >= 0 m (got {})", n + 1, o.readings_m[n]));
    common::require_input(std::isfinite(o.mounts_deg[n]),
                          fmt::format("--mounts item {} must be a finite number (got {})", n + 1, o.mounts_deg[n]));
  }
  common::require_input(o.half_angle_deg > 0.0 && o.half_angle_deg < 90.0,
                        fmt::format("--beta must be in (0, 90) deg (got {})", o.half_angle_deg));
  common::require_input(o.contact_m > 0.0, fmt::format("--alpha must be > 0 m (got {})", o.contact_m));
  common::require_input(o.resolution_m > 0.0, fmt::format("--resolution must be > 0 m (got {})", o.resolution_m));
  common::require_input(o.max_range_m > 0.0, fmt::format("--max-range must be > 0 m (got {})", o.max_range_m));
  const double reach = std::min(*std::max_element(o.readings_m.begin(), o.readings_m.end()), o.max_range_m) + o.contact_m;
  // Far from the origin a cell index loses its precision (at 1e308 m every slice would miss
  // every cell, and no cell would be updated).
  common::require_input(
      std::abs(o.x_m) / o.resolution_m <= kMaxPoseCells && std::abs(o.y_m) / o.resolution_m <= kMaxPoseCells,
      fmt::format("--pose X and Y must lie within {:g} cells of --resolution of 0,0 (got {:g}, {:g})", kMaxPoseCells,
                  o.x_m, o.y_m));
  common::require_input(
      2.0 * reach / o.resolution_m <= kMaxCellsPerSide,
      fmt::format("the slices would span more than {} cells a side: raise --resolution", kMaxCellsPerSide));
}

std::vector<PieSlice> pie_slices(const PieSliceOptions &o) {
  std::vector<PieSlice> slices;
  for (std::size_t n = 0; n < o.readings_m.size(); ++n) {
    PieSlice s;
    s.x_m = o.x_m;
    s.y_m = o.y_m;
    s.heading_deg = std::fmod(std::fmod(o.heading_deg + o.mounts_deg[n], 360.0) + 360.0, 360.0);
    s.reading_m = o.readings_m[n];
    s.contact = s.reading_m < o.max_range_m;
    s.clear_m = std::min(s.reading_m, o.max_range_m);
    s.contact_m = s.contact ? s.clear_m + o.contact_m : s.clear_m;
    slices.push_back(s);
  }
  return slices;
}

std::vector<PieSliceCell> pie_slice_update(const PieSliceOptions &o) {
  const double r = o.resolution_m;
  const double beta = o.half_angle_deg * common::kRadPerDeg;
  const double occupied = mapping::log_odds(kPieSliceOccupiedP);
  const double clear = mapping::log_odds(kPieSliceClearP);
  std::map<std::pair<int, int>, PieSliceCell> cells;  // keyed (-j, i): north row first
  for (const PieSlice &s : pie_slices(o)) {
    const double reach = s.contact_m;
    const int i0 = static_cast<int>(std::floor((s.x_m - reach) / r)) - 1;
    const int i1 = static_cast<int>(std::floor((s.x_m + reach) / r)) + 1;
    const int j0 = static_cast<int>(std::floor((s.y_m - reach) / r)) - 1;
    const int j1 = static_cast<int>(std::floor((s.y_m + reach) / r)) + 1;
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const Part part = verdict(s, beta, r, i, j);
        if (part == Part::outside) continue;
        PieSliceCell &c = cells[{-j, i}];
        c.i = i;
        c.j = j;
        c.log_odds += part == Part::contact ? occupied : clear;
        ++(part == Part::contact ? c.occupied : c.clear);
      }
    }
  }
  std::vector<PieSliceCell> out;
  for (const auto &[key, c] : cells) out.push_back(c);
  return out;
}

}  // namespace sensing
