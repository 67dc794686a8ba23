#include "app/picture/plain_grid_picture.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "app/picture/size_rules.hpp"

namespace app {
namespace {

double px_per_m(const PlainGrid &g) {
  const double side_m = std::max(g.cells_x * g.cell_w_m, g.cells_y * g.cell_h_m);
  const double smaller_cell_m = std::min(g.cell_w_m, g.cell_h_m);
  return std::max(600.0 / side_m, 1.0 / smaller_cell_m);
}

// Whole pixels a cell, so that the blocks have crisp edges.
double cell_w_px(const PlainGrid &g) { return std::max(1.0, std::round(g.cell_w_m * px_per_m(g))); }
double cell_h_px(const PlainGrid &g) { return std::max(1.0, std::round(g.cell_h_m * px_per_m(g))); }

Figure with_grid(const PlainGrid &g, Figure fig) {
  const int band = boundary_band_px(g);
  fig.map_w_px = static_cast<int>(g.cells_x * cell_w_px(g)) + 2 * band;
  fig.map_h_px = static_cast<int>(g.cells_y * cell_h_px(g)) + 2 * band;
  if (cell_w_px(g) == cell_h_px(g)) {
    fig.axes = Axes{g.cells_x, g.cells_y, cell_w_px(g), g.first_i, g.first_j, static_cast<double>(band)};
    if (g.axes_in_metres) {
      fig.axes->px_per_m = cell_w_px(g) / g.cell_w_m;
      fig.axes->x0_m = g.x0_m;
      fig.axes->y0_m = g.y0_m;
    }
  }
  fig.px_per_m = cell_w_px(g) / g.cell_w_m;
  return fig;
}

// Everything in the map area outside the solid boundary, as wall: the band round the grid
// and the grid's cells past the boundary.
void draw_boundary_wall(Drawing &page, const PlainGrid &g, const PlainGridFrame &frame, const RectPx &area) {
  if (!g.solid_boundary) return;
  const PlainGridBounds &b = *g.solid_boundary;
  const PointPx south_west = frame.at(b.x_min_m, b.y_min_m);
  const PointPx north_east = frame.at(b.x_max_m, b.y_max_m);
  const double right = area.x + area.w;
  const double bottom = area.y + area.h;
  const auto wall = [&page](RectPx r) {
    if (r.w > 0.0 && r.h > 0.0) page.fill_rect(r, kBoundaryWallColour);
  };
  wall({area.x, area.y, south_west.x - area.x, area.h});
  wall({north_east.x, area.y, right - north_east.x, area.h});
  wall({area.x, area.y, area.w, north_east.y - area.y});
  wall({area.x, south_west.y, area.w, bottom - south_west.y});
}

}  // namespace

int boundary_band_px(const PlainGrid &g) {
  return g.solid_boundary ? static_cast<int>(std::clamp(cell_w_px(g), 4.0, 16.0)) : 0;
}

Figure plain_grid_figure(const PlainGrid &grid, Figure legend) { return with_grid(grid, std::move(legend)); }

PointPx PlainGridFrame::at(double x_m, double y_m) const {
  const double col = (x_m - x0_m) / cell_w_m;
  const double row = cells_y - (y_m - y0_m) / cell_h_m;
  return {origin.x + col * cell_w_px, origin.y + row * cell_h_px};
}

PlainGrid plain_grid_around(int i_min, int i_max, int j_min, int j_max, double cell_m, Rgb fill) {
  PlainGrid g;
  g.cells_x = i_max - i_min + 5;
  g.cells_y = j_max - j_min + 5;
  g.x0_m = (i_min - 2) * cell_m;
  g.y0_m = (j_min - 2) * cell_m;
  g.first_i = i_min - 2;
  g.first_j = j_min - 2;
  g.cell_w_m = g.cell_h_m = cell_m;
  g.tones.assign(static_cast<std::size_t>(g.cells_x * g.cells_y), fill);
  return g;
}

void set_tone(PlainGrid &g, double x_m, double y_m, Rgb tone) {
  const int i = static_cast<int>(std::floor((x_m - g.x0_m) / g.cell_w_m));
  const int j = static_cast<int>(std::floor((y_m - g.y0_m) / g.cell_h_m));
  assert(i >= 0 && j >= 0 && i < g.cells_x && j < g.cells_y);
  g.tones[static_cast<std::size_t>(j * g.cells_x + i)] = tone;
}

PlainGridFrame plain_grid_frame(const PlainGrid &g, const Figure &legend) {
  PlainGridFrame frame;
  const PointPx area = layout_figure(with_grid(g, legend)).map_origin;
  frame.origin = {area.x + boundary_band_px(g), area.y + boundary_band_px(g)};
  frame.cell_w_px = cell_w_px(g);
  frame.cell_h_px = cell_h_px(g);
  frame.x0_m = g.x0_m;
  frame.y0_m = g.y0_m;
  frame.cell_w_m = g.cell_w_m;
  frame.cell_h_m = g.cell_h_m;
  frame.cells_y = g.cells_y;
  frame.least_mark_px = min_mark_px(layout_figure(with_grid(g, legend)).font_px);
  return frame;
}

Drawing plain_grid_picture(const PlainGrid &g, Figure legend, const PlainGridOverlay &overlay, PictureFormat format,
                           const std::optional<PageFrame> &shared) {
  const Figure fig = with_grid(g, std::move(legend));
  const FigureLayout layout = shared ? layout_figure(fig, *shared) : layout_figure(fig);
  PlainGridFrame frame = plain_grid_frame(g, fig);
  const int band = boundary_band_px(g);
  frame.origin = {layout.map_origin.x + band, layout.map_origin.y + band};
  frame.least_mark_px = min_mark_px(layout.font_px);
  Drawing page(layout.width, layout.height, format);
  std::vector<Rgb> top_first;
  top_first.reserve(g.tones.size());
  for (int j = g.cells_y - 1; j >= 0; --j) {
    for (int i = 0; i < g.cells_x; ++i) top_first.push_back(g.tones[static_cast<std::size_t>(j * g.cells_x + i)]);
  }
  page.blocks(top_first, g.cells_x, g.cells_y, frame.origin, frame.cell_w_px, frame.cell_h_px);
  draw_boundary_wall(page, g, frame,
                     {layout.map_origin.x, layout.map_origin.y, static_cast<double>(fig.map_w_px),
                      static_cast<double>(fig.map_h_px)});
  if (overlay) overlay(page, frame);
  draw_figure(page, fig, layout);
  return page;
}

MapTones log_odds_tones(double l0, double occupied_increment, double free_increment) {
  MapTones tones;
  tones.initial_log_odds = static_cast<float>(l0);
  tones.occupied_increment = occupied_increment;
  tones.free_increment = free_increment;
  return tones;
}

Rgb log_odds_tone(double log_odds, double l0, double occupied_increment, double free_increment) {
  return tone(static_cast<float>(log_odds), log_odds_tones(l0, occupied_increment, free_increment));
}

}  // namespace app
