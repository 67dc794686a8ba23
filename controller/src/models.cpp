#include "mapping/models.hpp"

#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"

namespace mapping {
namespace {

constexpr int kMaxHitDepth = 8;
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
  update.mark_occupied(grid.index(c, band_middle));
  // The band's corners: step from the band middle along the band both ways.
  const bool along_j = di(h) != 0;  // a north/south band runs along j, east/west along i
  for (const int end : {0, k - 1}) {
    const LocalSubCell corner = along_j ? LocalSubCell{band_middle.i, end} : LocalSubCell{end, band_middle.j};
    update.mark_occupied(grid.index(c, corner));
  }
}

void mark_cell_model(const MappingOptions &options, const OccupancyGrid &grid,
                     const LidarScan &scan, Cell c, ScanUpdate &update) {
  assert(grid.contains(c));
  const int mid = grid.k() / 2;
  update.mark_free(grid.index(c, LocalSubCell{mid, mid}));
  const double margin_m = options.wall_margin * grid.geometry().cell_size_m;
  for (const Heading h : kHeadings) {
    const auto beam = scan.beam_towards(yaw_rad(h));
    if (!beam) continue;
    const std::optional<float> median = scan.median_range(*beam, kCellModelHalfWindow_rad);
    if (!median) continue;
    const ReadingKind kind = scan.kind_of(*median);
    const double range = *median;
    const bool wall = kind == ReadingKind::hit &&
                      range < distance_to_side(grid, scan.origin, c, h) + margin_m;
    mark_cell_side(grid, c, h, wall, update);
  }
}

// One sub-cell of trace_flat's traversal.
struct FlatStep {
  std::size_t flat;     // index in the grid's layout
  double exit_m;        // path length at which the ray leaves the sub-cell
  bool crossed_side;    // entered across a cell side (not for the first sub-cell)
  bool interior;        // not in any of its cell's bands
};

// trace_ray's traversal, the same arithmetic step for step (so the same sub-cells and exit
// distances), but carrying the sub-cell's flat index in the grid's layout instead of
// (x, y): a step is an add, never a division. visit(const FlatStep &) returns false to stop.
template <typename Visit>
void trace_flat(const OccupancyGrid &grid, Point from, double dir_x, double dir_y, Visit &&visit) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const GridGeometry &g = grid.geometry();
  const auto start = start_traversal(g, from, dir_x, dir_y);
  if (!start) return;
  const int width = g.width_subcells();
  const int height = g.height_subcells();
  auto [x, y, step_x, step_y, delta_x, delta_y, next_x, next_y] = *start;
  // Flat index and position inside the cell: j from the west, r from the south (i = K-1-r).
  const std::ptrdiff_t k = g.subcells;
  const std::ptrdiff_t row_of_cells = static_cast<std::ptrdiff_t>(g.width_cells) * k * k;
  int j = x % g.subcells;
  int r = y % g.subcells;
  auto flat = static_cast<std::ptrdiff_t>(grid.index(SubCell{x, y}));
  // Steps of the flat index: inside a cell, and across into the next cell.
  const std::ptrdiff_t x_inside = step_x;
  const std::ptrdiff_t x_across = step_x * (k * k - k + 1);
  const std::ptrdiff_t y_inside = -step_y * k;
  const std::ptrdiff_t y_across = step_y * (row_of_cells + (k - 1) * k);
  const int j_edge = step_x > 0 ? g.subcells - 1 : 0;
  const int j_wrap = g.subcells - 1 - j_edge;
  const int r_edge = step_y > 0 ? g.subcells - 1 : 0;
  const int r_wrap = g.subcells - 1 - r_edge;
  const int last = g.subcells - 1;
  bool crossed = false;
  for (;;) {
    const double exit_m = std::min(next_x, next_y);
    const bool interior = j > 0 && j < last && r > 0 && r < last;
    if (!visit(FlatStep{static_cast<std::size_t>(flat), exit_m, crossed, interior}) || exit_m == inf) return;
    crossed = false;
    if (next_x <= next_y) {
      x += step_x;
      next_x += delta_x;
      if (j == j_edge) {
        j = j_wrap;
        flat += x_across;
        crossed = true;
      } else {
        j += step_x;
        flat += x_inside;
      }
    }
    if (next_y <= exit_m) {
      y += step_y;
      next_y += delta_y;
      if (r == r_edge) {
        r = r_wrap;
        flat += y_across;
        crossed = true;
      } else {
        r += step_y;
        flat += y_inside;
      }
    }
    if (x < 0 || y < 0 || x >= width || y >= height) return;
  }
}

// cos and sin of every beam's angle relative to the heading, for one beam count and field
// of view (computed again only when those change, so not per scan).
class BeamTable {
 public:
  void prepare(const LidarScan &scan) {
    if (scan.beam_count() == count_ && scan.fov_rad == fov_rad_) return;
    count_ = scan.beam_count();
    fov_rad_ = scan.fov_rad;
    cos_.resize(static_cast<std::size_t>(count_));
    sin_.resize(static_cast<std::size_t>(count_));
    for (int i = 0; i < count_; ++i) {
      cos_[static_cast<std::size_t>(i)] = std::cos(scan.beam_angle_rad(i));
      sin_[static_cast<std::size_t>(i)] = std::sin(scan.beam_angle_rad(i));
    }
  }
  double cos(int i) const { return cos_[static_cast<std::size_t>(i)]; }
  double sin(int i) const { return sin_[static_cast<std::size_t>(i)]; }

 private:
  int count_ = -1;
  double fov_rad_ = 0.0;
  std::vector<double> cos_, sin_;
};

// Frees the sub-cells a beam passes before it ends, as the ray model sees them (DESIGN §6).
//
// Walls stand on cell sides, and the band of sub-cells beside a side stands for that side.
// A beam tells whether a side is open only by crossing it, so band sub-cells are freed where
// the beam crosses their cell side (the two sub-cells beside the crossing point), and interior
// sub-cells wherever the beam passes. A beam running along a band without crossing its side
// says nothing about that side: freeing the band there would erase walls, since a 12 mm wall
// fills 4 % of a 1/3 m sub-cell and most of a band is air.
class BeamFreeMarker {
 public:
  explicit BeamFreeMarker(ScanUpdate &update) : update_(update) {}

  // The next sub-cell the beam passes, before its end.
  void pass(const FlatStep &s) {
    if (s.crossed_side && has_previous_) update_.mark_free(previous_);
    if (s.interior || s.crossed_side) update_.mark_free(s.flat);
    previous_ = s.flat;
    has_previous_ = true;
  }

  // The beam's end sub-cell: the side crossed into it (if any) frees the sub-cell before it.
  void end(const FlatStep &s) {
    if (s.crossed_side && has_previous_) update_.mark_free(previous_);
  }

  // The beam left the grid after the last sub-cell passed: it crossed that cell's outer side.
  void leave_grid() {
    if (has_previous_) update_.mark_free(previous_);
  }

 private:
  ScanUpdate &update_;
  std::size_t previous_ = 0;
  bool has_previous_ = false;
};

void mark_ray_model(const MappingOptions &options, const OccupancyGrid &grid,
                    const LidarScan &scan, ScanUpdate &update) {
  thread_local BeamTable table;  // per thread: no sharing, no per-scan allocation
  table.prepare(scan);
  // World direction of beam i: the beam's direction rotated by the yaw (two sin/cos per
  // scan instead of two per beam).
  const double cy = std::cos(scan.yaw_rad);
  const double sy = std::sin(scan.yaw_rad);
  for (int i = 0; i < scan.beam_count(); ++i) {
    const ReadingKind kind = scan.kind(i);
    if (kind == ReadingKind::invalid) continue;
    if (kind == ReadingKind::no_return && options.ignore_no_return) continue;
    if (kind == ReadingKind::no_return && scan.lone_no_return(i)) continue;
    const double dir_x = cy * table.cos(i) - sy * table.sin(i);
    const double dir_y = sy * table.cos(i) + cy * table.sin(i);
    BeamFreeMarker free_marker(update);
    if (kind == ReadingKind::no_return) {
      const double length = scan.max_range_m;
      bool within_length = true;
      trace_flat(grid, scan.origin, dir_x, dir_y, [&](const FlatStep &s) {
        free_marker.pass(s);
        within_length = s.exit_m < length;
        return within_length;
      });
      if (within_length) free_marker.leave_grid();  // stopped at the grid's edge, not at max range
      continue;
    }
    const double range = scan.ranges[static_cast<std::size_t>(i)];
    int behind = -1;  // -1 before the hit sub-cell, then the count of occupied sub-cells after it
    trace_flat(grid, scan.origin, dir_x, dir_y, [&](const FlatStep &s) {
      if (behind < 0 && s.exit_m < range) {
        free_marker.pass(s);
        return true;
      }
      if (behind < 0) free_marker.end(s);
      update.mark_occupied(s.flat);
      ++behind;
      return behind < options.hit_depth;
    });
  }
}

}  // namespace

std::string_view to_string(ModelKind kind) {
  switch (kind) {
    case ModelKind::cell: return "cell";
    case ModelKind::ray: return "ray";
    case ModelKind::bump: return "bump";
    case ModelKind::depth: return "depth";
    case ModelKind::pie: return "pie";
    case ModelKind::cone: return "cone";
  }
  return "?";
}

ModelKind parse_model(std::string_view name) {
  for (const ModelKind kind : {ModelKind::cell, ModelKind::ray, ModelKind::bump, ModelKind::depth,
                               ModelKind::pie, ModelKind::cone}) {
    if (name == to_string(kind)) return kind;
  }
  throw common::InputError(fmt::format(
      "unknown --model '{}' (choose cell, ray, bump, depth, pie or cone)", name));
}

void validate(const MappingOptions &options) {
  if (!(options.wall_margin >= 0.0 && options.wall_margin < 0.5)) {
    throw common::InputError(fmt::format(
        "wall margin must be at least 0 and less than 0.5 cells (got {})", options.wall_margin));
  }
  if (options.hit_depth < 0 || options.hit_depth > kMaxHitDepth) {
    throw common::InputError(fmt::format("--hit-depth must be between 0 and {} (got {})",
                                         kMaxHitDepth, options.hit_depth));
  }
}

void mark_scan(const MappingOptions &options, const OccupancyGrid &grid, const LidarScan &scan,
               Cell robot_cell, ScanUpdate &update) {
  assert(uses_lidar(options.kind));
  if (options.kind == ModelKind::cell) {
    mark_cell_model(options, grid, scan, robot_cell, update);
  } else {
    mark_ray_model(options, grid, scan, update);
  }
}

std::size_t integrate_scan(const MappingOptions &options, OccupancyGrid &grid,
                           const LidarScan &scan, Cell robot_cell, const SensorModel &model,
                           ScanUpdate &update) {
  mark_scan(options, grid, scan, robot_cell, update);
  return update.apply(grid, model);
}

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
