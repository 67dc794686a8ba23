#include "maze/formats/num_format.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "line_tokens.hpp"
#include "maze/world/validate.hpp"

namespace maze {

namespace {

constexpr const char *kFieldNames[] = {"X", "Y", "N", "E", "S", "W"};

struct Entry {
  std::size_t offset;   // where the line starts in the text
  std::uint16_t x, y;
  std::uint8_t walls;   // bit s: wall on side s
};

struct NumParser {
  std::string_view text;
  const std::string &file;

  common::InputError error(int line, std::size_t column, std::string message) const {
    return common::InputError(common::SourceLocation{file, line, static_cast<int>(column + 1)}, std::move(message));
  }

  int field(const LineToken &t, int index, int line, int limit) const {
    int value = 0;
    const char *begin = t.text.data();
    const char *end = begin + t.text.size();
    const auto [stop, ec] = std::from_chars(begin, end, value);
    if (stop != end || ec == std::errc::invalid_argument) {
      throw error(line, t.column, fmt::format("{} is not an integer: '{}'", kFieldNames[index], shown_token(t.text)));
    }
    if (ec == std::errc() && value >= 0 && value < limit) return value;
    if (index < 2) {
      throw error(line, t.column, fmt::format("{} must be 0 to {}, got {}", kFieldNames[index], limit - 1, shown_token(t.text)));
    }
    throw error(line, t.column, fmt::format("{} must be 0 or 1, got {}", kFieldNames[index], shown_token(t.text)));
  }

  Entry entry(std::string_view line, std::size_t offset, int line_number) const {
    const auto tokens = line_tokens(line, 7);
    Entry e{offset, 0, 0, 0};
    for (std::size_t i = 0; i < std::min<std::size_t>(tokens.size(), 6); ++i) {
      const int index = static_cast<int>(i);
      const int value = field(tokens[i], index, line_number, index < 2 ? kMaxMazeSide : 2);
      if (index == 0) e.x = static_cast<std::uint16_t>(value);
      if (index == 1) e.y = static_cast<std::uint16_t>(value);
      if (index >= 2 && value != 0) e.walls = static_cast<std::uint8_t>(e.walls | (1u << (index - 2)));
    }
    if (tokens.size() != 6) {
      const std::size_t column = tokens.size() > 6 ? tokens[6].column : line.size();
      throw error(line_number, column,
                  fmt::format("expected 6 integers 'X Y N E S W', got {}",
                              tokens.size() > 6 ? "more" : std::to_string(tokens.size())));
    }
    return e;
  }

  std::vector<Entry> entries() const {
    std::vector<Entry> out;
    std::size_t offset = 0;
    int line_number = 0;
    while (offset < text.size()) {
      const std::size_t end = std::min(text.find('\n', offset), text.size());
      std::string_view line = text.substr(offset, end - offset);
      ++line_number;
      if (line.ends_with('\r')) line.remove_suffix(1);
      if (line.find_first_not_of(" \t") != std::string_view::npos) out.push_back(entry(line, offset, line_number));
      offset = end + 1;
    }
    return out;
  }

  int line_of(std::size_t offset) const {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
  }

  std::string_view line_at(std::size_t offset) const {
    const std::size_t end = std::min(text.find('\n', offset), text.size());
    return text.substr(offset, end - offset);
  }
};

bool before(const Entry &a, const Entry &b) { return a.y != b.y ? a.y < b.y : a.x < b.x; }

// Rectangular: every cell of the W x H rectangle exactly once.
void check_every_cell_once(const NumParser &p, std::vector<Entry> &entries) {
  if (entries.empty()) throw common::InputError(common::SourceLocation{p.file, 0, 0}, "no cells: expected lines 'X Y N E S W'");
  std::stable_sort(entries.begin(), entries.end(), before);
  for (std::size_t i = 1; i < entries.size(); ++i) {
    const Entry &a = entries[i - 1];
    const Entry &b = entries[i];
    if (a.x == b.x && a.y == b.y) {
      const Entry &later = a.offset > b.offset ? a : b;
      const Entry &first = a.offset > b.offset ? b : a;
      throw p.error(p.line_of(later.offset), 0,
                    fmt::format("cell ({},{}) listed twice; the first is on line {}", b.x, b.y, p.line_of(first.offset)));
    }
  }
  int width = 0;
  int height = 0;
  for (const Entry &e : entries) {
    width = std::max(width, e.x + 1);
    height = std::max(height, e.y + 1);
  }
  std::size_t i = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x, ++i) {
      if (i < entries.size() && entries[i].x == x && entries[i].y == y) continue;
      throw common::InputError(common::SourceLocation{p.file, 0, 0},
                               fmt::format("cell ({},{}) is missing; the cells listed span {}x{}", x, y, width, height));
    }
  }
}

}  // namespace

Maze read_num(std::string_view text, const std::string &file) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 BOM, as the text map and XML take it
  const NumParser parser{text, file};
  auto entries = std::make_shared<std::vector<Entry>>(parser.entries());
  check_every_cell_once(parser, *entries);

  RawMaze raw;
  raw.resize(entries->back().x + 1, entries->back().y + 1);
  for (const Entry &e : *entries) {
    for (const Side s : kSides) raw.set({e.x, e.y}, s, (e.walls >> static_cast<int>(s) & 1u) != 0);
  }
  raw.start_where = {file, 0, 0};
  const int width = raw.width;
  raw.where = [parser, entries, width](Cell c, Side s) {
    const Entry &e = (*entries)[static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width) +
                                static_cast<std::size_t>(c.x)];
    const auto tokens = line_tokens(parser.line_at(e.offset), 7);
    return common::SourceLocation{parser.file, parser.line_of(e.offset),
                                  static_cast<int>(tokens[static_cast<std::size_t>(2 + static_cast<int>(s))].column + 1)};
  };
  return build_maze(raw);
}

std::string write_num(const Maze &maze) {
  std::string out;
  out.reserve(static_cast<std::size_t>(maze.width()) * static_cast<std::size_t>(maze.height()) * 20);
  for (int x = 0; x < maze.width(); ++x) {
    for (int y = 0; y < maze.height(); ++y) {
      const Cell c{x, y};
      fmt::format_to(std::back_inserter(out), "{} {} {:d} {:d} {:d} {:d}\n", x, y, maze.has_wall(c, Side::north) ? 1 : 0,
                     maze.has_wall(c, Side::east) ? 1 : 0, maze.has_wall(c, Side::south) ? 1 : 0,
                     maze.has_wall(c, Side::west) ? 1 : 0);
    }
  }
  return out;
}

}  // namespace maze
