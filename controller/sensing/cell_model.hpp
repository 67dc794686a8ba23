#pragma once
// The classroom sub-cell model (`--model cell`, the default set-up; docs/models.md). Only the
// robot's own cell is updated. The beams nearest to world N, E, S, W decide, per side, wall
// or opening:
//   wall     the whole band (its middle and every sub-cell left and right of it)  p_occ,
//            sub-cells strictly between centre and band middle  p_free
//   opening  band middle and the sub-cells between centre and it  p_free
// The centre is always free. A side whose beams are invalid, or split evenly between wall
// and opening, is not updated.
// K = 3, walls N and W, openings E and S, defaults (l(0.6) = 0.41, l(0.3) = -0.85):
//     +0.41 +0.41 +0.41
//     +0.41 -0.85 -0.85
//     +0.41 -0.85 +0.00

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/walls.hpp"
#include "sensing/scan.hpp"
#include "sensing/setups.hpp"

namespace sensing {

// Gathers the marks of one scan taken in robot_cell (inside the grid) into `update`.
void mark_cell_model(const ModelOptions &options, const mapping::OccupancyGrid &grid, const LidarScan &scan,
                     mapping::Cell robot_cell, mapping::ScanUpdate &update);

// The model's reading of side h of cell c from a scan taken in c (the median of the beams
// within 2.5 degrees of the side's direction): wall when it returns closer than the side
// plus wall_margin cells, open when further or no return, unknown without a valid beam or
// when an even count of readings splits evenly between the two. The controller also checks
// a side its grid calls open against it before driving through (a wall seen from half a
// cell beats a band freed by a faulty beam from afar).
mapping::SideState read_cell_side(const ModelOptions &options, const mapping::OccupancyGrid &grid,
                                  const LidarScan &scan, mapping::Cell c, mapping::Heading h);

// What a scan says of side h of cell c seen from afar, down the beams along h (c further
// along h from the scan's origin, or the origin's own cell): the same medians and rule as
// read_cell_side, except that no return says open only when the lidar reaches past the side
// plus wall_margin cells (a side beyond its reach is unknown). A robot reads the sides ahead
// of it this way before driving a straight without stopping.
mapping::SideState read_side_ahead(const ModelOptions &options, const mapping::OccupancyGrid &grid,
                                   const LidarScan &scan, mapping::Cell c, mapping::Heading h);

}  // namespace sensing
