#include "sensing/ray_model.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "mapping/traversal.hpp"
#include "sensing/ray_kernel.hpp"

namespace sensing {

using namespace mapping;  // the grid types this model marks
namespace {

using namespace ray_kernel;

// Room for a scan's free marks: a beam lists at most one sub-cell per step and steps at
// most width + height times in the grid, and a scan lists each sub-cell at most once; plus
// the slot a mark writes before it knows whether it keeps it.
std::size_t free_room(const OccupancyGrid &grid, const LidarScan &scan) {
  const GridGeometry &g = grid.geometry();
  const std::size_t per_beam = static_cast<std::size_t>(g.width_subcells()) +
                               static_cast<std::size_t>(g.height_subcells()) + 2;
  return std::min(grid.size(), static_cast<std::size_t>(scan.beam_count()) * per_beam) + 1;
}

// Room for its occupied marks: the hit and hit_depth behind it a beam.
std::size_t occupied_room(const OccupancyGrid &grid, const LidarScan &scan, int hit_depth) {
  return std::min(grid.size(), static_cast<std::size_t>(scan.beam_count()) * (static_cast<std::size_t>(hit_depth) + 1)) +
         1;
}

// A beam shorter than this cannot reach the grid's edge (the nearest edge, less two
// sub-cells for rounding), so its walk needs no check for leaving the grid.
double edge_free_reach_m(const GridGeometry &g, const TraversalOrigin &o) {
  return g.subcell_size_m() * (std::min({o.px, o.py, g.width_subcells() - o.px, g.height_subcells() - o.py}) - 2.0);
}

// The ray model for K sub-cells a side (a constant, so the walk's arithmetic on places in a
// cell folds).
template <int K>
void mark_rays(const ModelOptions &options, const OccupancyGrid &grid, const LidarScan &scan,
               const BeamTable &table, ScanUpdate &update) {
  const GridGeometry &g = grid.geometry();
  const auto origin = traversal_origin(g, scan.origin);
  if (!origin) return;  // every beam starts outside the grid
  thread_local MoveTable<K> moves;
  moves.prepare(g.width_cells);
  const WalkOrigin<K> start(grid, *origin);
  ScanUpdate::UniqueMarks marks = update.unique_marks(grid);
  std::uint32_t *free_out = marks.reserve_free(free_room(grid, scan));
  std::uint32_t *occupied_out = marks.reserve_occupied(occupied_room(grid, scan, options.hit_depth));
  // World direction of beam i: the beam's direction rotated by the yaw (two sin/cos per
  // scan instead of two per beam).
  const double cy = std::cos(scan.yaw_rad);
  const double sy = std::sin(scan.yaw_rad);
  const double inside_m = edge_free_reach_m(g, *origin);
  struct Lane {
    FlatWalk<K> walk;
    double length_m;
    bool no_return;
  };
  // A walk that stopped inside the grid: its end.
  const auto mark_end = [&](Lane &lane) {
    if (lane.no_return) {
      free_out = marks.mark_free(free_out, lane.walk.flat(), lane.walk.freed_anyway());
    } else {
      occupied_out = occupy_end(lane.walk, options.hit_depth, marks, occupied_out);
    }
  };
  // A beam that cannot reach the grid's edge waits here for the next such beam, to walk
  // beside it (free_pair); a beam that may reach the edge walks alone.
  std::optional<Lane> waiting;
  for (int i = 0; i < scan.beam_count(); ++i) {
    const ReadingKind kind = scan.kind(i);
    if (kind == ReadingKind::invalid) continue;
    const bool no_return = kind == ReadingKind::no_return;
    if (no_return && (options.ignore_no_return || scan.lone_no_return(i))) continue;
    const double dir_x = cy * table.cos(i) - sy * table.sin(i);
    const double dir_y = sy * table.cos(i) + cy * table.sin(i);
    Lane lane{FlatWalk<K>(start, moves, start_traversal(g, *origin, dir_x, dir_y)),
              no_return ? scan.max_range_m : scan.ranges[static_cast<std::size_t>(i)], no_return};
    if (!(lane.length_m < inside_m)) {
      if (free_passed(lane.walk, lane.length_m, no_return, true, marks, free_out)) mark_end(lane);
      continue;
    }
    if (!waiting) {
      waiting.emplace(lane);
      continue;
    }
    free_out = free_pair<K>(waiting->walk, waiting->length_m, lane.walk, lane.length_m, marks, free_out);
    // Whichever ended is marked; one still under way waits for the next beam.
    const bool waiting_ended = !waiting->walk.exits_before(waiting->length_m);
    const bool lane_ended = !lane.walk.exits_before(lane.length_m);
    if (waiting_ended) mark_end(*waiting);
    if (lane_ended) mark_end(lane);
    if (waiting_ended) {
      waiting.reset();
      if (!lane_ended) waiting.emplace(lane);
    }
  }
  if (waiting && free_passed(waiting->walk, waiting->length_m, waiting->no_return, false, marks, free_out)) {
    mark_end(*waiting);
  }
  marks.commit_free(free_out);
  marks.commit_occupied(occupied_out);
}

}  // namespace

void mark_ray_model(const ModelOptions &options, const OccupancyGrid &grid, const LidarScan &scan,
                    Cell /*robot_cell*/, ScanUpdate &update) {
  thread_local BeamTable table;  // per thread: no sharing, no per-scan allocation
  table.prepare(scan);
  switch (grid.k()) {
    case 3: return mark_rays<3>(options, grid, scan, table, update);
    case 5: return mark_rays<5>(options, grid, scan, table, update);
    case 7: return mark_rays<7>(options, grid, scan, table, update);
    case 9: return mark_rays<9>(options, grid, scan, table, update);
    default: assert(false && "K is odd, 3 ... 9 (validate(GridGeometry))");
  }
}

}  // namespace sensing
