#pragma once
// map.png (and the snapshots): the learned grid as a picture a projector survives, north up,
// each sub-cell a square of map_scale() pixels, a legend strip under it.
//
//   tone     never observed: a blue-grey mid tone, kUnknownTone, whatever the prior
//            occupied (log-odds above 0, or at least --threshold): dark, 70 after one
//            occupied update down to 0 after four or more
//            free (observed, not occupied): light, 215 after one free update up to 255
//            after four or more
//            So one p_occ update already reads as a wall, and the three tones stay apart
//            for every model (the increments are the set-up's own, see MapTones).
//   marks    the path (cell centres in order of arrival) in red, the start a green square,
//            the robot (where it stands at the picture's step) a blue disc, each goal cell a
//            gold frame; a planned path (plan.png) through its sub-cells' centres in
//            magenta, its start a magenta disc and its end a magenta ring; each landmark a
//            disc of its colour ringed in black
//   axes     cell indices (x, y), as the messages name cells; the sub-cells inside a margin
//            (map_margin_px) as wide as truth.png's outer walls, so that a run's map.png and
//            truth.png are one size and scale (shared_page) and can be flipped between
//   legend   the caption ("model cell, K 3", and a note such as a snapshot's step), what
//            each mark means, a colour bar of the tones by log-odds (map_tone_bar) with the
//            never-observed swatch, and a scale bar in metres
// Drawn by app/picture/drawing.hpp in the layout of app/picture/figure.hpp.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/picture/drawing.hpp"
#include "app/picture/figure.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"

namespace app {

inline constexpr Rgb kUnknownTone{150, 160, 190};
inline constexpr Rgb kPathColour{220, 30, 30};
inline constexpr Rgb kStartColour{20, 170, 40};
inline constexpr Rgb kEndColour{30, 90, 220};
inline constexpr Rgb kGoalColour{240, 170, 0};
inline constexpr Rgb kPlannedColour{200, 0, 200};

// What the tones are measured against, in the grid's log-odds.
struct MapTones {
  float initial_log_odds = 0.0f;        // l(prior): never observed
  std::optional<float> threshold;       // --threshold: occupied when >= this (default > 0)
  double occupied_increment = 0.4055;   // one occupied update of the set-up, > 0
  double free_increment = -0.8473;      // one free update of the set-up, < 0
};

Rgb tone(float log_odds, const MapTones &tones);
// The tone of an observed sub-cell (occupied or free by the rule above).
Rgb observed_tone(double log_odds, const MapTones &tones);
// The colour bar of these tones: log-odds from four free updates (left, "free") to four
// occupied updates (right, "occupied"), each of the knots (four and one free update, the
// occupied threshold, one and four occupied updates) a tick an equal part of the bar apart,
// the knot at the prior's log-odds noted "prior, p 0.5" (the tones' jump from free to
// occupied, by default), and `unknown_label` (e.g. "never observed") in kUnknownTone after it.
ColourBar map_tone_bar(const MapTones &tones, const std::string &unknown_label);

// A landmark of the world (maze::Landmark, or a cylinder a supervisor placed), where it
// stands in the world frame (m), its colour (none when the world does not say it) and radius.
struct LandmarkMark {
  mapping::Point at;
  std::optional<Rgb> colour;
  double radius_m = 0.0;
};
// A landmark whose colour is not known is drawn in this neutral grey.
inline constexpr Rgb kLandmarkNeutralTone{128, 128, 128};
// The fill a landmark is drawn in: its colour, else kLandmarkNeutralTone.
Rgb landmark_fill(const LandmarkMark &landmark);
// Draws a landmark as a disc of its fill, its radius at `px_per_m` and its diameter at least
// `least_mark_px` (app/picture/size_rules.hpp), ringed in black, centred at `at`.
void draw_landmark(Drawing &page, const LandmarkMark &landmark, PointPx at, double px_per_m, double least_mark_px);
// The legend's words for these landmarks: "landmark (its colour)" when one has a colour,
// "landmark, colour not given" (a neutral disc) when one has none; nothing for none.
std::vector<LegendItem> landmark_items(const std::vector<LandmarkMark> &landmarks);

// What is drawn over the map. The path is the caller's (a long run's is millions of cells):
// it must outlive the marks.
struct MapMarks {
  std::span<const mapping::Cell> path;  // cells in order of arrival, start first (may be empty)
  std::vector<mapping::Cell> goals;
  std::vector<mapping::SubCell> planned;  // a planned path (plan.png), sub-cell centres, in magenta
  std::vector<LandmarkMark> landmarks;    // discs of their colour, ringed in black
};

// Pixels a sub-cell: ceil(100 / K), so a cell is at least 100 px, lowered for big mazes so
// that the map stays within 4096 px a side where it can (never below 1).
int map_scale(const mapping::GridGeometry &geometry);

// The margin around the sub-cells inside the map area, in pixels (truth.png draws the maze's
// outer walls there): a tenth of a cell, 2 px at least.
int map_margin_px(const mapping::GridGeometry &geometry);

// The figure map_picture draws: its map area, axes and legend (for shared_page).
Figure map_figure(const mapping::GridGeometry &geometry, const MapTones &tones, const MapMarks &marks,
                  const std::string &caption);

// The picture (app/figure.hpp's layout) on its own page, or on `page` (a page shared with the
// run's other pictures); `caption` is the legend's first line. The robot's mark is at
// marks.path's last cell.
Drawing map_picture(const mapping::OccupancyGrid &grid, const MapTones &tones, const MapMarks &marks,
                    const std::string &caption, PictureFormat format = PictureFormat::png,
                    const std::optional<PageFrame> &page = std::nullopt);

// Where the map's top-left sub-cell's top-left corner is in the picture of a grid of this
// geometry on its own page.
PointPx map_origin_px(const mapping::GridGeometry &geometry);
// The pixel centre of a cell in that picture.
PointPx cell_centre_px(const mapping::GridGeometry &geometry, mapping::Cell c);

}  // namespace app
