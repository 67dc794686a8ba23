#pragma once
// The ray model (`--model ray`; docs/models.md): every beam traced through the sub-cells it
// crosses (Amanatides-Woo, mapping/traversal.hpp; the fast walk is sensing/ray_kernel.hpp):
// p_occ at the hit sub-cell and hit_depth sub-cells behind it, nothing beyond; before the
// hit, p_free for the interior sub-cells it crosses and, where it crosses a cell side, for
// the two band sub-cells beside the crossing. A band stands for its cell side, and a beam
// says a side is open only by crossing it: one running along a band without crossing the
// side leaves the band alone (a 12 mm wall fills 4 % of a 1/3 m sub-cell; freeing bands
// along corridors would erase the walls). A beam with no return frees the same way up to
// max range (unless ignore_no_return). Beams stop where they leave the grid; leaving it
// crosses the outer side.

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "sensing/scan.hpp"
#include "sensing/setups.hpp"

namespace sensing {

// Gathers the marks of one scan into `update` (robot_cell is not used: every beam starts at
// the scan's origin), with the kernel built for ray_kernel_isa().
void mark_ray_model(const ModelOptions &options, const mapping::OccupancyGrid &grid, const LidarScan &scan,
                    mapping::Cell robot_cell, mapping::ScanUpdate &update);

// The instruction sets the kernel is built for: SSE2 (every x86-64, and the portable build
// elsewhere) and AVX2, four lanes a register. Both give the same marks.
enum class RayKernelIsa { baseline, avx2 };
// The one this processor runs: avx2 when it has AVX2, else baseline.
RayKernelIsa ray_kernel_isa();
// mark_ray_model with the kernel built for `isa` (tests run both); `isa` must be baseline or
// ray_kernel_isa().
void mark_ray_model(const ModelOptions &options, const mapping::OccupancyGrid &grid, const LidarScan &scan,
                    mapping::Cell robot_cell, mapping::ScanUpdate &update, RayKernelIsa isa);

}  // namespace sensing
