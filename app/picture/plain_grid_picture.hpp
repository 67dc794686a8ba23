#pragma once
// A picture of a plain grid of cells in metres, north up, a legend strip under it: the
// pictures of `map-log --out` (a log-odds picture per snapshot, the thresholded map) and of
// `demo pie --png`, which are not the maze's 4D grid. Each cell is a rectangle of whole
// pixels in its own tone; overlays (a pie's slices) are drawn through plain_grid_px.
//
//   pixels a metre   about 600 / the longer side in metres, so that each cell is at least
//                    plain_grid_min_cell_px wide: a 25 x 25 grid is 24 px a cell, 50 x 50 12

#include <vector>

#include "app/picture/picture.hpp"
#include "app/picture/map_picture.hpp"

namespace app {

struct PlainGrid {
  int cells_x = 0;
  int cells_y = 0;
  double x0_m = 0.0;  // the south-west corner
  double y0_m = 0.0;
  double cell_w_m = 1.0;
  double cell_h_m = 1.0;
  std::vector<Rgb> tones;  // cell (i, j), column i from the west, row j from the south: j * cells_x + i
};

// Square cells of side cell_m on a lattice from the origin: cell (i, j) covers
// [i cell_m, (i + 1) cell_m] x [j cell_m, (j + 1) cell_m]; the grid holds i from i_min - 2 to
// i_max + 2 and j likewise (the cells to show and two of margin), every cell in `fill`.
PlainGrid plain_grid_around(int i_min, int i_max, int j_min, int j_max, double cell_m, Rgb fill);
// Sets the tone of the cell holding the point (x_m, y_m), which must lie on the grid.
void set_tone(PlainGrid &grid, double x_m, double y_m, Rgb tone);

// Whole pixels of one cell, across and down.
struct CellPixels {
  int w = 1;
  int h = 1;
};
CellPixels plain_grid_cell_px(const PlainGrid &grid);

// The pixel of the point (x_m, y_m) in the picture.
PixelPoint plain_grid_px(const PlainGrid &grid, double x_m, double y_m);

// The grid at the top-left, at least kMinPictureWidth wide, the legend under it (its
// px_per_m set here, for the scale bar).
Canvas plain_grid_picture(const PlainGrid &grid, Legend legend);

// The tone of a log-odds value in the map pictures' scale (app/picture/map_picture.hpp): never
// updated (== l0) blue-grey, occupied (> 0) dark, else light, graded by the increments.
Rgb log_odds_tone(double log_odds, double l0, double occupied_increment, double free_increment);

}  // namespace app
