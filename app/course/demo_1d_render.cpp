#include "app/course/demo_1d_render.hpp"

#include <cassert>
#include <cmath>
#include <cstddef>
#include <vector>

#include <fmt/format.h>

#include "common/xml_text.hpp"
#include "render/text_format.hpp"

namespace app::course {
namespace {

constexpr std::size_t kYLabelWidth = 4;   // " 0.7"
constexpr std::size_t kPlotLeft = 7;      // label, " +" or " |", one blank margin column

double span_of(std::span<const Demo1dCell> cells) {
  return cells.back().position_cm - cells.front().position_cm;
}

// Plot-area column of a position: 0 for the first cell, kPlotColumns - 1 for the last.
int column_of(double position_cm, double span_cm) {
  if (span_cm <= 0.0) return 0;
  return static_cast<int>(std::lround(position_cm / span_cm * (kPlotColumns - 1)));
}

int row_of(double belief) {
  return static_cast<int>(std::lround(belief * (kPlotRows - 1)));
}

std::vector<double> ticks(double span_cm) {
  if (span_cm <= 0.0) return {0.0};
  const double step = tick_step(span_cm);
  std::vector<double> result;
  for (int i = 0; i * step <= span_cm * (1.0 + 1e-9); ++i) result.push_back(i * step);
  return result;
}

// The plot area as text rows, row 0 at the top (belief 1).
std::vector<std::string> plot_area(std::span<const Demo1dCell> cells) {
  std::vector<std::string> rows(kPlotRows, std::string(kPlotColumns, ' '));
  const double span = span_of(cells);
  for (const Demo1dCell &cell : cells) {
    const auto column = static_cast<std::size_t>(column_of(cell.position_cm, span));
    const auto row = static_cast<std::size_t>(kPlotRows - 1 - row_of(cell.belief));
    rows[row][column] = '*';
  }
  return rows;
}

// " 1.0 +" on the rows of 0.0, 0.1, ..., 1.0; "     |" in between.
std::string y_axis(int row_from_top) {
  const int row_from_bottom = kPlotRows - 1 - row_from_top;
  if (row_from_bottom % 2 != 0) return std::string(kYLabelWidth + 1, ' ') + "|";
  return fmt::format("{:>{}} +", render::fixed(row_from_bottom / 20.0, 1), kYLabelWidth);
}

std::string x_axis_line(double span_cm) {
  std::string line = std::string(kYLabelWidth + 1, ' ') + "+" + std::string(kPlotColumns + 2, '-');
  for (const double tick : ticks(span_cm)) {
    line[kPlotLeft + static_cast<std::size_t>(column_of(tick, span_cm))] = '+';
  }
  return line;
}

// Tick labels centred under their ticks; a label that would touch the previous one is left out.
std::string x_labels(double span_cm) {
  std::string line;
  for (const double tick : ticks(span_cm)) {
    const std::string label = render::short_number(tick);
    const std::size_t centre = kPlotLeft + static_cast<std::size_t>(column_of(tick, span_cm));
    const std::size_t start = centre - std::min(centre, (label.size() - 1) / 2);
    if (!line.empty() && start <= line.size()) continue;
    line += std::string(start - line.size(), ' ') + label;
  }
  return line;
}

std::string centred(const std::string &text) {
  const std::size_t columns = kPlotColumns;
  const std::size_t pad = text.size() < columns ? (columns - text.size()) / 2 : 0;
  return std::string(kPlotLeft + pad, ' ') + text;
}

// SVG layout, in px: the plot area and its margins.
struct SvgFrame {
  double left = 70, top = 40, width = 560, height = 300;
  double x(double position_cm, double span_cm) const {
    return left + (span_cm > 0.0 ? position_cm / span_cm : 0.0) * width;
  }
  double y(double belief) const { return top + (1.0 - belief) * height; }
};

std::string svg_axes(const SvgFrame &f, double span_cm) {
  std::string out;
  for (int i = 0; i <= 10; ++i) {
    const double y = f.y(i / 10.0);
    out += fmt::format(R"(  <line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" stroke="#ddd"/>)"
                       "\n", f.left, y, f.left + f.width, y);
    out += fmt::format(R"(  <text x="{:.2f}" y="{:.2f}" text-anchor="end">{}</text>)" "\n",
                       f.left - 8, y + 4, render::fixed(i / 10.0, 1));
  }
  for (const double tick : ticks(span_cm)) {
    const double x = f.x(tick, span_cm);
    out += fmt::format(R"(  <line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" stroke="#000"/>)"
                       "\n", x, f.top + f.height, x, f.top + f.height + 5);
    out += fmt::format(R"(  <text x="{:.2f}" y="{:.2f}" text-anchor="middle">{}</text>)" "\n",
                       x, f.top + f.height + 20, render::short_number(tick));
  }
  out += fmt::format(R"(  <rect x="{:.2f}" y="{:.2f}" width="{:.2f}" height="{:.2f}" fill="none" stroke="#000"/>)"
                     "\n", f.left, f.top, f.width, f.height);
  out += fmt::format(R"(  <text x="{:.2f}" y="{:.2f}" text-anchor="middle">position (cm)</text>)"
                     "\n", f.left + f.width / 2, f.top + f.height + 42);
  out += fmt::format(R"svg(  <text x="18" y="{:.2f}" text-anchor="middle" transform="rotate(-90 18 {:.2f})">belief p</text>)svg"
                     "\n", f.top + f.height / 2, f.top + f.height / 2);
  return out;
}

std::string svg_points(const SvgFrame &f, std::span<const Demo1dCell> cells) {
  const double span = span_of(cells);
  std::string polyline = R"(  <polyline fill="none" stroke="#1f77b4" stroke-width="1.5" points=")";
  std::string circles;
  for (const Demo1dCell &cell : cells) {
    const double x = f.x(cell.position_cm, span);
    const double y = f.y(cell.belief);
    polyline += fmt::format("{}{:.2f},{:.2f}", &cell == &cells.front() ? "" : " ", x, y);
    circles += fmt::format(R"(  <circle cx="{:.2f}" cy="{:.2f}" r="3.5" fill="#1f77b4"><title>{} cm: {}</title></circle>)"
                           "\n", x, y, render::short_number(cell.position_cm), render::fixed(cell.belief, 4));
  }
  return polyline + "\"/>\n" + circles;
}

}  // namespace

double tick_step(double span_cm) {
  assert(span_cm > 0.0);
  double magnitude = std::pow(10.0, std::floor(std::log10(span_cm / 10.0)));
  for (;;) {
    for (const double factor : {1.0, 2.0, 5.0}) {
      if (span_cm / (factor * magnitude) <= 10.0 * (1.0 + 1e-9)) return factor * magnitude;
    }
    magnitude *= 10.0;
  }
}

std::string demo_1d_table(std::span<const Demo1dCell> cells) {
  std::string out = fmt::format("{:>9}  {:>9}  {:>8}  {:>4}  {:>8}\n", "cell (cm)", "log-odds",
                                "belief p", "free", "occupied");
  for (const Demo1dCell &cell : cells) {
    out += fmt::format("{:>9}  {:>9}  {:>8}  {:>4}  {:>8}\n", render::short_number(cell.position_cm),
                       render::fixed(cell.log_odds, 4), render::fixed(cell.belief, 4), cell.free_updates,
                       cell.occupied_updates);
  }
  return out;
}

std::string ascii_belief_plot(std::span<const Demo1dCell> cells) {
  assert(!cells.empty());
  const double span = span_of(cells);
  std::string out = "belief p\n";
  const std::vector<std::string> rows = plot_area(cells);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::string line = y_axis(static_cast<int>(r)) + " " + rows[r];
    line.erase(line.find_last_not_of(' ') + 1);
    out += line + "\n";
  }
  out += x_axis_line(span) + "\n";
  out += x_labels(span) + "\n";
  out += centred("position (cm)") + "\n";
  return out;
}

std::string svg_belief_plot(std::span<const Demo1dCell> cells, const std::string &title) {
  assert(!cells.empty());
  const SvgFrame frame;
  std::string out = R"(<?xml version="1.0" encoding="UTF-8"?>)" "\n";
  out += R"(<svg xmlns="http://www.w3.org/2000/svg" width="660" height="400" viewBox="0 0 660 400" font-family="sans-serif" font-size="12">)" "\n";
  out += R"(  <rect width="660" height="400" fill="#fff"/>)" "\n";
  out += fmt::format(R"(  <text x="{:.2f}" y="24" text-anchor="middle" font-size="14">{}</text>)" "\n",
                     frame.left + frame.width / 2, common::xml_escaped(title));
  out += svg_axes(frame, span_of(cells));
  out += svg_points(frame, cells);
  out += "</svg>\n";
  return out;
}

}  // namespace app::course
