#include "render/ascii_map.hpp"

#include <algorithm>
#include <cassert>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "mapping/walls.hpp"

namespace render {

using mapping::Cell;
using mapping::LocalSubCell;

const char *arrow(mapping::Heading h, bool ascii) {
  switch (h) {
    case mapping::Heading::north: return ascii ? "^" : "\u2191";
    case mapping::Heading::east: return ascii ? ">" : "\u2192";
    case mapping::Heading::south: return ascii ? "v" : "\u2193";
    case mapping::Heading::west: return ascii ? "<" : "\u2190";
  }
  return "?";
}

namespace {

constexpr const char *kReset = "\x1b[0m";
constexpr const char *kWallColor = "\x1b[1;34m";
constexpr const char *kUnknownColor = "\x1b[48;5;236m";
constexpr const char *kArrowColor = "\x1b[32m";
constexpr const char *kRobotColor = "\x1b[1;31m";

enum class Glyph { plain, wall, unknown, arrow, robot };

// The text of one sub-cell, `subcell_columns` wide: one-column text doubled, except an
// arrow or the robot, which a blank follows.
void put_text(std::string &out, const MapStyle &style, Glyph kind, std::string_view text) {
  out += text;
  for (int extra = 1; extra < style.subcell_columns; ++extra) {
    out += (kind == Glyph::arrow || kind == Glyph::robot) ? std::string_view(" ") : text;
  }
}

void put(std::string &out, const MapStyle &style, Glyph kind, std::string_view text) {
  if (!style.color || kind == Glyph::plain) {
    put_text(out, style, kind, text);
    return;
  }
  switch (kind) {
    case Glyph::wall: out += kWallColor; break;
    case Glyph::unknown: out += kUnknownColor; break;
    case Glyph::arrow: out += kArrowColor; break;
    case Glyph::robot: out += kRobotColor; break;
    case Glyph::plain: break;
  }
  put_text(out, style, kind, text);
  out += kReset;
}

void put_subcell(std::string &out, const mapping::OccupancyGrid &grid, const explore::Visits &visits,
                 const MapStyle &style, int row, int col) {
  const int k = grid.k();
  const int mid = k / 2;
  const Cell c{col / k, grid.height() - 1 - row / k};
  const LocalSubCell s{row % k, col % k};
  if (style.robot && style.robot->at == mapping::to_global(c, s, k)) {
    put(out, style, Glyph::robot, style.robot->glyph);
    return;
  }
  if (style.path != nullptr && (*style.path)[grid.index(c, s)]) {
    put(out, style, Glyph::plain, "*");
    return;
  }
  if (s.i == mid && s.j == mid) {
    if (const auto h = visits.heading(c)) {
      put(out, style, Glyph::arrow, arrow(*h, style.ascii));
      return;
    }
  }
  const float v = grid.at(c, s);
  if (!mapping::observed(v, style.initial_log_odds)) {
    const char blank = style.unknown.value_or(' ');
    put(out, style, Glyph::unknown, std::string_view(&blank, 1));
  } else if (mapping::is_occupied(v, style.threshold)) {
    put(out, style, Glyph::wall, "W");
  } else {
    put(out, style, Glyph::plain, " ");
  }
}

}  // namespace

MapWindow window_around(const mapping::OccupancyGrid &grid, mapping::SubCell at, int rows, int cols) {
  const int map_rows = grid.height() * grid.k();
  const int map_cols = grid.width() * grid.k();
  const int row_count = std::clamp(rows, 1, map_rows);
  const int col_count = std::clamp(cols, 1, map_cols);
  const int at_row = map_rows - 1 - at.y;  // rows count from the north
  return {std::clamp(at_row - row_count / 2, 0, map_rows - row_count), row_count,
          std::clamp(at.x - col_count / 2, 0, map_cols - col_count), col_count};
}

void render_window(std::string &out, const mapping::OccupancyGrid &grid,
                   const explore::Visits &visits, const MapStyle &style, const MapWindow &w) {
  [[maybe_unused]] const int k = grid.k();
  assert(w.first_row >= 0 && w.row_count >= 0 && w.first_row + w.row_count <= grid.height() * k);
  assert(w.first_col >= 0 && w.col_count >= 0 && w.first_col + w.col_count <= grid.width() * k);
  out.reserve(out.size() + static_cast<std::size_t>(w.row_count) *
                               (static_cast<std::size_t>(w.col_count * style.subcell_columns) + 1));
  for (int row = w.first_row; row < w.first_row + w.row_count; ++row) {
    for (int col = w.first_col; col < w.first_col + w.col_count; ++col) {
      put_subcell(out, grid, visits, style, row, col);
    }
    out += '\n';
  }
}

void render_rows(std::string &out, const mapping::OccupancyGrid &grid, const explore::Visits &visits,
                 const MapStyle &style, int first_row, int row_count) {
  render_window(out, grid, visits, style,
                MapWindow{first_row, row_count, 0, grid.width() * grid.k()});
}

std::string render_map(const mapping::OccupancyGrid &grid, const explore::Visits &visits,
                       const MapStyle &style) {
  std::string out;
  render_rows(out, grid, visits, style, 0, grid.height() * grid.k());
  return out;
}

std::string format_cell_matrix(const mapping::OccupancyGrid &grid, Cell c) {
  const int k = grid.k();
  std::vector<std::string> cells;
  cells.reserve(static_cast<std::size_t>(k * k));
  std::size_t width = 0;
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) {
      std::string text = fmt::format("{:+.2f}", grid.at(c, LocalSubCell{i, j}));
      if (text == "-0.00") text = "+0.00";
      cells.push_back(std::move(text));
      width = std::max(width, cells.back().size());
    }
  }
  std::string out;
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) {
      if (j > 0) out += ' ';
      out += fmt::format("{:>{}}", cells[static_cast<std::size_t>(i * k + j)], width);
    }
    out += '\n';
  }
  return out;
}

std::string format_status(long step, Cell c, mapping::Heading h, int visited, int total) {
  return fmt::format("step {}  cell ({},{})  heading {}  visited {}/{}", step, c.x, c.y,
                     mapping::to_char(h), visited, total);
}

}  // namespace render
