#include "maze/formats/solids_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <numbers>
#include <optional>
#include <vector>

#include "common/error.hpp"
#include "common/parse_number.hpp"
#include "maze/world/maze.hpp"
#include "line_tokens.hpp"
#include "metres_text.hpp"

namespace maze {

namespace {

// The statement part of a line (before '#', without a trailing '\r').
std::string_view statement_of(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  return line;
}

struct RoomParser {
  const std::string &file;
  int line = 0;

  common::SourceLocation at(std::size_t column) const {
    return common::SourceLocation{file, line, static_cast<int>(column + 1)};
  }
  common::InputError error(std::size_t column, std::string message) const {
    return common::InputError(at(column), std::move(message));
  }

  // The project's one number rule (common/parse_number.hpp), and within 1e9 m.
  double number(const LineToken &t) const {
    const std::optional<double> v = common::parse_real(t.text);
    if (!v) throw error(t.column, fmt::format("'{}' is not a number", shown_token(t.text)));
    if (!std::isfinite(*v) || std::abs(*v) > 1e9) {
      throw error(t.column, fmt::format("'{}' is not a finite number of metres", shown_token(t.text)));
    }
    return *v;
  }

  // The numbers after the keyword: at least `least`, at most `most`.
  std::vector<double> numbers(const std::vector<LineToken> &tokens, std::size_t least, std::size_t most,
                              std::string_view usage) const {
    const std::size_t given = tokens.size() - 1;
    if (given < least || given > most) {
      const std::size_t column = given > most ? tokens[most + 1].column : tokens.front().column;
      throw error(column, fmt::format("{} takes {}: got {} number{}", tokens.front().text, usage, given,
                                      given == 1 ? "" : "s"));
    }
    std::vector<double> values;
    for (std::size_t i = 1; i < tokens.size(); ++i) values.push_back(number(tokens[i]));
    return values;
  }
};

// The yaw in degrees, in the fewest digits that read back (times pi / 180) as the very yaw.
std::string degrees_of(double yaw_rad) {
  const double deg = yaw_rad * 180.0 / std::numbers::pi;
  for (int digits = 6; digits < 17; ++digits) {
    const std::string text = fmt::format("{:.{}g}", deg, digits);
    const double back = common::parse_real(text).value_or(0.0);
    if (back * std::numbers::pi / 180.0 == yaw_rad) return text;
  }
  return fmt::format("{}", deg);
}

// A wall's ends as written: 12 significant digits on the scale of its largest coordinate.
std::array<std::string, 4> wall_ends_text(const std::array<double, 5> &line) {
  const double scale_m = std::max({std::abs(line[0]), std::abs(line[1]), std::abs(line[2]), std::abs(line[3])});
  std::array<std::string, 4> ends;
  for (std::size_t i = 0; i < 4; ++i) ends[i] = metres_text_on_scale(line[i], scale_m);
  return ends;
}

// The wall those ends read back as.
Obstacle wall_of(const std::array<std::string, 4> &ends, double width_m) {
  return Obstacle::from_segment(*common::parse_real(ends[0]), *common::parse_real(ends[1]),
                                *common::parse_real(ends[2]), *common::parse_real(ends[3]), width_m, WallEnds::flush);
}

// A box's statement, "rect X0 Y0 X1 Y1", in the digits the format keeps.
std::string rect_statement(const std::array<double, 4> &b) {
  return fmt::format("rect {} {} {} {}", metres_text(b[0]), metres_text(b[1]), metres_text(b[2]), metres_text(b[3]));
}

// Whether a box keeps an area at the 12 significant digits the format writes.
bool has_written_area(const std::array<double, 4> &b) {
  return metres_text(b[0]) != metres_text(b[2]) && metres_text(b[1]) != metres_text(b[3]);
}

// A solid as the room format writes it: an axis-aligned box as "rect", a slanted wall as
// "wall" with the ends as it reads back (written, read and written again until the text
// holds: an end a rounding step away, a scale a hair under a power of ten, settles in a round
// or two), so that a written room writes the same text again. A wall whose written ends lie
// on an axis reads back as a rectangle, so is written as one; `box` is then its bounds.
struct SolidStatement {
  std::string text;
  std::optional<std::array<double, 4>> box;
};

SolidStatement solid_statement(const Obstacle &o) {
  if (o.axis_aligned()) return {rect_statement(o.bounds()), o.bounds()};
  auto l = o.centre_line();
  std::array<std::string, 4> ends = wall_ends_text(l);
  Obstacle read_back = wall_of(ends, l[4]);
  for (int round = 0; round < 3; ++round) {
    l = read_back.centre_line();
    const std::array<std::string, 4> again = wall_ends_text(l);
    if (again == ends) break;
    ends = again;
    read_back = wall_of(ends, l[4]);
  }
  if (read_back.axis_aligned()) return {rect_statement(read_back.bounds()), read_back.bounds()};
  return {fmt::format("wall {} {} {} {} {}", ends[0], ends[1], ends[2], ends[3], metres_text(l[4])), std::nullopt};
}

}  // namespace

// A wall statement's obstacle; refused (common::InputError) where what is written of it would
// not read back.
Obstacle read_wall(const RoomParser &p, const std::vector<LineToken> &tokens) {
  const LineToken &key = tokens.front();
  const std::vector<double> v = p.numbers(tokens, 4, 5, "4 or 5 numbers X1 Y1 X2 Y2 [WIDTH]");
  const double width = v.size() == 5 ? v[4] : kDefaultWallThickness_m;
  if (!(width > 0.0)) throw p.error(tokens[5].column, fmt::format("the width must be positive, got {}", width));
  if (v[0] == v[2] && v[1] == v[3]) {
    throw p.error(key.column, fmt::format("the wall from ({}, {}) to ({}, {}) has zero length", v[0], v[1], v[2],
                                          v[3]));
  }
  Obstacle o = Obstacle::from_segment(v[0], v[1], v[2], v[3], width, WallEnds::flush);
  // What is written of the wall must read back: a wall whose written ends lie on an axis (or
  // are one point) is written as a rectangle, which needs an area in the digits the format
  // writes, as a rectangle read does.
  if (const SolidStatement written = solid_statement(o); written.box && !has_written_area(*written.box)) {
    throw p.error(key.column, fmt::format("the wall from ({}, {}) to ({}, {}), {} m wide, has no area at the 12 "
                                          "significant digits the format keeps",
                                          v[0], v[1], v[2], v[3], width));
  }
  o.where = p.at(key.column);
  return o;
}

// One statement of a room file (its tokens, its line) into the arena; boundary_line is the
// line of the boundary read so far (0: none yet).
void read_statement(RoomParser &p, const std::vector<LineToken> &tokens, std::string_view line, Arena &arena,
                    int &boundary_line) {
  const LineToken &key = tokens.front();
  if (key.text == "name") {
    const std::string_view rest = statement_of(line).substr(tokens[1 < tokens.size() ? 1 : 0].column);
    if (tokens.size() < 2) throw p.error(key.column, "name takes a text: got none");
    // Trailing blanks and carriage returns go: the name is written on a line of its own, and a
    // '\r' left at its end would be read back as the line's end.
    arena.name = std::string(rest.substr(0, rest.find_last_not_of(" \t\r") + 1));
  } else if (key.text == "boundary") {
    if (boundary_line != 0) {
      throw p.error(key.column, fmt::format("a second boundary (the first is at line {})", boundary_line));
    }
    const std::vector<double> v = p.numbers(tokens, 4, 4, "4 numbers XS XE YS YE");
    boundary_line = p.line;
    arena.x_min_m = v[0];
    arena.x_max_m = v[1];
    arena.y_min_m = v[2];
    arena.y_max_m = v[3];
    arena.boundary_where = p.at(key.column);
    if (!(v[0] < v[1]) || !(v[2] < v[3])) {
      throw p.error(key.column, fmt::format("the boundary x {} to {} m, y {} to {} m is empty: it needs XS < XE "
                                            "and YS < YE",
                                            v[0], v[1], v[2], v[3]));
    }
    // Empty at the 12 significant digits the format keeps (a boundary written back is so).
    if (!has_written_area({v[0], v[2], v[1], v[3]})) {
      throw p.error(key.column, fmt::format("the boundary x {} to {} m, y {} to {} m is empty at the 12 significant "
                                            "digits the format keeps",
                                            v[0], v[1], v[2], v[3]));
    }
  } else if (key.text == "rect") {
    const std::vector<double> v = p.numbers(tokens, 4, 4, "4 numbers X0 Y0 X1 Y1");
    // No area at the 12 significant digits the format keeps (a rectangle written back is so).
    if (!has_written_area({v[0], v[1], v[2], v[3]})) {
      throw p.error(key.column, fmt::format("the rectangle ({}, {})-({}, {}) has no area", v[0], v[1], v[2], v[3]));
    }
    Obstacle o = Obstacle::from_box(v[0], v[1], v[2], v[3]);
    o.where = p.at(key.column);
    arena.obstacles.push_back(o);
  } else if (key.text == "wall") {
    arena.obstacles.push_back(read_wall(p, tokens));
  } else if (key.text == "start") {
    const std::vector<double> v = p.numbers(tokens, 2, 3, "2 or 3 numbers X Y [YAW_DEG]");
    const double yaw_deg = v.size() == 3 ? v[2] : 90.0;
    arena.starts.push_back({v[0], v[1], yaw_deg * std::numbers::pi / 180.0});
    arena.start_where.push_back(p.at(key.column));
  } else if (key.text == "goal") {
    const std::vector<double> v = p.numbers(tokens, 2, 2, "2 numbers X Y");
    arena.goals.push_back({v[0], v[1]});
    arena.goal_where.push_back(p.at(key.column));
  } else {
    throw p.error(key.column, fmt::format("unknown statement '{}': expected name, boundary, rect, wall, start or "
                                          "goal",
                                          shown_token(key.text)));
  }
}

Arena read_room(std::string_view text, const std::string &file) {
  Arena arena;
  arena.source = file;
  RoomParser p{file};
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  int boundary_line = 0;
  std::size_t offset = 0;
  while (offset <= text.size()) {
    ++p.line;
    const std::size_t end = std::min(text.find('\n', offset), text.size());
    const std::string_view line = text.substr(offset, end - offset);
    offset = end + 1;
    const std::vector<LineToken> tokens = line_tokens(statement_of(line));
    if (tokens.empty()) continue;
    read_statement(p, tokens, line, arena, boundary_line);
    const LineToken &key = tokens.front();
    if (arena.obstacles.size() > kMaxObstacles) {
      throw p.error(key.column, fmt::format("more than {} obstacles", kMaxObstacles));
    }
  }
  return arena;
}

std::string write_room(const Arena &arena) {
  // The boundary's size as the written boundary reads back (so that the text written again is
  // the same), in the digits of its ends.
  const auto size_text = [](double from, double to) {
    const double from_written = *common::parse_real(metres_text(from));
    const double to_written = *common::parse_real(metres_text(to));
    return metres_text_on_scale(to_written - from_written, std::max(std::abs(from_written), std::abs(to_written)));
  };
  std::string text = fmt::format("# maze_mapper arena: {} obstacle{}, boundary {} x {} m\n", arena.obstacles.size(),
                                 arena.obstacles.size() == 1 ? "" : "s", size_text(arena.x_min_m, arena.x_max_m),
                                 size_text(arena.y_min_m, arena.y_max_m));
  if (!arena.name.empty()) fmt::format_to(std::back_inserter(text), "name {}\n", arena.name);
  fmt::format_to(std::back_inserter(text), "boundary {} {} {} {}\n", metres_text(arena.x_min_m),
                 metres_text(arena.x_max_m), metres_text(arena.y_min_m), metres_text(arena.y_max_m));
  for (const Obstacle &o : arena.obstacles) {
    fmt::format_to(std::back_inserter(text), "{}\n", solid_statement(o).text);
  }
  for (const ArenaPose &s : arena.starts) {
    fmt::format_to(std::back_inserter(text), "start {} {} {}\n", metres_text(s.x_m), metres_text(s.y_m),
                   degrees_of(s.yaw_rad));
  }
  for (const ArenaPoint &g : arena.goals) {
    fmt::format_to(std::back_inserter(text), "goal {} {}\n", metres_text(g.x_m), metres_text(g.y_m));
  }
  return text;
}

}  // namespace maze
