#include "sensing/ray_model.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "mapping/traversal.hpp"
#include "sensing/ray_kernel.hpp"
#include "sensing/ray_lanes.hpp"

namespace sensing {

using namespace mapping;  // the grid types this model marks
namespace {

using namespace ray_kernel;

// Room for a scan's free marks: a beam lists at most one sub-cell per step and steps at
// most width + height times in the grid, and a scan lists each sub-cell at most once; plus
// the slots a mark writes before it knows whether it keeps it (list_stamped writes eight).
std::size_t free_room(const OccupancyGrid &grid, const LidarScan &scan) {
  const GridGeometry &g = grid.geometry();
  const std::size_t per_beam = static_cast<std::size_t>(g.width_subcells()) +
                               static_cast<std::size_t>(g.height_subcells()) + 2;
  return std::min(grid.size(), static_cast<std::size_t>(scan.beam_count()) * per_beam) + 1 +
         ScanUpdate::UniqueMarks::kStampSlack;
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

// Lists the sub-cells the lanes stamped: all within reach_m of the origin (the cells around
// them, a row of cells at a time: a contiguous run of flat indices).
std::uint32_t *list_stamped_near(const GridGeometry &g, const TraversalOrigin &o, double reach_m,
                                 const ScanUpdate::UniqueMarks &marks, std::uint32_t *out) {
  const double reach = reach_m / g.subcell_size_m() + 1.0;  // sub-cells, and one for rounding
  const auto cell_of_axis = [&](double p, int subcells) {
    return static_cast<int>(std::clamp(p, 0.0, subcells - 1.0)) / g.subcells;
  };
  const auto kk = static_cast<std::uint32_t>(g.subcells * g.subcells);
  const int y1 = cell_of_axis(o.py + reach, g.height_subcells());
  for (int y = cell_of_axis(o.py - reach, g.height_subcells()); y <= y1; ++y) {
    // The row's sub-cells nearest the origin are dy from it; the circle is 2 half_x wide there.
    const double dy = std::max({0.0, y * g.subcells - o.py, o.py - (y + 1) * g.subcells});
    const double half_x = std::sqrt(std::max(0.0, reach * reach - dy * dy));
    const int x0 = cell_of_axis(o.px - half_x, g.width_subcells());
    const int x1 = cell_of_axis(o.px + half_x, g.width_subcells());
    const auto row = static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(g.width_cells);
    out = marks.list_stamped(out, (row + static_cast<std::uint32_t>(x0)) * kk,
                             (row + static_cast<std::uint32_t>(x1) + 1) * kk);
  }
  return out;
}

// One beam as the walk needs it.
struct Beam {
  TraversalStart start;
  double length_m;
  bool no_return;
};

// What every beam of one scan shares, for K sub-cells a side (a constant, so the walk's
// arithmetic on places in a cell folds): where the beams start, the marks and where the next
// ones go. Its functions are inlined into each build of the kernel (mark_rays_on).
template <int K>
struct ScanWalk {
  ScanWalk(const ModelOptions &o, const OccupancyGrid &grid, const LidarScan &scan, const TraversalOrigin &from,
           MoveTable<K> &m, ScanUpdate &update)
      : options(o), g(grid.geometry()), origin(from), moves(m), start(grid, from), marks(update.unique_marks(grid)),
        free_out(marks.reserve_free(free_room(grid, scan))),
        occupied_out(marks.reserve_occupied(occupied_room(grid, scan, o.hit_depth))),
        cy(std::cos(scan.yaw_rad)), sy(std::sin(scan.yaw_rad)), inside_m(edge_free_reach_m(g, from)) {}

  // Beam i of the scan, or nothing for a beam that marks nothing. The world direction is the
  // beam's rotated by the yaw (two sin/cos per scan instead of two per beam).
  [[gnu::always_inline]] std::optional<Beam> beam(const LidarScan &scan, const BeamTable &table, int i) const {
    const ReadingKind kind = scan.kind(i);
    if (kind == ReadingKind::invalid) return std::nullopt;
    const bool no_return = kind == ReadingKind::no_return;
    if (no_return && (options.ignore_no_return || scan.lone_no_return(i))) return std::nullopt;
    const double dir_x = cy * table.cos(i) - sy * table.sin(i);
    const double dir_y = sy * table.cos(i) + cy * table.sin(i);
    return Beam{start_traversal(g, origin, dir_x, dir_y),
                no_return ? scan.max_range_m : scan.ranges[static_cast<std::size_t>(i)], no_return};
  }
  // A walk that stopped inside the grid: its end.
  [[gnu::always_inline]] void mark_end(FlatWalk<K> &walk, bool no_return) {
    if (no_return) {
      free_out = marks.mark_free(free_out, walk.flat(), walk.freed_anyway());
    } else {
      occupied_out = occupy_end(walk, options.hit_depth, marks, occupied_out);
    }
  }
  // The whole walk of a beam, alone; may_leave false: it cannot reach the grid's edge.
  [[gnu::always_inline]] void walk_alone(FlatWalk<K> &walk, double length_m, bool no_return, bool may_leave) {
    if (free_passed(walk, length_m, no_return, may_leave, marks, free_out)) mark_end(walk, no_return);
  }
  void commit() {
    marks.commit_free(free_out);
    marks.commit_occupied(occupied_out);
  }

  const ModelOptions &options;
  const GridGeometry &g;
  TraversalOrigin origin;
  const MoveTable<K> &moves;
  WalkOrigin<K> start;
  ScanUpdate::UniqueMarks marks;
  std::uint32_t *free_out;
  std::uint32_t *occupied_out;
  double cy, sy;
  double inside_m;  // a beam shorter than this cannot reach the grid's edge
};

// The baseline (SSE2) build: a beam that cannot reach the grid's edge waits for the next such
// beam, to walk beside it (free_pair); a beam that may reach the edge walks alone.
template <int K>
void mark_rays_paired(ScanWalk<K> &w, const LidarScan &scan, const BeamTable &table) {
  struct Lane {
    FlatWalk<K> walk;
    double length_m;
    bool no_return;
  };
  std::optional<Lane> waiting;
  for (int i = 0; i < scan.beam_count(); ++i) {
    const std::optional<Beam> beam = w.beam(scan, table, i);
    if (!beam) continue;
    Lane lane{FlatWalk<K>(w.start, w.moves, beam->start), beam->length_m, beam->no_return};
    if (!(lane.length_m < w.inside_m)) {
      w.walk_alone(lane.walk, lane.length_m, lane.no_return, true);
      continue;
    }
    if (!waiting) {
      waiting.emplace(lane);
      continue;
    }
    w.free_out = free_pair<K>(waiting->walk, waiting->length_m, lane.walk, lane.length_m, w.marks, w.free_out);
    // Whichever ended is marked; one still under way waits for the next beam.
    const bool waiting_ended = !waiting->walk.exits_before(waiting->length_m);
    const bool lane_ended = !lane.walk.exits_before(lane.length_m);
    if (waiting_ended) w.mark_end(waiting->walk, waiting->no_return);
    if (lane_ended) w.mark_end(lane.walk, lane.no_return);
    if (waiting_ended) {
      waiting.reset();
      if (!lane_ended) waiting.emplace(lane);
    }
  }
  if (waiting) w.walk_alone(waiting->walk, waiting->length_m, waiting->no_return, false);
}

#if defined(__x86_64__) || defined(__i386__)
// The walks of `inner`, four at a time (walk_lanes), a quarter of the scan apart: beams side
// by side would cross the same sub-cells in the same round, each stamp waiting on the one
// before, and beams a quarter turn apart take as many steps (|cos| + |sin|). Where each
// ended goes to `ends`.
template <int K, bool kPlain>
[[gnu::target("avx2")]] void walk_in_lanes(ScanWalk<K> &w, const std::vector<Beam> &inner,
                                           std::vector<std::pair<FlatWalk<K>, bool>> &ends) {
  const std::size_t quarter = (inner.size() + 3) / 4;
  Lanes lanes{};
  for (std::size_t j = 0; j < quarter; ++j) {
    for (int l = 0; l < 4; ++l) {
      const std::size_t b = j + static_cast<std::size_t>(l) * quarter;
      if (b < inner.size()) {
        lane_start(lanes, l, w.start, w.g.width_cells, inner[b].start, inner[b].length_m, inner[b].no_return);
      } else {
        lane_idle(lanes, l);
      }
    }
    walk_lanes<K, kPlain>(lanes, w.marks);
    for (int l = 0; l < 4; ++l) {
      if (j + static_cast<std::size_t>(l) * quarter < inner.size()) ends.emplace_back(lane_walk(lanes, l, w.moves), lanes.no_return[l]);
    }
  }
}

// The AVX2 build: beams that cannot reach the grid's edge walk in lanes (walk_in_lanes), the
// others alone.
template <int K>
[[gnu::target("avx2")]] void mark_rays_lanes(ScanWalk<K> &w, const LidarScan &scan, const BeamTable &table) {
  thread_local std::vector<Beam> inner, alone;
  thread_local std::vector<std::pair<FlatWalk<K>, bool>> ends;
  inner.clear();
  alone.clear();
  ends.clear();
  double reach_m = 0.0;  // the longest of the beams in lanes
  for (int i = 0; i < scan.beam_count(); ++i) {
    const std::optional<Beam> beam = w.beam(scan, table, i);
    if (!beam) continue;
    // In lanes unless it may reach the edge, ends where it starts, or next_x is NaN (FlatWalk).
    if (beam->length_m < w.inside_m && FlatWalk<K>(w.start, w.moves, beam->start).exits_before(beam->length_m)) {
      inner.push_back(*beam);
      reach_m = std::max(reach_m, beam->length_m);
    } else {
      alone.push_back(*beam);
    }
  }
  // Nothing of this scan tagged yet: the lanes' stamps are plain stores until listed, and
  // every other mark waits until then.
  if (w.marks.first_of_scan()) {
    walk_in_lanes<K, true>(w, inner, ends);
  } else {
    walk_in_lanes<K, false>(w, inner, ends);
  }
  w.free_out = list_stamped_near(w.g, w.origin, reach_m, w.marks, w.free_out);
  for (auto &[walk, no_return] : ends) w.mark_end(walk, no_return);
  for (const Beam &beam : alone) {
    FlatWalk<K> walk(w.start, w.moves, beam.start);
    if (beam.length_m < w.inside_m) {
      w.mark_end(walk, beam.no_return);
    } else {
      w.walk_alone(walk, beam.length_m, beam.no_return, true);
    }
  }
}
#endif

template <int K>
void mark_rays_on(RayKernelIsa isa, const ModelOptions &options, const OccupancyGrid &grid, const LidarScan &scan,
                  const BeamTable &table, ScanUpdate &update) {
  const auto origin = traversal_origin(grid.geometry(), scan.origin);
  if (!origin) return;  // every beam starts outside the grid
  thread_local MoveTable<K> moves;
  moves.prepare(grid.width());
  ScanWalk<K> walk(options, grid, scan, *origin, moves, update);
#if defined(__x86_64__) || defined(__i386__)
  if (isa == RayKernelIsa::avx2) {
    mark_rays_lanes<K>(walk, scan, table);
    return walk.commit();
  }
#endif
  (void)isa;
  mark_rays_paired<K>(walk, scan, table);
  walk.commit();
}

}  // namespace

RayKernelIsa ray_kernel_isa() {
#if defined(__x86_64__) || defined(__i386__)
  static const RayKernelIsa isa = __builtin_cpu_supports("avx2") ? RayKernelIsa::avx2 : RayKernelIsa::baseline;
  return isa;
#else
  return RayKernelIsa::baseline;
#endif
}

void mark_ray_model(const ModelOptions &options, const OccupancyGrid &grid, const LidarScan &scan,
                    Cell robot_cell, ScanUpdate &update) {
  mark_ray_model(options, grid, scan, robot_cell, update, ray_kernel_isa());
}

void mark_ray_model(const ModelOptions &options, const OccupancyGrid &grid, const LidarScan &scan,
                    Cell /*robot_cell*/, ScanUpdate &update, RayKernelIsa isa) {
  thread_local BeamTable table;  // per thread: no sharing, no per-scan allocation
  table.prepare(scan);
  switch (grid.k()) {
    case 3: return mark_rays_on<3>(isa, options, grid, scan, table, update);
    case 5: return mark_rays_on<5>(isa, options, grid, scan, table, update);
    case 7: return mark_rays_on<7>(isa, options, grid, scan, table, update);
    case 9: return mark_rays_on<9>(isa, options, grid, scan, table, update);
    default: assert(false && "K is odd, 3 ... 9 (validate(GridGeometry))");
  }
}

}  // namespace sensing
