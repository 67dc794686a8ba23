#include "app/picture/figure.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace app {
namespace {

double padding(double f) { return f; }
double tick_px(double f) { return 0.35 * f; }
double axis_font(double f) { return 0.85 * f; }
double row_px(double f) { return 1.5 * f; }
double swatch_px(double f) { return f; }
double bar_px(double f) { return 24.0 * f; }

double item_width(const LegendItem &item, double f) { return swatch_px(f) + 0.4 * f + text_width(item.label, f) + 1.2 * f; }

// The widest y label (the axis's largest index), or 0 without axes.
double y_label_width(const Figure &fig, double f) {
  if (!fig.axes) return 0.0;
  const Axes &a = *fig.axes;
  return std::max(text_width(std::to_string(a.first_y), axis_font(f)),
                  text_width(std::to_string(a.first_y + a.rows - 1), axis_font(f)));
}

double x_label_width(const Figure &fig, double f) {
  if (!fig.axes) return 0.0;
  const Axes &a = *fig.axes;
  return std::max(text_width(std::to_string(a.first_x), axis_font(f)),
                  text_width(std::to_string(a.first_x + a.columns - 1), axis_font(f)));
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

void draw_axes(Drawing &page, const Axes &a, const FigureLayout &l, const Figure &fig) {
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

FigureLayout layout_figure(const Figure &fig) {
  FigureLayout l;
  const double f = std::round(std::max(14.0, std::max(fig.map_w_px, fig.map_h_px) / 45.0));
  l.font_px = f;
  l.map_origin = {std::round(left_margin(fig, f)), std::round(top_margin(fig, f))};
  double width = l.map_origin.x + fig.map_w_px + (fig.axes ? 1.5 * f : padding(f));
  for (const std::string &line : fig.lines) width = std::max(width, 2 * padding(f) + text_width(line, f));
  for (const LegendItem &item : fig.items) width = std::max(width, 2 * padding(f) + item_width(item, f));
  if (fig.bar) width = std::max(width, 2 * padding(f) + bar_row_width(*fig.bar, f));
  if (fig.px_per_m > 0.0) width = std::max(width, 2 * padding(f) + 8 * f);
  l.width = static_cast<int>(std::ceil(width));
  double y = l.map_origin.y + fig.map_h_px + x_axis_height(fig, f) + 0.5 * padding(f);
  y += row_px(f) * static_cast<double>(fig.lines.size());
  double next = y;
  place_items(fig.items, l.width, f, y, next);
  y = next;
  if (fig.bar) y += bar_block_height(f);
  if (fig.px_per_m > 0.0) y += row_px(f);
  l.height = static_cast<int>(std::ceil(y + 0.5 * padding(f)));
  return l;
}

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
