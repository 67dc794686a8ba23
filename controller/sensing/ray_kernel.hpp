#pragma once
// The ray model's walk (sensing/ray_model.cpp's only user): trace_ray's arithmetic
// (mapping/traversal.hpp) in the grid's flat layout, two beams at a time, with the
// free/occupied marks written straight into a ScanUpdate. Its results are those of the
// reference walk bit for bit (tests/test_controller_ray_kernel.cpp); only its speed differs.

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "mapping/occupancy_grid.hpp"
#include "mapping/traversal.hpp"
#include "sensing/scan.hpp"

namespace sensing::ray_kernel {

using mapping::kMaxCellsPerSide;
using mapping::kMaxSubcells;
using mapping::OccupancyGrid;
using mapping::SubCell;
using mapping::ScanUpdate;
using mapping::TraversalOrigin;
using mapping::TraversalStart;

// The two axes of a beam's walk: the path lengths to the next sub-cell boundary on x and y
// (trace_ray's next_x, next_y), what one sub-cell adds to them, and the steps left on each
// axis before the grid's edge. step() is trace_ray's rule without a branch: which axis steps
// on a diagonal beam is a coin toss a branch predictor loses. With SSE2 (every x86-64) both
// axes go in one register; the same IEEE additions and comparisons either way.
#if defined(__SSE2__)
class AxisPair {
 public:
  AxisPair(const TraversalStart &t, std::int64_t to_edge_x, std::int64_t to_edge_y)
      : next_(_mm_set_pd(t.next_y, t.next_x)),
        delta_(_mm_set_pd(t.delta_y, t.delta_x)),
        to_edge_(_mm_set_epi64x(to_edge_y, to_edge_x)) {}

  // min(next_x, next_y) as std::min takes it (next_y < next_x ? next_y : next_x): MINSD.
  double exit_m() const { return _mm_cvtsd_f64(_mm_min_sd(_mm_unpackhi_pd(next_, next_), next_)); }
  // exit_m() < length_m, as next_x < length_m || next_y < length_m: the same unless next_x is
  // NaN, which FlatWalk rules out.
  bool exits_before(double length_m) const {
    return _mm_movemask_pd(_mm_cmplt_pd(next_, _mm_set1_pd(length_m))) != 0;
  }

  // x steps when next_x <= next_y; y when next_y <= min(next_x, next_y) taken before x
  // steps, which is next_y <= next_x, NaN included. Returns bit 0 x stepped, bit 1 y.
  // A lane that does not step adds +0.0, which leaves it as it is (next_x and next_y are
  // +0.0 or more, infinity or NaN).
  int step() {
    const __m128d swapped = _mm_castsi128_pd(_mm_shuffle_epi32(_mm_castpd_si128(next_), 0x4E));
    const __m128d moves = _mm_cmple_pd(next_, swapped);
    next_ = _mm_add_pd(next_, _mm_and_pd(moves, delta_));
    to_edge_ = _mm_add_epi64(to_edge_, _mm_castpd_si128(moves));  // -1 where it stepped
    return _mm_movemask_pd(moves);
  }
  bool outside() const { return _mm_movemask_pd(_mm_castsi128_pd(to_edge_)) != 0; }

 private:
  __m128d next_, delta_;
  __m128i to_edge_;
};
#else
class AxisPair {
 public:
  AxisPair(const TraversalStart &t, std::int64_t to_edge_x, std::int64_t to_edge_y)
      : next_x_(t.next_x), next_y_(t.next_y), delta_x_(t.delta_x), delta_y_(t.delta_y),
        to_edge_x_(to_edge_x), to_edge_y_(to_edge_y) {}
  double exit_m() const { return std::min(next_x_, next_y_); }
  bool exits_before(double length_m) const { return exit_m() < length_m; }
  int step() {
    const bool sx = next_x_ <= next_y_;
    const bool sy = next_y_ <= next_x_;
    next_x_ = sx ? next_x_ + delta_x_ : next_x_;
    next_y_ = sy ? next_y_ + delta_y_ : next_y_;
    to_edge_x_ -= sx;
    to_edge_y_ -= sy;
    return static_cast<int>(sx) | (static_cast<int>(sy) << 1);
  }
  bool outside() const { return (to_edge_x_ | to_edge_y_) < 0; }

 private:
  double next_x_, next_y_, delta_x_, delta_y_;
  std::int64_t to_edge_x_, to_edge_y_;
};
#endif

// Where a walk stands in its cell, as one small number, and what each move does to it: a
// table per K instead of arithmetic per step. A place is (to_side_x, to_side_y, entered):
// the steps left on each axis before crossing into the next cell (counted in the beam's
// direction, so the table serves every direction), and whether the sub-cell was entered
// across a cell side. An entry, for a place and the axes that step (bit 0 x, bit 1 y):
//   bits 0-7    the next place
//   bit 8       the sub-cell being left is freed: interior, entered across a side, or left
//               across one (decided once the step out is known)
//   bit 9       it is interior or was entered across a side (freed whichever way it is left)
//   bits 12-15  the kind of move, x kind * 3 + y kind (0 none, 1 inside the cell, 2 across)
template <int K>
struct PlaceTable {
  static constexpr std::size_t kPlaces = 2 * K * K;
  static constexpr std::uint16_t kFree = 1 << 8;
  static constexpr std::uint16_t kFreeAnyway = 1 << 9;
  std::uint16_t entry[kPlaces * 4] = {};

  static constexpr unsigned place(int to_side_x, int to_side_y, bool entered) {
    return static_cast<unsigned>((to_side_x * K + to_side_y) * 2 + (entered ? 1 : 0));
  }

  constexpr PlaceTable() {
    for (int ux = 0; ux < K; ++ux) {
      for (int uy = 0; uy < K; ++uy) {
        for (const bool entered : {false, true}) {
          for (unsigned moves = 0; moves < 4; ++moves) {
            const bool sx = (moves & 1) != 0;
            const bool sy = (moves & 2) != 0;
            const bool across_x = sx && ux == 0;
            const bool across_y = sy && uy == 0;
            const int next_ux = across_x ? K - 1 : ux - (sx ? 1 : 0);
            const int next_uy = across_y ? K - 1 : uy - (sy ? 1 : 0);
            const bool interior = ux > 0 && ux < K - 1 && uy > 0 && uy < K - 1;
            const bool anyway = interior || entered;
            const bool freed = anyway || across_x || across_y;
            const unsigned kind = (sx ? (across_x ? 2u : 1u) : 0u) * 3 + (sy ? (across_y ? 2u : 1u) : 0u);
            const unsigned next = place(next_ux, next_uy, across_x || across_y);
            entry[place(ux, uy, entered) * 4 + moves] = static_cast<std::uint16_t>(
                next | (freed ? kFree : 0u) | (anyway ? kFreeAnyway : 0u) | (kind << 12));
          }
        }
      }
    }
  }
};

template <int K>
inline constexpr PlaceTable<K> kPlaceTable{};

// PlaceTable with the flat-index step of each move folded in, one table per quadrant of beam
// directions (the steps depend on the grid's width). Built again only when the grid's width
// changes. An entry, everything a step needs from one load:
//   bits 0-9    where the next place's row starts (4 * the next place)
//   bit 10      kFree, bit 11 kFreeAnyway (PlaceTable's flags)
//   bits 12-31  the signed flat-index step
template <int K>
class MoveTable {
 public:
  static constexpr int kFlatShift = 12;
  static constexpr std::uint32_t kRowMask = 0x3FF;
  static constexpr std::uint32_t kFree = 1u << 10;  // FlatWalk::mark_left spreads it with << 21 >> 31
  static constexpr std::uint32_t kFreeAnyway = 1u << 11;
  static_assert(4 * PlaceTable<K>::kPlaces <= kRowMask + 1);
  // The longest step, a row of cells and a cell's rows, fits the 20 signed bits.
  static_assert(std::int64_t{kMaxCellsPerSide} * kMaxSubcells * kMaxSubcells + kMaxSubcells * kMaxSubcells <
                (std::int64_t{1} << (31 - kFlatShift)));

  void prepare(int width_cells) {
    if (width_cells == width_cells_) return;
    width_cells_ = width_cells;
    constexpr std::int32_t kk = K;
    const std::int32_t row_of_cells = width_cells * kk * kk;
    for (int quadrant = 0; quadrant < 4; ++quadrant) {
      const std::int32_t step_x = (quadrant & 1) != 0 ? 1 : -1;
      const std::int32_t step_y = (quadrant & 2) != 0 ? 1 : -1;
      // By kind of move: inside a cell x moves 1 and y a row of K; across, into the
      // neighbour cell's first or last column or row.
      const std::int32_t dx[3] = {0, step_x, step_x * (kk * kk - kk + 1)};
      const std::int32_t dy[3] = {0, -step_y * kk, step_y * (row_of_cells + (kk - 1) * kk)};
      for (std::size_t n = 0; n < PlaceTable<K>::kPlaces * 4; ++n) {
        const std::uint16_t e = kPlaceTable<K>.entry[n];
        const unsigned kind = e >> 12u;
        const std::int32_t flat_step = dx[kind / 3] + dy[kind % 3];
        const std::uint32_t row = 4u * (e & 0xFFu);
        const std::uint32_t flags = ((e & PlaceTable<K>::kFree) != 0 ? kFree : 0u) |
                                    ((e & PlaceTable<K>::kFreeAnyway) != 0 ? kFreeAnyway : 0u);
        entries_[static_cast<std::size_t>(quadrant)][n] =
            static_cast<std::int32_t>((static_cast<std::uint32_t>(flat_step) << kFlatShift) | flags | row);
      }
    }
  }
  const std::int32_t *quadrant(int step_x, int step_y) const {
    return entries_[static_cast<std::size_t>((step_x > 0 ? 1 : 0) + (step_y > 0 ? 2 : 0))].data();
  }

 private:
  int width_cells_ = -1;
  std::array<std::array<std::int32_t, PlaceTable<K>::kPlaces * 4>, 4> entries_{};
};

// One beam's Amanatides-Woo walk in the grid's flat layout, for K sub-cells a side: trace_ray's
// arithmetic (the same sub-cells and exit distances), carrying the sub-cell's flat index and
// its place in its cell instead of (x, y).
// What every beam of a scan shares: the sub-cell it starts in.
template <int K>
struct WalkOrigin {
  WalkOrigin(const OccupancyGrid &grid, const TraversalOrigin &o)
      : flat(static_cast<std::uint32_t>(grid.index(SubCell{o.x, o.y}))),
        j(o.x % K),
        r(o.y % K),
        west(o.x),
        south(o.y),
        east(grid.geometry().width_subcells() - 1 - o.x),
        north(grid.geometry().height_subcells() - 1 - o.y) {}
  std::uint32_t flat;
  int j, r;                        // place in the cell: column from the west, row from the south
  int west, south, east, north;    // sub-cells between it and the grid's edges
};

template <int K>
class FlatWalk;
template <int K>
std::uint32_t *free_pair(FlatWalk<K> &a, double length_a_m, FlatWalk<K> &b, double length_b_m,
                         const ScanUpdate::UniqueMarks &marks, std::uint32_t *out);

template <int K>
class FlatWalk {
 public:
  FlatWalk(const WalkOrigin<K> &o, const MoveTable<K> &moves, const TraversalStart &t)
      : axes_(t, to_edge(t.step_x, o.east, o.west), to_edge(t.step_y, o.north, o.south)),
        moves_(moves.quadrant(t.step_x, t.step_y)),
        flat_(o.flat),
        row_(4 * PlaceTable<K>::place(t.step_x > 0 ? K - 1 - o.j : o.j, t.step_y > 0 ? K - 1 - o.r : o.r, false)),
        // next_x is NaN only from 0 * infinity (a direction too small to divide by, starting
        // on a boundary); trace_ray then ends in the first sub-cell.
        stuck_(t.next_x != t.next_x) {}
  // A walk resumed where another left it (sensing/ray_lanes.hpp): t's directions and its
  // current next_x, next_y; the steps left to the grid's edges; the flat index and place.
  FlatWalk(const MoveTable<K> &moves, const TraversalStart &t, std::int64_t to_edge_x, std::int64_t to_edge_y,
           std::uint32_t flat, unsigned place)
      : axes_(t, to_edge_x, to_edge_y), moves_(moves.quadrant(t.step_x, t.step_y)), flat_(flat),
        row_(4 * place), stuck_(false) {}
  // The steps an axis has before the grid's edge: `ahead` or `behind` by its direction.
  static std::int64_t to_edge(int step, int ahead, int behind) {
    constexpr std::int64_t never = std::int64_t{1} << 40;  // an axis the beam does not move along
    return step > 0 ? ahead : (step < 0 ? behind : never);
  }

  // exit_m() < length_m: the beam leaves the current sub-cell before length_m.
  bool exits_before(double length_m) const { return !stuck_ && axes_.exits_before(length_m); }
  // Path length (m) at which the beam leaves the current sub-cell.
  double exit_m() const { return axes_.exit_m(); }
  std::uint32_t flat() const { return flat_; }
  bool outside() const { return axes_.outside(); }

  // Moves to the next sub-cell (which may be outside the grid: then flat() means nothing).
  // Returns MoveTable's entry for the move: whether the sub-cell left is freed (kFree), or
  // would be freed whichever way it was left (kFreeAnyway).
  std::uint32_t step() { return step(axes_, moves_, flat_, row_); }
  // The current sub-cell is interior or was entered across a cell side.
  bool freed_anyway() const { return (kPlaceTable<K>.entry[row_] & PlaceTable<K>::kFreeAnyway) != 0; }

  // Steps while the beam leaves the current sub-cell before length_m, listing each sub-cell
  // it leaves that the step frees (MoveTable::kFree) through `marks` from `out` on; returns
  // where the next mark goes. Stops early when a step leaves the grid: then left_grid() is
  // true and left_here()/left_move() tell the sub-cell left and the step's entry.
  // kMayLeave false: the caller knows the beam ends before it could reach the grid's edge.
  // The loop keeps the walk in local variables, one register each, and is not inlined, so
  // that nothing of the caller competes for registers: every spill would add a store and a
  // load to a loop of some thirty instructions.
  template <bool kMayLeave>
  [[gnu::noinline]] std::uint32_t *free_until(double length_m, const ScanUpdate::UniqueMarks &marks,
                                              std::uint32_t *out);
  // free_until<false> for two beams side by side, a step of each in turn, until either
  // ends. One walk's steps wait on each other (a comparison and a table load on the last
  // step's result); a second, independent walk fills that wait. Marks come in another
  // order than beam by beam, which changes nothing: a sub-cell is listed once a scan.
  friend std::uint32_t *free_pair<K>(FlatWalk &a, double length_a_m, FlatWalk &b, double length_b_m,
                                     const ScanUpdate::UniqueMarks &marks, std::uint32_t *out);
  bool left_grid() const { return left_grid_; }
  std::uint32_t left_here() const { return left_here_; }
  std::uint32_t left_move() const { return left_move_; }

 private:
  // step() on a walk held in locals.
  static std::uint32_t step(AxisPair &axes, const std::int32_t *moves, std::uint32_t &flat, unsigned &row) {
    const auto e = static_cast<std::uint32_t>(moves[row + static_cast<unsigned>(axes.step())]);
    row = e & MoveTable<K>::kRowMask;
    flat += static_cast<std::uint32_t>(static_cast<std::int32_t>(e) >> MoveTable<K>::kFlatShift);  // wraps outside the grid
    return e;
  }
  // A step inside the grid that went on from sub-cell `here` with entry e: lists `here` when
  // the step frees it.
  static std::uint32_t *mark_left(const ScanUpdate::UniqueMarks &marks, std::uint32_t *out, std::uint32_t here,
                                  std::uint32_t e) {
    // kFree (bit 10) spread to a mask: all ones when set.
    return marks.mark_free_if(out, here, static_cast<std::uint32_t>(static_cast<std::int32_t>(e << 21) >> 31));
  }

  AxisPair axes_;
  const std::int32_t *moves_;
  std::uint32_t flat_;
  unsigned row_;  // 4 * the place in the cell (PlaceTable)
  bool stuck_;
  bool left_grid_ = false;
  std::uint32_t left_here_ = 0, left_move_ = 0;
};

template <int K>
[[gnu::noinline]] std::uint32_t *free_pair(FlatWalk<K> &a, double length_a_m, FlatWalk<K> &b, double length_b_m,
                                           const ScanUpdate::UniqueMarks &marks, std::uint32_t *out) {
  if (a.stuck_ || b.stuck_) return out;
  AxisPair axes_a = a.axes_, axes_b = b.axes_;
  const std::int32_t *const moves_a = a.moves_;
  const std::int32_t *const moves_b = b.moves_;
  std::uint32_t flat_a = a.flat_, flat_b = b.flat_;
  unsigned row_a = a.row_, row_b = b.row_;
  const ScanUpdate::UniqueMarks m = marks;
  while (axes_a.exits_before(length_a_m) && axes_b.exits_before(length_b_m)) {
    const std::uint32_t here_a = flat_a;
    out = FlatWalk<K>::mark_left(m, out, here_a, FlatWalk<K>::step(axes_a, moves_a, flat_a, row_a));
    assert(!axes_a.outside());
    const std::uint32_t here_b = flat_b;
    out = FlatWalk<K>::mark_left(m, out, here_b, FlatWalk<K>::step(axes_b, moves_b, flat_b, row_b));
    assert(!axes_b.outside());
  }
  a.axes_ = axes_a;
  a.flat_ = flat_a;
  a.row_ = row_a;
  b.axes_ = axes_b;
  b.flat_ = flat_b;
  b.row_ = row_b;
  return out;
}

template <int K>
template <bool kMayLeave>
std::uint32_t *FlatWalk<K>::free_until(double length_m, const ScanUpdate::UniqueMarks &marks, std::uint32_t *out) {
  if (stuck_) return out;
  AxisPair axes = axes_;
  const std::int32_t *const moves = moves_;
  std::uint32_t flat = flat_;
  unsigned row = row_;
  const ScanUpdate::UniqueMarks m = marks;
  while (axes.exits_before(length_m)) {
    const std::uint32_t here = flat;
    const std::uint32_t e = step(axes, moves, flat, row);
    if (kMayLeave && axes.outside()) {
      left_grid_ = true;
      left_here_ = here;
      left_move_ = e;
      break;
    }
    assert(!axes.outside());
    out = mark_left(m, out, here, e);
  }
  axes_ = axes;
  flat_ = flat;
  row_ = row;
  return out;
}

// cos and sin of every beam's angle relative to the heading, for one beam count and field
// of view and beam offset (computed again only when those change, so not per scan).
class BeamTable {
 public:
  void prepare(const LidarScan &scan) {
    if (scan.beam_count() == count_ && scan.fov_rad == fov_rad_ && scan.beam_offset == offset_) return;
    count_ = scan.beam_count();
    fov_rad_ = scan.fov_rad;
    offset_ = scan.beam_offset;
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
  double offset_ = 0.0;
  std::vector<double> cos_, sin_;
};

// Frees the sub-cells a beam passes before it ends, as the ray model sees them (docs/models.md),
// and leaves `walk` at the end: the first sub-cell the beam does not leave within length_m.
// Returns false when the beam left the grid first.
//
// Walls stand on cell sides, and the band of sub-cells beside a side stands for that side.
// A beam tells whether a side is open only by crossing it, so band sub-cells are freed where
// the beam crosses their cell side (the two sub-cells beside the crossing point), and interior
// sub-cells wherever the beam passes. A beam running along a band without crossing its side
// says nothing about that side: freeing the band there would erase walls, since a 12 mm wall
// fills 4 % of a 1/3 m sub-cell and most of a band is air. A passed sub-cell is decided once
// the step out of it is known: interior, entered across a side, or left across one. Leaving
// the grid crosses its outer side only for a beam with no return (a return beyond the grid's
// edge is not a view of that side).
//
// may_leave false: the caller knows the beam ends before it could reach the grid's edge.
template <int K>
bool free_passed(FlatWalk<K> &walk, double length_m, bool no_return, bool may_leave,
                 const ScanUpdate::UniqueMarks &marks, std::uint32_t *&out) {
  out = may_leave ? walk.template free_until<true>(length_m, marks, out)
                  : walk.template free_until<false>(length_m, marks, out);
  if (walk.left_grid()) {
    out = marks.mark_free(out, walk.left_here(), (walk.left_move() & MoveTable<K>::kFreeAnyway) != 0 || no_return);
    return false;
  }
  if (no_return) out = marks.mark_free(out, walk.flat(), walk.freed_anyway());
  return true;
}

// The end sub-cell of a beam with a return and hit_depth sub-cells behind it, within the grid.
template <int K>
std::uint32_t *occupy_end(FlatWalk<K> &walk, int hit_depth, const ScanUpdate::UniqueMarks &marks,
                          std::uint32_t *out) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  out = marks.mark_occupied(out, walk.flat());
  for (int behind = 0; behind < hit_depth && walk.exit_m() != inf; ++behind) {
    walk.step();
    if (walk.outside()) break;
    out = marks.mark_occupied(out, walk.flat());
  }
  return out;
}

}  // namespace sensing::ray_kernel
