#include "app/picture/figure.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace app {
namespace {

double padding(double f) { return f; }
double tick_px(double f) { return 0.35 * f; }
double axis_font(double f) { return f; }
double row_px(double f) { return 1.5 * f; }
double swatch_px(double f) { return f; }
double bar_px(double f) { return 16.0 * f; }

double item_width(const LegendItem &item, double f) { return swatch_px(f) + 0.4 * f + text_width(item.label, f) + 1.2 * f; }

bool in_metres(const Axes &a) { return a.px_per_m > 0.0; }

// A label in metres: "1.5", "-2", "0".
std::string metres_label(double m) { return fmt::format("{:g}", std::abs(m) < 1e-9 ? 0.0 : m); }

// The extent the axes cover, in metres, from `first_m` over `length_px`.
double last_m(double first_m, double length_px, const Axes &a) { return first_m + length_px / a.px_per_m; }

// The widest y label (the axis's largest index, or metre), or 0 without axes.
double y_label_width(const Figure &fig, double f) {
  if (!fig.axes) return 0.0;
  const Axes &a = *fig.axes;
  if (in_metres(a)) {
    const double top_m = last_m(a.y0_m, fig.map_h_px - 2 * a.offset_px, a);
    return std::max({text_width(metres_label(a.y0_m), axis_font(f)), text_width(metres_label(top_m), axis_font(f)),
                     text_width("-0.5", axis_font(f))});
  }
  return std::max(text_width(std::to_string(a.first_y), axis_font(f)),
                  text_width(std::to_string(a.first_y + a.rows - 1), axis_font(f)));
}

double x_label_width(const Figure &fig, double f) {
  if (!fig.axes) return 0.0;
  const Axes &a = *fig.axes;
  if (in_metres(a)) {
    const double right_m = last_m(a.x0_m, fig.map_w_px - 2 * a.offset_px, a);
    return std::max({text_width(metres_label(a.x0_m), axis_font(f)), text_width(metres_label(right_m), axis_font(f)),
                     text_width("-0.5", axis_font(f))});
  }
  return std::max(text_width(std::to_string(a.first_x), axis_font(f)),
                  text_width(std::to_string(a.first_x + a.columns - 1), axis_font(f)));
}

// The step between labelled metres: the least of 0.1, 0.2, 0.5, 1, 2, 5 ... whose labels are
// label_px apart at least.
double metre_step(double px_per_m, double label_px) {
  for (double decade = 0.1;; decade *= 10.0) {
    for (const double step : {1.0, 2.0, 5.0}) {
      if (step * decade * px_per_m >= label_px || decade > 1e5) return step * decade;
    }
  }
}

// Each round metre from first_m to last_m (a step apart) and its distance from first_m in px.
template <typename Each>
void for_each_metre(double first_m, double end_m, double step_m, double px_per_m, Each each) {
  for (double k = std::ceil(first_m / step_m - 1e-9); k * step_m <= end_m + 1e-9; k += 1.0) {
    each(metres_label(k * step_m), (k * step_m - first_m) * px_per_m);
  }
}

double left_margin(const Figure &fig, double f) {
  return padding(f) + (fig.axes ? y_label_width(fig, f) + tick_px(f) + 0.3 * f : 0.0);
}

double top_margin(const Figure &fig, double f) { return padding(f) + (fig.axes ? 1.3 * axis_font(f) : 0.0); }

// The x labels' row under the map area.
double x_axis_height(const Figure &fig, double f) { return fig.axes ? tick_px(f) + 1.6 * axis_font(f) : 0.0; }

double bar_row_width(const ColourBar &bar, double f) {
  double w = text_width(bar.name, f) + 0.6 * f + bar_px(f) + 0.8 * f;
  if (bar.extra) w += item_width(*bar.extra, f);
  return w;
}

double bar_block_height(double f) { return f + 0.3 * f + 1.3 * axis_font(f) + 1.3 * axis_font(f) + 0.4 * f; }

struct Placed {
  double x = 0.0;
  double y = 0.0;  // the row's top
};

// Where each legend item goes from row top `top` in a page `width` wide; the top after them.
std::vector<Placed> place_items(const std::vector<LegendItem> &items, double width, double f, double top,
                                double &next_top) {
  std::vector<Placed> at;
  double x = padding(f);
  double y = top;
  for (const LegendItem &item : items) {
    if (x > padding(f) && x + item_width(item, f) > width - padding(f)) {
      x = padding(f);
      y += row_px(f);
    }
    at.push_back({x, y});
    x += item_width(item, f);
  }
  next_top = y + (items.empty() ? 0.0 : row_px(f));
  return at;
}

void draw_swatch(Drawing &page, const LegendItem &item, PointPx top_left, double f) {
  const double s = swatch_px(f);
  const PointPx centre{top_left.x + s / 2, top_left.y + s / 2};
  switch (item.swatch) {
    case Swatch::box:
      page.fill_rect({top_left.x, top_left.y, s, s}, item.colour);
      page.stroke_rect({top_left.x, top_left.y, s, s}, 1.0, kInk);
      break;
    case Swatch::line:
      page.polyline({{top_left.x, centre.y}, {top_left.x + s, centre.y}}, std::max(2.0, s / 5), item.colour);
      break;
    case Swatch::square: page.fill_rect({top_left.x + s / 5, top_left.y + s / 5, 0.6 * s, 0.6 * s}, item.colour); break;
    case Swatch::disc: page.disc(centre, 0.35 * s, item.colour); break;
    case Swatch::frame:
      page.stroke_rect({top_left.x + s / 10, top_left.y + s / 10, 0.8 * s, 0.8 * s}, std::max(2.0, s / 6), item.colour);
      break;
    case Swatch::ring: page.ringed_disc(centre, 0.3 * s, kWhite, std::max(2.0, s / 8), item.colour); break;
  }
}

// The row's text baseline for a row whose top is `top`.
double baseline(double top, double f) { return top + 0.5 * f + 0.5 * (text_ascent(f) - text_descent(f)); }

void draw_item(Drawing &page, const LegendItem &item, Placed at, double f) {
  const double top = at.y + (row_px(f) - swatch_px(f)) / 2;
  draw_swatch(page, item, {at.x, top}, f);
  page.text({at.x + swatch_px(f) + 0.4 * f, baseline(top, f)}, item.label, f, kInk);
}

void draw_metre_axes(Drawing &page, const Axes &a, const FigureLayout &l, const Figure &fig) {
  const double f = l.font_px;
  const double af = axis_font(f);
  const double left = l.map_origin.x + a.offset_px;
  const double bottom = l.map_origin.y + fig.map_h_px - a.offset_px;
  const double width_px = fig.map_w_px - 2 * a.offset_px;
  const double height_px = fig.map_h_px - 2 * a.offset_px;
  const double axis_y = l.map_origin.y + fig.map_h_px;
  const double x_step = metre_step(a.px_per_m, x_label_width(fig, f) + 0.8 * af);
  for_each_metre(a.x0_m, last_m(a.x0_m, width_px, a), x_step, a.px_per_m, [&](const std::string &label, double dx) {
    page.fill_rect({left + dx - 0.5, axis_y, 1.0, tick_px(f)}, kInk);
    page.text({left + dx, axis_y + tick_px(f) + af}, label, af, kInk, Align::centre);
  });
  page.text({l.map_origin.x + fig.map_w_px + 0.9 * f, axis_y + tick_px(f) + af}, "x (m)", af, kInk);
  const double y_step = metre_step(a.px_per_m, 1.3 * af);
  for_each_metre(a.y0_m, last_m(a.y0_m, height_px, a), y_step, a.px_per_m, [&](const std::string &label, double dy) {
    page.fill_rect({l.map_origin.x - tick_px(f), bottom - dy - 0.5, tick_px(f), 1.0}, kInk);
    page.text({l.map_origin.x - tick_px(f) - 0.3 * f, bottom - dy + 0.35 * af}, label, af, kInk, Align::right);
  });
  // Above the top label (which reaches about 0.4 of a font size over the map's top edge).
  page.text({l.map_origin.x - tick_px(f) - 0.3 * f, l.map_origin.y - 0.9 * af}, "y (m)", af, kInk, Align::left);
}

void draw_axes(Drawing &page, const Axes &a, const FigureLayout &l, const Figure &fig) {
  if (in_metres(a)) {
    draw_metre_axes(page, a, l, fig);
    return;
  }
  const double f = l.font_px;
  const double af = axis_font(f);
  const double left = l.map_origin.x;
  const double top = l.map_origin.y;
  const double bottom = top + fig.map_h_px;
  const int x_step = axis_step(a.cell_px, x_label_width(fig, f) + 0.8 * af);
  for (int i = 0; i < a.columns; ++i) {
    const int index = a.first_x + i;
    if (index % x_step != 0) continue;
    const double x = left + a.offset_px + a.cell_px * (i + 0.5);
    page.fill_rect({x - 0.5, bottom, 1.0, tick_px(f)}, kInk);
    page.text({x, bottom + tick_px(f) + af}, std::to_string(index), af, kInk, Align::centre);
  }
  page.text({left + fig.map_w_px + 0.4 * f, bottom + tick_px(f) + af}, "x", af, kInk);
  const int y_step = axis_step(a.cell_px, 1.3 * af);
  for (int j = 0; j < a.rows; ++j) {
    const int index = a.first_y + j;
    if (index % y_step != 0) continue;
    const double y = top + a.offset_px + a.cell_px * (a.rows - j - 0.5);
    page.fill_rect({left - tick_px(f), y - 0.5, tick_px(f), 1.0}, kInk);
    page.text({left - tick_px(f) - 0.3 * f, y + 0.35 * af}, std::to_string(index), af, kInk, Align::right);
  }
  page.text({left - tick_px(f) - 0.3 * f, top - 0.4 * af}, "y", af, kInk, Align::right);
}

void draw_bar(Drawing &page, const ColourBar &bar, double top, double f) {
  const double af = axis_font(f);
  double x = padding(f);
  page.text({x, baseline(top, f)}, bar.name, f, kInk);
  x += text_width(bar.name, f) + 0.6 * f;
  const double w = bar_px(f);
  const double bar_top = top + (row_px(f) - f) / 2;
  const auto n = static_cast<int>(bar.tones.size());
  page.blocks(bar.tones, n, 1, {x, bar_top}, w / n, f);
  page.stroke_rect({x, bar_top, w, f}, 1.0, kInk);
  const double under = bar_top + f;
  for (const ColourBar::Tick &t : bar.ticks) {
    const double tx = x + t.at * w;
    page.fill_rect({tx - 0.5, under, 1.0, 0.3 * f}, kInk);
    page.text({tx, under + 0.3 * f + af}, t.label, af, kInk, Align::centre);
  }
  const double words = under + 0.3 * f + 2.3 * af;
  for (const ColourBar::Tick &t : bar.ticks) {
    if (!t.note.empty()) page.text({x + t.at * w, words}, t.note, af, kInk, Align::centre);
  }
  page.text({x, words}, bar.left_word, af, kInk, Align::left);
  page.text({x + w, words}, bar.right_word, af, kInk, Align::right);
  if (bar.extra) draw_item(page, *bar.extra, {x + w + 0.8 * f, top}, f);
}

void draw_scale_bar(Drawing &page, double px_per_m, double top, double f, double max_px) {
  const double metres = scale_bar_length_m(px_per_m, max_px);
  const double length = metres * px_per_m;
  const double x = padding(f);
  const double mid = top + row_px(f) / 2;
  const double t = std::max(2.0, f / 7);
  page.fill_rect({x, mid - t / 2, length, t}, kInk);
  page.fill_rect({x, mid - f / 2, t, f}, kInk);
  page.fill_rect({x + length - t, mid - f / 2, t, f}, kInk);
  page.text({x + length + 0.5 * f, baseline(top, f)}, fmt::format("{:g} m", metres), f, kInk);
}

}  // namespace

double scale_bar_length_m(double px_per_m, double max_px) {
  double best = 0.001;
  for (double decade = 0.001; decade <= 1e6; decade *= 10.0) {
    for (const double step : {1.0, 2.0, 5.0}) {
      if (step * decade * px_per_m <= max_px) best = step * decade;
    }
  }
  return best;
}

int axis_step(double cell_px, double label_px) {
  for (int decade = 1;; decade *= 10) {
    for (const int step : {1, 2, 5}) {
      if (step * decade * cell_px >= label_px || decade > 100000) return step * decade;
    }
  }
}

namespace {

// The width the figure needs at font f.
double natural_width(const Figure &fig, double f) {
  const double origin_x = std::round(left_margin(fig, f));
  const double right = !fig.axes ? padding(f) : in_metres(*fig.axes) ? 4.4 * f : 1.5 * f;  // room for "x" or "x (m)"
  double width = origin_x + fig.map_w_px + right;
  for (const std::string &line : fig.lines) width = std::max(width, 2 * padding(f) + text_width(line, f));
  for (const LegendItem &item : fig.items) width = std::max(width, 2 * padding(f) + item_width(item, f));
  if (fig.bar) width = std::max(width, 2 * padding(f) + bar_row_width(*fig.bar, f));
  if (fig.px_per_m > 0.0) width = std::max(width, 2 * padding(f) + 8 * f);
  return std::ceil(width);
}

// The height the figure needs at font f on a page `width` wide (its legend wrapped to it).
double natural_height(const Figure &fig, double f, double width) {
  double y = std::round(top_margin(fig, f)) + fig.map_h_px + x_axis_height(fig, f) + 0.5 * padding(f);
  y += row_px(f) * static_cast<double>(fig.lines.size());
  double next = y;
  place_items(fig.items, width, f, y, next);
  y = next;
  if (fig.bar) y += bar_block_height(f);
  if (fig.px_per_m > 0.0) y += row_px(f);
  return std::ceil(y + 0.5 * padding(f));
}

}  // namespace

PageFrame shared_page(const std::vector<Figure> &figures) {
  int map_h = 0;
  int map_side = 0;
  for (const Figure &fig : figures) {
    map_h = std::max(map_h, fig.map_h_px);
    map_side = std::max({map_side, fig.map_w_px, fig.map_h_px});
  }
  // From an 18th of the map's height (a legend up to 22 font sizes tall then keeps the text a
  // 40th of the page, so the font, and with it the map's place, depends on the map alone) and
  // a 45th of its longer side, up until the text is a 40th of the page's height.
  for (double f = std::round(std::max({14.0, map_h / 18.0, map_side / 45.0}));; f += 1.0) {
    PageFrame page{f, 0, 0};
    for (const Figure &fig : figures) page.width = std::max(page.width, static_cast<int>(natural_width(fig, f)));
    for (const Figure &fig : figures) {
      page.height = std::max(page.height, static_cast<int>(natural_height(fig, f, page.width)));
    }
    if (40.0 * f >= page.height || f > 4096.0) return page;
  }
}

FigureLayout layout_figure(const Figure &fig, const PageFrame &page) {
  FigureLayout l;
  const double f = page.font_px;
  l.font_px = f;
  l.map_origin = {std::round(left_margin(fig, f)), std::round(top_margin(fig, f))};
  // A figure wider or taller than the page is never cut.
  l.width = std::max(page.width, static_cast<int>(natural_width(fig, f)));
  l.height = std::max(page.height, static_cast<int>(natural_height(fig, f, l.width)));
  return l;
}

FigureLayout layout_figure(const Figure &fig) { return layout_figure(fig, shared_page({fig})); }

void draw_figure(Drawing &page, const Figure &fig, const FigureLayout &l) {
  const double f = l.font_px;
  if (fig.axes) draw_axes(page, *fig.axes, l, fig);
  double y = l.map_origin.y + fig.map_h_px + x_axis_height(fig, f) + 0.5 * padding(f);
  for (const std::string &line : fig.lines) {
    page.text({padding(f), baseline(y, f)}, line, f, kInk);
    y += row_px(f);
  }
  double next = y;
  const std::vector<Placed> at = place_items(fig.items, l.width, f, y, next);
  for (std::size_t i = 0; i < fig.items.size(); ++i) draw_item(page, fig.items[i], at[i], f);
  y = next;
  if (fig.bar) {
    draw_bar(page, *fig.bar, y, f);
    y += bar_block_height(f);
  }
  if (fig.px_per_m > 0.0) draw_scale_bar(page, fig.px_per_m, y, f, l.width / 3.0);
}

}  // namespace app
