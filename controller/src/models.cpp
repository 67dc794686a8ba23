#include "mapping/models.hpp"

#include <cassert>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

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
  BeamFreeMarker(const OccupancyGrid &grid, ScanUpdate &update) : grid_(grid), update_(update) {}

  // The next sub-cell the beam enters, before its end.
  void pass(SubCell s) {
    const int k = grid_.k();
    if (has_previous_ && crosses_cell_side(previous_, s, k)) update_.mark_free(grid_.index(previous_));
    if (is_interior(s, k) || (has_previous_ && crosses_cell_side(previous_, s, k))) {
      update_.mark_free(grid_.index(s));
    }
    previous_ = s;
    has_previous_ = true;
  }

  // The beam left the grid after the last sub-cell passed: it crossed that cell's outer side.
  void leave_grid() {
    if (has_previous_) update_.mark_free(grid_.index(previous_));
  }

  // The beam's end sub-cell: the side crossed into it (if any) frees the sub-cell before it.
  void end(SubCell s) {
    if (has_previous_ && crosses_cell_side(previous_, s, grid_.k())) {
      update_.mark_free(grid_.index(previous_));
    }
  }

 private:
  static bool crosses_cell_side(SubCell from, SubCell to, int k) {
    return cell_of(from, k) != cell_of(to, k);
  }
  static bool is_interior(SubCell s, int k) {
    const LocalSubCell l = local_of(s, k);
    return l.i > 0 && l.j > 0 && l.i < k - 1 && l.j < k - 1;
  }

  const OccupancyGrid &grid_;
  ScanUpdate &update_;
  SubCell previous_;
  bool has_previous_ = false;
};

void mark_ray_model(const MappingOptions &options, const OccupancyGrid &grid,
                    const LidarScan &scan, ScanUpdate &update) {
  const GridGeometry &g = grid.geometry();
  for (int i = 0; i < scan.beam_count(); ++i) {
    const ReadingKind kind = scan.kind(i);
    if (kind == ReadingKind::invalid) continue;
    if (kind == ReadingKind::no_return && options.ignore_no_return) continue;
    if (kind == ReadingKind::no_return && scan.lone_no_return(i)) continue;
    const double angle = scan.beam_world_angle_rad(i);
    const double dir_x = std::cos(angle);
    const double dir_y = std::sin(angle);
    BeamFreeMarker free_marker(grid, update);
    if (kind == ReadingKind::no_return) {
      const double length = scan.max_range_m;
      bool within_length = true;
      trace_ray(g, scan.origin, dir_x, dir_y, [&](SubCell s, double exit_m) {
        free_marker.pass(s);
        within_length = exit_m < length;
        return within_length;
      });
      if (within_length) free_marker.leave_grid();  // stopped at the grid's edge, not at max range
      continue;
    }
    const double range = scan.ranges[static_cast<std::size_t>(i)];
    int behind = -1;  // -1 before the hit sub-cell, then the count of occupied sub-cells after it
    trace_ray(g, scan.origin, dir_x, dir_y, [&](SubCell s, double exit_m) {
      if (behind < 0 && exit_m < range) {
        free_marker.pass(s);
        return true;
      }
      if (behind < 0) free_marker.end(s);
      update.mark_occupied(grid.index(s));
      ++behind;
      return behind < options.hit_depth;
    });
  }
}

}  // namespace

std::string_view to_string(ModelKind kind) { return kind == ModelKind::cell ? "cell" : "ray"; }

ModelKind parse_model(std::string_view name) {
  if (name == "cell") return ModelKind::cell;
  if (name == "ray") return ModelKind::ray;
  throw common::InputError(fmt::format("unknown --model '{}' (choose cell or ray)", name));
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
