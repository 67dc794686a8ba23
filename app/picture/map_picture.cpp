#include "app/picture/map_picture.hpp"

#include <algorithm>
#include <cmath>

#include "mapping/walls.hpp"

namespace app {
namespace {

unsigned char level(double v) { return static_cast<unsigned char>(std::lround(std::clamp(v, 0.0, 255.0))); }

Rgb grey(double v) { return Rgb{level(v), level(v), level(v)}; }

bool occupied(float l, const MapTones &tones) { return tones.threshold ? l >= *tones.threshold : l > 0.0f; }

// The evidence in updates beyond the first, 0 to 1 at three more.
double strength(double l, double one_update) { return std::clamp((l / one_update - 1.0) / 3.0, 0.0, 1.0); }

void draw_marks(Canvas &canvas, const mapping::GridGeometry &g, const MapMarks &marks) {
  const int scale = map_scale(g);
  const int cell_px = g.subcells * scale;
  // Landmarks first: the other marks are drawn over them.
  const double px_per_m = scale / g.subcell_size_m();
  for (const LandmarkMark &l : marks.landmarks) {
    const int x = static_cast<int>(std::lround((l.at.x_m - g.origin.x_m) * px_per_m));
    const int y = static_cast<int>(std::lround((g.height_cells * g.cell_size_m - (l.at.y_m - g.origin.y_m)) * px_per_m));
    const int r = std::max(2, static_cast<int>(std::lround(l.radius_m * px_per_m)));
    canvas.disc(x, y, r + 1, Rgb{0, 0, 0});
    canvas.disc(x, y, r, l.colour);
  }
  for (const mapping::Cell goal : marks.goals) {
    const PixelPoint c = cell_centre_px(g, goal);
    const int inset = cell_px / 8;
    canvas.frame(c.x - cell_px / 2 + inset, c.y - cell_px / 2 + inset, cell_px - 2 * inset, cell_px - 2 * inset,
                 std::max(1, cell_px / 14), kGoalColour);
  }
  const int thickness = std::max(1, scale / 3);
  const auto subcell_px = [&](mapping::SubCell s) {
    return PixelPoint{s.x * scale + scale / 2, (g.height_subcells() - 1 - s.y) * scale + scale / 2};
  };
  for (std::size_t i = 1; i < marks.planned.size(); ++i) {
    const PixelPoint a = subcell_px(marks.planned[i - 1]);
    const PixelPoint b = subcell_px(marks.planned[i]);
    canvas.line(a.x, a.y, b.x, b.y, std::max(1, scale / 2), kPlannedColour);
  }
  for (std::size_t i = 1; i < marks.path.size(); ++i) {
    const PixelPoint a = cell_centre_px(g, marks.path[i - 1]);
    const PixelPoint b = cell_centre_px(g, marks.path[i]);
    canvas.line(a.x, a.y, b.x, b.y, thickness, kPathColour);
  }
  if (marks.path.empty()) return;
  const PixelPoint start = cell_centre_px(g, marks.path.front());
  const int side = std::max(1, cell_px / 3);
  canvas.fill(start.x - side / 2, start.y - side / 2, side, side, kStartColour);
  const PixelPoint end = cell_centre_px(g, marks.path.back());
  canvas.disc(end.x, end.y, std::max(1, cell_px / 7), kEndColour);
}

Legend map_legend(const std::string &caption, const mapping::GridGeometry &g, const MapMarks &marks) {
  Legend legend;
  legend.lines.push_back(caption);
  legend.items = {{Swatch::box, grey(35), "occupied"}, {Swatch::box, grey(235), "free"},
                  {Swatch::box, kUnknownTone, "never observed"}};
  if (!marks.path.empty()) {
    legend.items.insert(legend.items.end(), {{Swatch::line, kPathColour, "path"},
                                             {Swatch::square, kStartColour, "start"},
                                             {Swatch::disc, kEndColour, "end"}});
  }
  legend.items.push_back({Swatch::frame, kGoalColour, "goal"});
  if (!marks.planned.empty()) legend.items.push_back({Swatch::line, kPlannedColour, "planned path"});
  if (!marks.landmarks.empty()) legend.items.push_back({Swatch::disc, Rgb{0, 0, 0}, "landmark (its colour)"});
  legend.px_per_m = map_scale(g) / g.subcell_size_m();
  return legend;
}

}  // namespace

Rgb tone(float log_odds, const MapTones &tones) {
  if (!mapping::observed(log_odds, tones.initial_log_odds)) return kUnknownTone;
  if (occupied(log_odds, tones)) return grey(70.0 - 70.0 * strength(log_odds, tones.occupied_increment));
  return grey(215.0 + 40.0 * strength(log_odds, tones.free_increment));
}

int map_scale(const mapping::GridGeometry &geometry) {
  const int k = geometry.subcells;
  const int wanted = (100 + k - 1) / k;
  const int side = std::max(geometry.width_subcells(), geometry.height_subcells());
  return std::clamp(4096 / side, 1, wanted);
}

PixelPoint cell_centre_px(const mapping::GridGeometry &g, mapping::Cell c) {
  const int cell_px = g.subcells * map_scale(g);
  return {c.x * cell_px + cell_px / 2, (g.height_cells - 1 - c.y) * cell_px + cell_px / 2};
}

Canvas map_picture(const mapping::OccupancyGrid &grid, const MapTones &tones, const MapMarks &marks,
                   const std::string &caption) {
  const mapping::GridGeometry &g = grid.geometry();
  const int scale = map_scale(g);
  const int w = g.width_subcells();
  const int h = g.height_subcells();
  const int width = std::max(w * scale, kMinPictureWidth);
  const int font = legend_font(width);
  const Legend legend = map_legend(caption, g, marks);
  Canvas canvas(width, h * scale + legend_height(legend, width, font), Rgb{255, 255, 255});
  for (int row = 0; row < h; ++row) {
    for (int x = 0; x < w; ++x) {
      canvas.fill(x * scale, row * scale, scale, scale, tone(grid.at(mapping::SubCell{x, h - 1 - row}), tones));
    }
  }
  draw_marks(canvas, g, marks);
  draw_legend(canvas, h * scale, legend, font);
  return canvas;
}

}  // namespace app
