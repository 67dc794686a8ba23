#pragma once
// The page layout every picture shares (map, truth, snapshots, plan, demo pie / cone,
// map-log): a map area with cell indices on its axes, and under it the legend: the caption
// lines, a swatch and a name for each mark, a colour bar that explains every tone, and a
// scale bar in metres. The page is as wide as the widest of these and no wider.
//
//   +-------------------------------------------+
//   |  y                                        |
//   |  3 -+--------------------+                |
//   |  2 -|      map area      |                |
//   |  1 -|                    |                |
//   |  0 -+--------------------+ x              |
//   |       0    1    2    3                    |
//   |  caption lines                            |
//   |  [#] occupied  [ ] free  -- path  o robot |
//   |  log-odds [colour bar] never observed [ ] |
//   |  |----| 1 m                               |
//   +-------------------------------------------+
//
// The font size is at least a 40th of the page's height (and 14 px), every text on the page
// (axes and ticks too) in that size, so that a picture scaled to a projector's screen keeps
// its text readable. Several pictures of one map area (a run's map.png, truth.png and
// snapshots) share one page (shared_page): the same size, font and map origin, so that one
// can be flipped to the next.

#include <optional>
#include <string>
#include <vector>

#include "app/picture/drawing.hpp"

namespace app {

// The cell indices on the axes: column i's centre at offset_px + cell_px (i + 0.5) from the
// map area's left edge, labelled first_x + i; row j (from the south) at offset_px + cell_px
// (rows - j - 0.5) from its top, labelled first_y + j.
// With px_per_m > 0 the axes are in metres instead: ticks at round metres (0.1, 0.2, 0.5,
// 1, 2, 5 ... apart), the map area's left edge at x0_m and its bottom edge at y0_m (beyond
// offset_px), the axes named "x (m)" and "y (m)".
struct Axes {
  int columns = 0;
  int rows = 0;
  double cell_px = 1.0;
  int first_x = 0;
  int first_y = 0;
  double offset_px = 0.0;
  double px_per_m = 0.0;
  double x0_m = 0.0;
  double y0_m = 0.0;
};

enum class Swatch { box, line, square, disc, frame, ring };
struct LegendItem {
  Swatch swatch = Swatch::box;
  Rgb colour;
  std::string label;
};

// A horizontal bar of tones from left to right, ticks under it at fractions (0 to 1) of its
// length with their labels, a name before it and words under its ends (e.g. "free",
// "occupied"); `extra` (e.g. never observed) a swatch after it.
struct ColourBar {
  std::string name;
  std::vector<Rgb> tones;
  struct Tick {
    double at = 0.0;
    std::string label;
    std::string note;  // under the label, on the row of left_word and right_word (e.g. "prior")
  };
  std::vector<Tick> ticks;
  std::string left_word;
  std::string right_word;
  std::optional<LegendItem> extra;
};

struct Figure {
  int map_w_px = 0;  // the map area, drawn by the caller at map_origin()
  int map_h_px = 0;
  std::optional<Axes> axes;
  std::vector<std::string> lines;  // the caption, then any numbers
  std::vector<LegendItem> items;
  std::optional<ColourBar> bar;
  double px_per_m = 0.0;  // the scale bar's unit; none when 0
};

// The font size, the map area's top-left corner and the page's size.
struct FigureLayout {
  double font_px = 14.0;
  PointPx map_origin;
  int width = 0;
  int height = 0;
};

// A page several figures share: the font and the size.
struct PageFrame {
  double font_px = 14.0;
  int width = 0;
  int height = 0;
};

// The smallest page that holds each of `figures` (which must share their map area's size
// and axes) in one font, that font at least 14 px and a 40th of the page's height: an 18th
// of the map's height (and a 45th of its longer side) for a legend up to 22 font sizes tall,
// larger for a taller one.
PageFrame shared_page(const std::vector<Figure> &figures);

// The figure on its own page (shared_page of it alone), or on `page` (made larger where the
// figure would not fit it at its font: nothing is cut).
FigureLayout layout_figure(const Figure &figure);
FigureLayout layout_figure(const Figure &figure, const PageFrame &page);

// Draws all but the map area's content (axes, legend) on a page of layout's size.
void draw_figure(Drawing &page, const Figure &figure, const FigureLayout &layout);

// A scale bar's length: the largest of 1, 2, 5 x 10^n metres that is at most max_px long at
// px_per_m pixels a metre (and at least 0.001 m).
double scale_bar_length_m(double px_per_m, double max_px);

// The step between labelled indices on an axis whose cells are cell_px apart and whose
// labels need label_px each: 1, 2, 5, 10, 20, 50, ...
int axis_step(double cell_px, double label_px);

}  // namespace app
