#pragma once
// A picture of a plain grid of cells in metres, north up, with app/figure.hpp's axes and
// legend: the pictures of `map-log --out` (a log-odds picture per snapshot, the thresholded
// map), of `demo pie --png` and of `demo cone --png`, which are not the maze's 4D grid. Each
// cell is a block in its own tone; overlays (a pie's slices, a cone's edges) are drawn by the
// caller through the frame's metres-to-pixels mapping.
//
//   pixels a metre   about 600 / the longer side in metres, so that each cell is at least
//                    one pixel: a 25 x 25 grid is 24 px a cell, 50 x 50 12
//   a solid boundary (a room's: walled all round, its walls on the grid's edge or past it)
//                    everything outside it drawn as wall, in kBoundaryWallColour: a band a
//                    cell wide (4 to 16 px) round the grid, and any cells the grid has past
//                    the boundary, so that the outer wall reads whole whatever the map holds
//                    in the cells along it

#include <functional>
#include <optional>
#include <vector>

#include "app/picture/drawing.hpp"
#include "app/picture/figure.hpp"
#include "app/picture/map_picture.hpp"

namespace app {

// The colour of a solid boundary's wall.
inline constexpr Rgb kBoundaryWallColour{0, 0, 0};

// A rectangle in metres, x_min < x_max, y_min < y_max.
struct PlainGridBounds {
  double x_min_m = 0.0;
  double x_max_m = 0.0;
  double y_min_m = 0.0;
  double y_max_m = 0.0;
};

struct PlainGrid {
  int cells_x = 0;
  int cells_y = 0;
  double x0_m = 0.0;  // the south-west corner
  double y0_m = 0.0;
  double cell_w_m = 1.0;
  double cell_h_m = 1.0;
  int first_i = 0;  // the index the axes give the west column and the south row
  int first_j = 0;
  bool axes_in_metres = false;  // the axes in metres (a room's map) instead of cell indices
  std::vector<Rgb> tones;  // cell (i, j), column i from the west, row j from the south: j * cells_x + i
  // The world's solid boundary, inside the grid's extent (or on its edge): drawn as wall
  // outside it (above). None: the grid alone, no band.
  std::optional<PlainGridBounds> solid_boundary;
};

// The width of the band drawn round a grid with a solid boundary (0 without one), in pixels.
int boundary_band_px(const PlainGrid &grid);

// Square cells of side cell_m on a lattice from the origin: cell (i, j) covers
// [i cell_m, (i + 1) cell_m] x [j cell_m, (j + 1) cell_m]; the grid holds i from i_min - 2 to
// i_max + 2 and j likewise (the cells to show and two of margin), every cell in `fill`, its
// axes labelled with these i and j.
PlainGrid plain_grid_around(int i_min, int i_max, int j_min, int j_max, double cell_m, Rgb fill);
// Sets the tone of the cell holding the point (x_m, y_m), which must lie on the grid.
void set_tone(PlainGrid &grid, double x_m, double y_m, Rgb tone);

// Where the grid is in the picture: the pixel of a point in metres, and a cell's size.
struct PlainGridFrame {
  PointPx origin;  // the grid's north-west corner (inside the boundary's band, when there is one)
  double cell_w_px = 1.0;
  double cell_h_px = 1.0;
  double x0_m = 0.0;
  double y0_m = 0.0;
  double cell_w_m = 1.0;
  double cell_h_m = 1.0;
  int cells_y = 0;
  double least_mark_px = 8.4;  // a mark's least size on this page (app/picture/size_rules.hpp)
  PointPx at(double x_m, double y_m) const;
};

// Draws over the grid (after the tones, before the legend).
using PlainGridOverlay = std::function<void(Drawing &page, const PlainGridFrame &frame)>;

// The picture: the grid with cell indices (or metres) on its axes, the figure's legend under
// it (`legend`'s lines, items and bar; its map size, axes and scale are set here), on its own
// page or on `page` (shared with other pictures of the grid: shared_page of their figures).
Drawing plain_grid_picture(const PlainGrid &grid, Figure legend, const PlainGridOverlay &overlay = {},
                           PictureFormat format = PictureFormat::png,
                           const std::optional<PageFrame> &page = std::nullopt);
// The figure plain_grid_picture draws `grid` in with this legend.
Figure plain_grid_figure(const PlainGrid &grid, Figure legend);

// The frame plain_grid_picture draws `grid` in with this legend.
PlainGridFrame plain_grid_frame(const PlainGrid &grid, const Figure &legend);

// The tone of a log-odds value in the map pictures' scale (app/picture/map_picture.hpp): never
// updated (== l0) blue-grey, occupied (> 0) dark, else light, graded by the increments.
Rgb log_odds_tone(double log_odds, double l0, double occupied_increment, double free_increment);
// The MapTones of that scale, for its colour bar (map_tone_bar).
MapTones log_odds_tones(double l0, double occupied_increment, double free_increment);

}  // namespace app
