#include "maze/formats/text_map.hpp"

#include <cstddef>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "maze/world/validate.hpp"

namespace maze {

namespace {

constexpr std::size_t kMaxLineLength = 4 * static_cast<std::size_t>(kMaxMazeSide) + 1;
constexpr std::size_t kMaxLines = 2 * static_cast<std::size_t>(kMaxMazeSide) + 1;

struct Reader {
  const std::string &file;
  std::vector<std::string_view> lines;  // the maze's lines, line ends removed
  int width = 0;
  int height = 0;

  common::InputError error(std::size_t line_index, std::size_t column_index, std::string message) const {
    return common::InputError(
        common::SourceLocation{file, static_cast<int>(line_index + 1), static_cast<int>(column_index + 1)},
        std::move(message));
  }
};

bool is_post(char c) { return c == 'o' || c == '+'; }
bool starts_maze_line(std::string_view line) {
  return !line.empty() && (is_post(line[0]) || line[0] == '|' || line[0] == ' ');
}

// The lines from the top of the file to the first line that is not part of a maze.
void split_maze_lines(std::string_view text, Reader &r) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    if (line.ends_with('\r')) line.remove_suffix(1);
    if (!starts_maze_line(line)) return;
    if (r.lines.size() == kMaxLines) {
      throw r.error(r.lines.size(), 0,
                    fmt::format("the maze is taller than {} cells (more than {} lines)", kMaxMazeSide, kMaxLines));
    }
    r.lines.push_back(line);
    if (end == std::string_view::npos) return;
    text.remove_prefix(end + 1);
  }
}

void check_line_count(Reader &r) {
  const std::size_t n = r.lines.size();
  if (n < 3) {
    throw r.error(n, 0, fmt::format("a maze needs at least 3 lines (2H+1 for H rows), found {}", n));
  }
  if (n % 2 == 0) {
    throw r.error(n - 1, 0, "the maze's last line must be a post line ('o---o...'), not a cell line");
  }
  r.height = static_cast<int>((n - 1) / 2);
}

// The side of which cell a character at (line, column) belongs to; line and column from 0.
struct Place {
  enum Kind { post, horizontal, vertical, centre } kind;
  Cell cell;
  Side side;
};

Place place_of(const Reader &r, std::size_t line, std::size_t column) {
  const int x = static_cast<int>(column / 4);
  const int row = static_cast<int>(line / 2);  // rows from the north, 0-based
  if (line % 2 == 0) {
    if (column % 4 == 0) return {Place::post, {x, 0}, Side::north};
    if (row < r.height) return {Place::horizontal, {x, r.height - 1 - row}, Side::north};
    return {Place::horizontal, {x, 0}, Side::south};
  }
  const int y = r.height - 1 - row;
  if (column % 4 == 0) {
    if (x < r.width) return {Place::vertical, {x, y}, Side::west};
    return {Place::vertical, {x - 1, y}, Side::east};
  }
  return {Place::centre, {x, y}, Side::north};
}

// Known characters only: each position of a line has its own short list.
std::optional<common::InputError> check_character(const Reader &r, std::size_t line, std::size_t column) {
  const char c = r.lines[line][column];
  const Place p = place_of(r, line, column);
  switch (p.kind) {
    case Place::post:
      if (is_post(c)) return std::nullopt;
      return r.error(line, column, fmt::format("unexpected {} where a post 'o' or '+' belongs", describe_byte(c)));
    case Place::horizontal:
      if (c == '-' || c == ' ') return std::nullopt;
      return r.error(line, column,
                     fmt::format("unexpected {} in the {} wall of cell ({},{}); expected '---' or three blanks",
                                 describe_byte(c), to_string(p.side), p.cell.x, p.cell.y));
    case Place::vertical:
      if (c == '|' || c == ' ') return std::nullopt;
      return r.error(line, column,
                     fmt::format("unexpected {} in the {} wall of cell ({},{}); expected '|' or a blank",
                                 describe_byte(c), to_string(p.side), p.cell.x, p.cell.y));
    case Place::centre:
      if (c == ' ' || c == 'S' || c == 'G') return std::nullopt;
      return r.error(line, column,
                     fmt::format("unexpected {} in cell ({},{}); expected a blank, 'S' or 'G'", describe_byte(c),
                                 p.cell.x, p.cell.y));
  }
  return std::nullopt;
}

// A horizontal wall is all '-' or all blank: "-- " is a wall drawn only in part.
std::optional<common::InputError> check_wall_drawn_whole(const Reader &r, std::size_t line, std::size_t column) {
  const std::string_view field = r.lines[line].substr(column, 3);
  if (field == "---" || field == "   ") return std::nullopt;
  const Place p = place_of(r, line, column);
  return r.error(line, column,
                 fmt::format("cell ({},{}): {} wall partly drawn ('{}'); expected '---' or three blanks", p.cell.x,
                             p.cell.y, to_string(p.side), field));
}

void check_width(Reader &r) {
  if (r.lines.empty()) throw r.error(0, 0, "expected a maze: the first line must be a post line ('o---o...')");
  const std::size_t length = r.lines[0].size();
  if (length > kMaxLineLength) {
    throw r.error(0, kMaxLineLength,
                  fmt::format("the maze is wider than {} cells (lines longer than {} characters)", kMaxMazeSide,
                              kMaxLineLength));
  }
  if (length < 5 || (length - 1) % 4 != 0) {
    throw r.error(0, length,
                  fmt::format("the first line is {} characters long; a maze line is 4W+1 characters (5, 9, 13, ...)",
                              length));
  }
  r.width = static_cast<int>((length - 1) / 4);
}

void check_line(const Reader &r, std::size_t line) {
  const std::string_view text = r.lines[line];
  const std::size_t expected = r.lines[0].size();
  const std::size_t scanned = std::min(text.size(), expected);
  for (std::size_t column = 0; column < scanned; ++column) {
    if (auto e = check_character(r, line, column)) throw *e;
    if (line % 2 == 0 && column % 4 == 3) {
      if (auto e = check_wall_drawn_whole(r, line, column - 2)) throw *e;
    }
  }
  if (text.size() != expected) {
    throw r.error(line, scanned,
                  fmt::format("line {} is {} characters long, expected {} like the first line", line + 1,
                              text.size(), expected));
  }
}

common::SourceLocation location_of(const std::string &file, int height, Cell c, Side s) {
  const int row_line = 2 * (height - 1 - c.y) + 2;  // 1-based line of the cell's row
  switch (s) {
    case Side::north: return {file, row_line - 1, 4 * c.x + 2};
    case Side::south: return {file, row_line + 1, 4 * c.x + 2};
    case Side::west: return {file, row_line, 4 * c.x + 1};
    case Side::east: return {file, row_line, 4 * c.x + 5};
  }
  return {file, 0, 0};
}

void read_walls(const Reader &r, RawMaze &raw) {
  for (int row = 0; row <= r.height; ++row) {
    const std::string_view posts = r.lines[static_cast<std::size_t>(2 * row)];
    for (int x = 0; x < r.width; ++x) {
      const bool wall = posts[static_cast<std::size_t>(4 * x + 1)] == '-';
      if (row < r.height) raw.set({x, r.height - 1 - row}, Side::north, wall);
      if (row > 0) raw.set({x, r.height - row}, Side::south, wall);
    }
  }
  for (int row = 0; row < r.height; ++row) {
    const std::string_view cells = r.lines[static_cast<std::size_t>(2 * row + 1)];
    const int y = r.height - 1 - row;
    for (int x = 0; x <= r.width; ++x) {
      const bool wall = cells[static_cast<std::size_t>(4 * x)] == '|';
      if (x < r.width) raw.set({x, y}, Side::west, wall);
      if (x > 0) raw.set({x - 1, y}, Side::east, wall);
    }
  }
}

void read_marks(const Reader &r, RawMaze &raw) {
  bool have_start = false;
  raw.start = {0, 0};
  raw.start_heading = Side::north;
  for (std::size_t line = 1; line < r.lines.size(); line += 2) {
    const std::string_view cells = r.lines[line];
    for (std::size_t column = 1; column < cells.size(); ++column) {
      const char c = cells[column];
      if (c != 'S' && c != 'G') continue;
      const Place p = place_of(r, line, column);
      const common::SourceLocation where{r.file, static_cast<int>(line + 1), static_cast<int>(column + 1)};
      if (c == 'G') {
        raw.goals.push_back(p.cell);
        raw.goal_where.push_back(where);
        continue;
      }
      if (have_start) {
        throw common::InputError(where, fmt::format("a second start 'S' in cell ({},{}); the first is in cell ({},{})",
                                                    p.cell.x, p.cell.y, raw.start.x, raw.start.y));
      }
      have_start = true;
      raw.start = p.cell;
      raw.start_where = where;
    }
  }
}

}  // namespace

Maze read_text_map(std::string_view text, const std::string &file) {
  Reader r{file, {}};
  split_maze_lines(text, r);
  check_width(r);
  check_line_count(r);
  for (std::size_t line = 0; line < r.lines.size(); ++line) check_line(r, line);

  RawMaze raw;
  raw.resize(r.width, r.height);
  read_walls(r, raw);
  read_marks(r, raw);
  const int height = r.height;
  raw.where = [&file, height](Cell c, Side s) { return location_of(file, height, c, s); };
  return build_maze(raw);
}

std::string write_text_map(const Maze &maze) {
  const auto w = static_cast<std::size_t>(maze.width());
  const auto h = static_cast<std::size_t>(maze.height());
  std::string out;
  out.reserve((2 * h + 1) * (4 * w + 2));
  auto post_line = [&](int y, Side side) {
    for (int x = 0; x < maze.width(); ++x) {
      out += 'o';
      out += maze.has_wall({x, y}, side) ? "---" : "   ";
    }
    out += "o\n";
  };
  for (int y = maze.height() - 1; y >= 0; --y) {
    post_line(y, Side::north);
    for (int x = 0; x < maze.width(); ++x) {
      out += maze.has_wall({x, y}, Side::west) ? '|' : ' ';
      const Cell c{x, y};
      const bool start = c == maze.start();
      const bool goal = maze.is_goal(c);
      out += start && goal ? " SG" : start ? " S " : goal ? " G " : "   ";
    }
    out += maze.has_wall({maze.width() - 1, y}, Side::east) ? "|\n" : " \n";
  }
  post_line(0, Side::south);
  return out;
}

}  // namespace maze
