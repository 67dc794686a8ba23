#include "app/picture/map_picture.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "app/picture/size_rules.hpp"
#include "mapping/walls.hpp"

namespace app {
namespace {

unsigned char level(double v) { return static_cast<unsigned char>(std::lround(std::clamp(v, 0.0, 255.0))); }

Rgb grey(double v) { return Rgb{level(v), level(v), level(v)}; }

bool occupied(double l, const MapTones &tones) { return tones.threshold ? l >= *tones.threshold : l > 0.0; }

// The evidence in updates beyond the first, 0 to 1 at three more.
double strength(double l, double one_update) { return std::clamp((l / one_update - 1.0) / 3.0, 0.0, 1.0); }

// The frame of the map area: the sub-cells inside a margin of map_margin_px (where truth.png
// draws its outer walls), its axes in cells, no legend yet.
Figure map_frame(const mapping::GridGeometry &g) {
  const int scale = map_scale(g);
  const int margin = map_margin_px(g);
  Figure fig;
  fig.map_w_px = g.width_subcells() * scale + 2 * margin;
  fig.map_h_px = g.height_subcells() * scale + 2 * margin;
  fig.axes = Axes{g.width_cells, g.height_cells, static_cast<double>(g.subcells * scale), 0, 0, static_cast<double>(margin)};
  return fig;
}

// The sub-cells' top-left corner in a page whose map area is at `area`.
PointPx inside_margin(const mapping::GridGeometry &g, PointPx area) {
  return {area.x + map_margin_px(g), area.y + map_margin_px(g)};
}

PointPx cell_centre_at(const mapping::GridGeometry &g, PointPx origin, mapping::Cell c) {
  const double cell_px = g.subcells * map_scale(g);
  return {origin.x + (c.x + 0.5) * cell_px, origin.y + (g.height_cells - 1 - c.y + 0.5) * cell_px};
}

PointPx subcell_centre_px(const mapping::GridGeometry &g, PointPx origin, mapping::SubCell s) {
  const double scale = map_scale(g);
  return {origin.x + (s.x + 0.5) * scale, origin.y + (g.height_subcells() - 1 - s.y + 0.5) * scale};
}

// The marks at least `least_mark_px` (size_rules.hpp's min_mark_px) across, so that a big
// map's robot and start stay visible when the picture is scaled to a screen.
void draw_marks(Drawing &page, const mapping::GridGeometry &g, PointPx origin, const MapMarks &marks,
                double least_mark_px) {
  const int scale = map_scale(g);
  const double cell_px = g.subcells * scale;
  // Landmarks first: the other marks are drawn over them.
  const double px_per_m = scale / g.subcell_size_m();
  for (const LandmarkMark &l : marks.landmarks) {
    const PointPx at{origin.x + (l.at.x_m - g.origin.x_m) * px_per_m,
                     origin.y + (g.height_cells * g.cell_size_m - (l.at.y_m - g.origin.y_m)) * px_per_m};
    draw_landmark(page, l, at, px_per_m, least_mark_px);
  }
  const double goal_line = std::max(1.0, cell_px / 14);
  for (const mapping::Cell goal : marks.goals) {
    const PointPx c = cell_centre_at(g, origin, goal);
    const double inset = cell_px / 8 + goal_line / 2;
    page.stroke_rect({c.x - cell_px / 2 + inset, c.y - cell_px / 2 + inset, cell_px - 2 * inset, cell_px - 2 * inset},
                     goal_line, kGoalColour);
  }
  if (!marks.planned.empty()) {
    std::vector<PointPx> points;
    for (const mapping::SubCell s : marks.planned) points.push_back(subcell_centre_px(g, origin, s));
    page.polyline(points, std::max(1.5, scale / 2.0), kPlannedColour);
    const double r = std::max({3.0, cell_px / 7, least_mark_px / 2});
    page.ringed_disc(points.back(), r, kWhite, std::max(1.5, r / 3), kPlannedColour);
    page.ringed_disc(points.front(), r, kPlannedColour, std::max(1.0, r / 5), kWhite);
  }
  if (marks.path.empty()) return;
  const auto path_point = [&](std::size_t i) { return cell_centre_at(g, origin, marks.path[i]); };
  page.polyline(marks.path.size(), path_point, std::max(1.5, cell_px / 9), kPathColour);
  const PointPx start = path_point(0);
  const double side = std::max({2.0, cell_px / 3, least_mark_px});
  page.fill_rect({start.x - side / 2, start.y - side / 2, side, side}, kStartColour);
  const double r = std::max({2.0, cell_px / 7, least_mark_px / 2});
  page.ringed_disc(path_point(marks.path.size() - 1), r, kEndColour, std::max(1.0, r / 5), kWhite);
}

std::vector<LegendItem> map_items(const MapMarks &marks) {
  std::vector<LegendItem> items;
  const auto add = [&items](Swatch swatch, Rgb colour, const char *label) { items.push_back({swatch, colour, label}); };
  if (!marks.path.empty()) {
    add(Swatch::line, kPathColour, "path");
    add(Swatch::square, kStartColour, "start");
    add(Swatch::disc, kEndColour, "robot");
  }
  add(Swatch::frame, kGoalColour, "goal");
  if (!marks.planned.empty()) {
    add(Swatch::line, kPlannedColour, "planned path");
    add(Swatch::disc, kPlannedColour, "plan start");
    add(Swatch::ring, kPlannedColour, "plan end");
  }
  for (LegendItem &item : landmark_items(marks.landmarks)) items.push_back(std::move(item));
  return items;
}

std::string signed_2(double v) { return std::abs(v) < 0.005 ? "0" : fmt::format("{:+.2f}", v); }

}  // namespace

Rgb landmark_fill(const LandmarkMark &landmark) { return landmark.colour.value_or(kLandmarkNeutralTone); }

void draw_landmark(Drawing &page, const LandmarkMark &landmark, PointPx at, double px_per_m, double least_mark_px) {
  const double r = std::max({2.0, landmark.radius_m * px_per_m, least_mark_px / 2});
  page.ringed_disc(at, r, landmark_fill(landmark), std::max(1.0, r / 8), Rgb{0, 0, 0});
}

std::vector<LegendItem> landmark_items(const std::vector<LandmarkMark> &landmarks) {
  const auto coloured = [](const LandmarkMark &l) { return l.colour.has_value(); };
  std::vector<LegendItem> items;
  if (std::any_of(landmarks.begin(), landmarks.end(), coloured)) {
    items.push_back({Swatch::disc, Rgb{0, 0, 0}, "landmark (its colour)"});
  }
  if (!std::all_of(landmarks.begin(), landmarks.end(), coloured)) {
    items.push_back({Swatch::disc, kLandmarkNeutralTone, "landmark, colour not given"});
  }
  return items;
}

Rgb observed_tone(double log_odds, const MapTones &tones) {
  if (occupied(log_odds, tones)) return grey(70.0 - 70.0 * strength(log_odds, tones.occupied_increment));
  return grey(215.0 + 40.0 * strength(log_odds, tones.free_increment));
}

Rgb tone(float log_odds, const MapTones &tones) {
  if (!mapping::observed(log_odds, tones.initial_log_odds)) return kUnknownTone;
  return observed_tone(log_odds, tones);
}

ColourBar map_tone_bar(const MapTones &tones, const std::string &unknown_label) {
  const double threshold = tones.threshold ? *tones.threshold : 0.0;
  std::vector<double> knots{4 * tones.free_increment, tones.free_increment, threshold, tones.occupied_increment,
                            4 * tones.occupied_increment};
  std::sort(knots.begin(), knots.end());
  knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
  ColourBar bar;
  bar.name = "log-odds";
  const auto segments = static_cast<int>(knots.size()) - 1;
  const int per_segment = 60;
  // Each segment of the bar spans two knots linearly; a sample at the middle of its column.
  for (int s = 0; s < segments; ++s) {
    const double a = knots[static_cast<std::size_t>(s)];
    const double b = knots[static_cast<std::size_t>(s) + 1];
    for (int i = 0; i < per_segment; ++i) bar.tones.push_back(observed_tone(a + (b - a) * (i + 0.5) / per_segment, tones));
  }
  for (std::size_t k = 0; k < knots.size(); ++k) {
    // The prior's knot says so: where the tones jump from free to occupied by default.
    const bool prior = std::abs(knots[k] - tones.initial_log_odds) < 1e-6;
    bar.ticks.push_back({segments == 0 ? 0.5 : static_cast<double>(k) / segments, signed_2(knots[k]),
                         prior ? (tones.initial_log_odds == 0.0f ? "prior, p 0.5" : "prior") : ""});
  }
  bar.left_word = "free";
  bar.right_word = "occupied";
  bar.extra = LegendItem{Swatch::box, kUnknownTone, unknown_label};
  return bar;
}

int map_scale(const mapping::GridGeometry &geometry) {
  const int k = geometry.subcells;
  const int wanted = (100 + k - 1) / k;
  const int side = std::max(geometry.width_subcells(), geometry.height_subcells());
  return std::clamp(4096 / side, 1, wanted);
}

int map_margin_px(const mapping::GridGeometry &geometry) {
  return std::max(2, geometry.subcells * map_scale(geometry) / 10);
}

PointPx map_origin_px(const mapping::GridGeometry &geometry) {
  return inside_margin(geometry, layout_figure(map_frame(geometry)).map_origin);
}

PointPx cell_centre_px(const mapping::GridGeometry &g, mapping::Cell c) {
  return cell_centre_at(g, map_origin_px(g), c);
}

Figure map_figure(const mapping::GridGeometry &g, const MapTones &tones, const MapMarks &marks,
                  const std::string &caption) {
  Figure fig = map_frame(g);
  fig.lines = {caption};
  fig.items = map_items(marks);
  fig.bar = map_tone_bar(tones, "never observed (prior)");
  fig.px_per_m = map_scale(g) / g.subcell_size_m();
  return fig;
}

Drawing map_picture(const mapping::OccupancyGrid &grid, const MapTones &tones, const MapMarks &marks,
                    const std::string &caption, PictureFormat format, const std::optional<PageFrame> &page) {
  const mapping::GridGeometry &g = grid.geometry();
  const Figure fig = map_figure(g, tones, marks, caption);
  const FigureLayout layout = page ? layout_figure(fig, *page) : layout_figure(fig);
  Drawing drawing(layout.width, layout.height, format);
  const int scale = map_scale(g);
  const int h = g.height_subcells();
  const PointPx origin = inside_margin(g, layout.map_origin);
  drawing.blocks([&](int x, int row) { return tone(grid.at(mapping::SubCell{x, h - 1 - row}), tones); },
                 g.width_subcells(), h, origin, scale, scale);
  draw_marks(drawing, g, origin, marks, min_mark_px(layout.font_px));
  draw_figure(drawing, fig, layout);
  return drawing;
}

}  // namespace app
