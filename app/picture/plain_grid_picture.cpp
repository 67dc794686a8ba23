#include "app/picture/plain_grid_picture.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace app {
namespace {

double px_per_m(const PlainGrid &g) {
  const double side_m = std::max(g.cells_x * g.cell_w_m, g.cells_y * g.cell_h_m);
  const double smaller_cell_m = std::min(g.cell_w_m, g.cell_h_m);
  return std::max(600.0 / side_m, 1.0 / smaller_cell_m);
}

}  // namespace

PlainGrid plain_grid_around(int i_min, int i_max, int j_min, int j_max, double cell_m, Rgb fill) {
  PlainGrid g;
  g.cells_x = i_max - i_min + 5;
  g.cells_y = j_max - j_min + 5;
  g.x0_m = (i_min - 2) * cell_m;
  g.y0_m = (j_min - 2) * cell_m;
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

CellPixels plain_grid_cell_px(const PlainGrid &g) {
  const double ppm = px_per_m(g);
  return {std::max(1, static_cast<int>(std::lround(g.cell_w_m * ppm))),
          std::max(1, static_cast<int>(std::lround(g.cell_h_m * ppm)))};
}

PixelPoint plain_grid_px(const PlainGrid &g, double x_m, double y_m) {
  const CellPixels c = plain_grid_cell_px(g);
  const double col = (x_m - g.x0_m) / g.cell_w_m;
  const double row = g.cells_y - (y_m - g.y0_m) / g.cell_h_m;
  return {static_cast<int>(std::lround(col * c.w)), static_cast<int>(std::lround(row * c.h))};
}

Canvas plain_grid_picture(const PlainGrid &g, Legend legend) {
  const CellPixels c = plain_grid_cell_px(g);
  const int map_w = g.cells_x * c.w;
  const int map_h = g.cells_y * c.h;
  const int width = std::max(map_w, kMinPictureWidth);
  const int font = legend_font(width);
  legend.px_per_m = c.w / g.cell_w_m;
  Canvas canvas(width, map_h + legend_height(legend, width, font), Rgb{255, 255, 255});
  for (int j = 0; j < g.cells_y; ++j) {
    for (int i = 0; i < g.cells_x; ++i) {
      canvas.fill(i * c.w, (g.cells_y - 1 - j) * c.h, c.w, c.h, g.tones[static_cast<std::size_t>(j * g.cells_x + i)]);
    }
  }
  draw_legend(canvas, map_h, legend, font);
  return canvas;
}

Rgb log_odds_tone(double log_odds, double l0, double occupied_increment, double free_increment) {
  MapTones tones;
  tones.initial_log_odds = static_cast<float>(l0);
  tones.occupied_increment = occupied_increment;
  tones.free_increment = free_increment;
  return tone(static_cast<float>(log_odds), tones);
}

}  // namespace app
