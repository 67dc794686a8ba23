#pragma once
// Four beams' walks side by side, one beam a lane (sensing/ray_model.cpp's only user): the
// arithmetic of FlatWalk (sensing/ray_kernel.hpp), so trace_ray's, in GCC vector types of
// four lanes. Written once: a function built for AVX2 turns each operation into one
// instruction, the SSE2 baseline into two; the same IEEE additions and comparisons on both,
// so the same marks (tests/test_controller_ray_kernel.cpp runs both paths).
//
// A lane holds what MoveTable's entry holds for a FlatWalk, as numbers instead of a table
// row: the steps left on each axis before the next cell side (to_side, counted in the beam's
// direction), whether the sub-cell was entered across a side, and the flat-index steps of
// its quadrant. No table load waits on the step before; only the marks (ScanUpdate's tags)
// go lane by lane.

#if defined(__x86_64__) || defined(__i386__)

#include <cstdint>
#include <cstring>

#include <immintrin.h>

#include "mapping/occupancy_grid.hpp"
#include "sensing/ray_kernel.hpp"

namespace sensing::ray_kernel {

typedef double F64x4 __attribute__((vector_size(32)));
typedef std::int64_t I64x4 __attribute__((vector_size(32)));
typedef std::uint64_t U64x4 __attribute__((vector_size(32)));
// Places (to_side, entered) in 32-bit halves, each lane's value in both halves of its 64
// bits: 32-bit comparisons (SSE2 has no 64-bit ones) then give a lane's mask in all 64.
typedef std::int32_t I32x8 __attribute__((vector_size(32)));

struct Lanes {
  F64x4 next_x, next_y, delta_x, delta_y, length_m;
  I32x8 to_side_x, to_side_y, entered;
  U64x4 flat;
  I64x4 to_edge_x, to_edge_y;  // as AxisPair's: -1 once the walk left the grid
  U64x4 flat_x, flat_y;        // a step inside the cell along x, along y
  U64x4 cross_x, cross_y;      // what a step across a cell side adds to that
  int step_x[4], step_y[4];
  bool no_return[4];
};

// Starts lane l with the walk of a beam from `o` as start_traversal set it up.
template <int K>
[[gnu::always_inline]] inline void lane_start(Lanes &v, int l, const WalkOrigin<K> &o, int width_cells,
                                              const TraversalStart &t, double length_m, bool no_return) {
  constexpr std::int64_t kk = K;
  const std::int64_t row_of_cells = std::int64_t{width_cells} * kk * kk;
  const int ux = t.step_x > 0 ? K - 1 - o.j : o.j;
  const int uy = t.step_y > 0 ? K - 1 - o.r : o.r;
  v.next_x[l] = t.next_x;
  v.next_y[l] = t.next_y;
  v.delta_x[l] = t.delta_x;
  v.delta_y[l] = t.delta_y;
  v.length_m[l] = length_m;
  v.to_side_x[2 * l] = v.to_side_x[2 * l + 1] = ux;
  v.to_side_y[2 * l] = v.to_side_y[2 * l + 1] = uy;
  v.entered[2 * l] = v.entered[2 * l + 1] = 0;
  v.flat[l] = o.flat;
  v.to_edge_x[l] = FlatWalk<K>::to_edge(t.step_x, o.east, o.west);
  v.to_edge_y[l] = FlatWalk<K>::to_edge(t.step_y, o.north, o.south);
  // MoveTable::prepare's steps: x moves 1, y a row of K; across a side, into the neighbour
  // cell's first or last column or row.
  v.flat_x[l] = static_cast<std::uint64_t>(std::int64_t{t.step_x});
  v.cross_x[l] = static_cast<std::uint64_t>(t.step_x * (kk * kk - kk + 1) - t.step_x);
  v.flat_y[l] = static_cast<std::uint64_t>(-t.step_y * kk);
  v.cross_y[l] = static_cast<std::uint64_t>(t.step_y * (row_of_cells + (kk - 1) * kk) + t.step_y * kk);
  v.step_x[l] = t.step_x;
  v.step_y[l] = t.step_y;
  v.no_return[l] = no_return;
}

// Lane l without a beam: it has ended before it starts.
inline void lane_idle(Lanes &v, int l) {
  v.next_x[l] = v.next_y[l] = 1.0;
  v.delta_x[l] = v.delta_y[l] = 0.0;
  v.length_m[l] = 0.0;
  v.flat[l] = 0;
}

// Lane l's walk as a FlatWalk, to go on alone from where the lane stands.
template <int K>
[[gnu::always_inline]] inline FlatWalk<K> lane_walk(const Lanes &v, int l, const MoveTable<K> &moves) {
  TraversalStart t{};
  t.step_x = v.step_x[l];
  t.step_y = v.step_y[l];
  t.delta_x = v.delta_x[l];
  t.delta_y = v.delta_y[l];
  t.next_x = v.next_x[l];
  t.next_y = v.next_y[l];
  const unsigned place = PlaceTable<K>::place(v.to_side_x[2 * l], v.to_side_y[2 * l], v.entered[2 * l] != 0);
  return FlatWalk<K>(moves, t, v.to_edge_x[l], v.to_edge_y[l], static_cast<std::uint32_t>(v.flat[l]), place);
}

// FlatWalk::free_until<false> for the four lanes at once, a step of each a round, until
// every lane has ended (its beam leaves no more sub-cells before its length); a lane that
// ended stands still. No lane may reach the grid's edge before its end. Marks by stamp
// (ScanUpdate::UniqueMarks::stamp_free_if): the caller lists them.
// kPlain: UniqueMarks::stamp, a plain store, where the caller knows nothing else is tagged.
template <int K, bool kPlain>
[[gnu::target("avx2"), gnu::always_inline]] inline void walk_lanes(Lanes &v, const ScanUpdate::UniqueMarks &marks) {
  F64x4 nx = v.next_x, ny = v.next_y;
  const F64x4 dx = v.delta_x, dy = v.delta_y, len = v.length_m;
  I32x8 ux = v.to_side_x, uy = v.to_side_y, entered = v.entered;
  U64x4 flat = v.flat;
  I64x4 ex = v.to_edge_x, ey = v.to_edge_y;
  const U64x4 fx = v.flat_x, fy = v.flat_y, cx = v.cross_x, cy = v.cross_y;
  const I32x8 zero = {}, last = zero + (K - 1), k = zero + K;
  const ScanUpdate::UniqueMarks m = marks;
  const U64x4 spare = U64x4{} + std::uint64_t{marks.spare()};
  I64x4 go = (nx < len) | (ny < len);
  while (_mm256_movemask_pd(__builtin_bit_cast(__m256d, go)) != 0) {
    // trace_ray's rule as AxisPair::step has it: x steps when next_x <= next_y, y when
    // next_y <= next_x; a lane that does not step adds +0.0.
    const I64x4 sx = (nx <= ny) & go, sy = (ny <= nx) & go;
    nx += __builtin_bit_cast(F64x4, __builtin_bit_cast(I64x4, dx) & sx);
    ny += __builtin_bit_cast(F64x4, __builtin_bit_cast(I64x4, dy) & sy);
    const I32x8 sx32 = __builtin_bit_cast(I32x8, sx), sy32 = __builtin_bit_cast(I32x8, sy);
    const I32x8 go32 = __builtin_bit_cast(I32x8, go);
    const I32x8 at_x = ux == zero, at_y = uy == zero;
    const I32x8 band = at_x | at_y | (ux == last) | (uy == last);
    const I32x8 across_x = sx32 & at_x, across_y = sy32 & at_y;
    // PlaceTable's kFree: interior, entered across a side, or left across one.
    const I32x8 freed = (~band | entered | across_x | across_y) & go32;
    ux += sx32 + (across_x & k);  // -1, or K - 1 from 0 across the side
    uy += sy32 + (across_y & k);
    entered = (entered & ~go32) | across_x | across_y;
    const U64x4 here = flat;
    flat += (__builtin_bit_cast(U64x4, sx) & fx) + (__builtin_bit_cast(U64x4, across_x) & cx) +
            (__builtin_bit_cast(U64x4, sy) & fy) + (__builtin_bit_cast(U64x4, across_y) & cy);
    ex += sx;
    ey += sy;
    // Through memory: four loads take the load ports, where four extractions would compete
    // with the walk for the vector ones.
    alignas(32) std::uint32_t at[8], wanted[8];
    if constexpr (kPlain) {
      const U64x4 to = (here & __builtin_bit_cast(U64x4, freed)) | (spare & ~__builtin_bit_cast(U64x4, freed));
      std::memcpy(at, &to, sizeof at);
      for (int l = 0; l < 4; ++l) m.stamp(at[2 * l]);
    } else {
      std::memcpy(at, &here, sizeof at);
      std::memcpy(wanted, &freed, sizeof wanted);
      for (int l = 0; l < 4; ++l) m.stamp_free_if(at[2 * l], wanted[2 * l]);
    }
    go = (nx < len) | (ny < len);
  }
  v.next_x = nx;
  v.next_y = ny;
  v.to_side_x = ux;
  v.to_side_y = uy;
  v.entered = entered;
  v.flat = flat;
  v.to_edge_x = ex;
  v.to_edge_y = ey;
}

}  // namespace sensing::ray_kernel

#endif  // x86
