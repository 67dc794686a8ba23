#include "render/ascii_map.hpp"

#include <algorithm>
#include <cassert>
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

void render_rows(std::string &out, const mapping::OccupancyGrid &grid, const explore::Visits &visits,
                 const MapStyle &style, int first_row, int row_count) {
  const int k = grid.k();
  const int mid = k / 2;
  assert(first_row >= 0 && row_count >= 0 && first_row + row_count <= grid.height() * k);
  out.reserve(out.size() + static_cast<std::size_t>(row_count) *
                               (static_cast<std::size_t>(grid.width() * k) + 1));
  for (int row = first_row; row < first_row + row_count; ++row) {
    const int y = grid.height() - 1 - row / k;
    const int i = row % k;
    for (int x = 0; x < grid.width(); ++x) {
      const Cell c{x, y};
      for (int j = 0; j < k; ++j) {
        if (style.path != nullptr && (*style.path)[grid.index(c, LocalSubCell{i, j})]) {
          out += '*';
          continue;
        }
        if (i == mid && j == mid) {
          if (const auto h = visits.heading(c)) {
            out += arrow(*h, style.ascii);
            continue;
          }
        }
        const float v = grid.at(c, LocalSubCell{i, j});
        if (!mapping::observed(v, style.initial_log_odds)) {
          out += style.unknown.value_or(' ');
        } else {
          out += mapping::is_occupied(v, style.threshold) ? 'W' : ' ';
        }
      }
    }
    out += '\n';
  }
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
