#include "maze/xml_format.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <tinyxml2.h>

#include "common/error.hpp"
#include "maze/validate.hpp"

namespace maze {

namespace {

// How far (in cells) a wall end may sit from a grid point; files round to a few decimals.
constexpr double kGridTolerance = 1e-3;
constexpr double kHeadingTolerance_rad = 0.01;

struct Source {
  std::string_view text;
  const std::string &file;
  std::vector<std::size_t> line_starts;

  Source(std::string_view t, const std::string &f) : text(t), file(f) {
    line_starts.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\n') line_starts.push_back(i + 1);
    }
  }

  // The element's line, and the column of `attribute=` on that line if it is there. Several
  // elements on one line are told apart by counting the earlier siblings of the same name.
  // With a cursor (elements of one name visited in document order), the tag is searched from
  // the one before on its line: N elements on one line cost O(line), not O(N * line).
  struct Cursor {
    int line = 0;
    std::size_t from = 0;
  };
  common::SourceLocation at(const tinyxml2::XMLElement &e, const char *attribute = nullptr,
                            Cursor *cursor = nullptr) const {
    const int line = e.GetLineNum();
    if (line < 1 || static_cast<std::size_t>(line) > line_starts.size()) return {file, 0, 0};
    const std::size_t begin = line_starts[static_cast<std::size_t>(line - 1)];
    const std::size_t end = static_cast<std::size_t>(line) < line_starts.size()
                                ? line_starts[static_cast<std::size_t>(line)]
                                : text.size();
    const std::string_view text_of_line = text.substr(begin, end - begin);
    if (cursor != nullptr && cursor->line != line) *cursor = Cursor{line, 0};
    std::size_t column = cursor == nullptr ? find_tag(text_of_line, e.Name(), earlier_on_same_line(e))
                                           : find_tag(text_of_line.substr(cursor->from), e.Name(), 0);
    if (cursor != nullptr && column != std::string_view::npos) cursor->from = (column += cursor->from) + 1;
    if (attribute != nullptr && column != std::string_view::npos) {
      column = text_of_line.find(fmt::format(" {}=", attribute), column);
      if (column != std::string_view::npos) ++column;
    }
    if (column == std::string_view::npos) return {file, line, 0};
    return {file, line, static_cast<int>(column + 1)};
  }

  static std::size_t earlier_on_same_line(const tinyxml2::XMLElement &e) {
    std::size_t n = 0;
    for (auto *p = e.PreviousSiblingElement(e.Name()); p != nullptr && p->GetLineNum() == e.GetLineNum();
         p = p->PreviousSiblingElement(e.Name())) {
      ++n;
    }
    return n;
  }

  // Where the (skip + 1)-th tag `<name` starts in the line.
  static std::size_t find_tag(std::string_view line, std::string_view name, std::size_t skip) {
    const std::string tag = fmt::format("<{}", name);
    for (std::size_t at = line.find(tag); at != std::string_view::npos; at = line.find(tag, at + 1)) {
      const std::size_t after = at + tag.size();
      const bool whole = after == line.size() || std::string_view(" \t\r\n/>").find(line[after]) != std::string_view::npos;
      if (!whole) continue;
      if (skip == 0) return at;
      --skip;
    }
    return std::string_view::npos;
  }

  common::InputError error(const tinyxml2::XMLElement &e, const char *attribute, std::string message) const {
    return common::InputError(at(e, attribute), std::move(message));
  }
};

std::optional<double> number(const tinyxml2::XMLElement &e, const char *name, const Source &src, bool required) {
  const char *value = e.Attribute(name);
  if (value == nullptr) {
    if (required) throw src.error(e, nullptr, fmt::format("<{}> needs the attribute {}", e.Name(), name));
    return std::nullopt;
  }
  std::string_view text(value);
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  double result = 0.0;
  const auto [stop, ec] = std::from_chars(text.data(), text.data() + text.size(), result);
  const std::string shown(std::string_view(value).substr(0, 20));
  if (ec != std::errc() || stop != text.data() + text.size() || text.empty()) {
    throw src.error(e, name, fmt::format("{} is not a number: '{}'", name, shown));
  }
  if (!std::isfinite(result) || std::abs(result) > 1e9) {
    const std::string_view unit = std::string_view(name) == "theta" ? "radians" : "metres";
    throw src.error(e, name, fmt::format("{} is not a finite number of {}: '{}'", name, unit, shown));
  }
  return result;
}

struct Segment {
  const tinyxml2::XMLElement *element;
  double x1, y1, x2, y2;
  bool horizontal;
};

std::vector<Segment> read_segments(const tinyxml2::XMLElement &world, const Source &src, double &thickness_m) {
  std::vector<Segment> segments;
  const tinyxml2::XMLElement *first = nullptr;
  for (auto *e = world.FirstChildElement("wall"); e != nullptr; e = e->NextSiblingElement("wall")) {
    Segment s{e, *number(*e, "x1", src, true), *number(*e, "y1", src, true), *number(*e, "x2", src, true),
              *number(*e, "y2", src, true), false};
    const double width = number(*e, "width", src, false).value_or(kDefaultWallThickness_m);
    if (width <= 0.0) throw src.error(*e, "width", fmt::format("width must be positive, got {}", width));
    if (first == nullptr) {
      first = e;
      thickness_m = width;
    } else if (width != thickness_m) {
      throw src.error(*e, "width",
                      fmt::format("wall width {} m differs from the {} m of the first wall (line {}); a maze has one "
                                  "wall thickness",
                                  width, thickness_m, first->GetLineNum()));
    }
    const bool flat = s.y1 == s.y2;
    const bool upright = s.x1 == s.x2;
    if (flat && upright) throw src.error(*e, nullptr, "wall has zero length");
    if (!flat && !upright) {
      throw src.error(*e, nullptr,
                      fmt::format("wall from ({}, {}) to ({}, {}) is neither horizontal nor vertical", s.x1, s.y1,
                                  s.x2, s.y2));
    }
    s.horizontal = flat;
    if (flat && s.x1 > s.x2) std::swap(s.x1, s.x2);
    if (upright && s.y1 > s.y2) std::swap(s.y1, s.y2);
    segments.push_back(s);
  }
  if (segments.empty()) {
    throw src.error(world, nullptr, "no <wall> elements: an open arena, not a grid maze; a maze needs walls");
  }
  return segments;
}

struct Grid {
  double origin_x, origin_y, cell;
  int width, height;
};

// A grid maze's walls are thin: a wall at least a quarter as thick as a cell (or as the
// shortest wall) makes an arena of obstacles, which this program cannot map cell by cell.
constexpr double kMaxThicknessPerCell = 0.25;

// How far a wall end may sit from a lattice line when the lattice is inferred: 1e-6 m, or
// 1e-6 of the maze's extent when that is above 1 m (decimal files hold 0.1 as a rounded
// binary number).
constexpr double kLatticeTolerance = 1e-6;

// The largest length dividing both a and b (>= 0) to within tol: Euclid on remainders, a
// remainder within tol of 0 or of the divisor counting as none. 0 when both are 0.
double common_divisor(double a, double b, double tol) {
  if (a < b) std::swap(a, b);
  while (b > tol) {
    double r = std::fmod(a, b);
    if (r > b - tol) r = 0.0;
    a = b;
    b = r;
  }
  return a;
}

struct Extent {
  double min_x, min_y, max_x, max_y;
};

Extent extent_of(const std::vector<Segment> &segments) {
  Extent e{segments[0].x1, segments[0].y1, segments[0].x1, segments[0].y1};
  for (const Segment &s : segments) {
    e.min_x = std::min({e.min_x, s.x1, s.x2});
    e.min_y = std::min({e.min_y, s.y1, s.y2});
    e.max_x = std::max({e.max_x, s.x1, s.x2});
    e.max_y = std::max({e.max_y, s.y1, s.y2});
  }
  return e;
}

double length_of(const Segment &s) { return (s.x2 - s.x1) + (s.y2 - s.y1); }

// "Not a grid maze" when the walls are thick for their length (an arena of obstacles).
void check_thin_walls(const std::vector<Segment> &segments, double thickness_m, const Source &src) {
  const Segment &shortest = *std::min_element(
      segments.begin(), segments.end(), [](const Segment &a, const Segment &b) { return length_of(a) < length_of(b); });
  if (thickness_m >= kMaxThicknessPerCell * length_of(shortest)) {
    throw src.error(*shortest.element, "width",
                    fmt::format("walls {} m thick, the shortest {} m long, are obstacles in an arena, not a grid "
                                "maze (its walls are thinner than a quarter of a cell)",
                                thickness_m, length_of(shortest)));
  }
}

// The lattice of the wall ends: the largest length dividing every end's offset from the
// origin (so every wall's length too), to within kLatticeTolerance. A lattice no coarser than
// the walls are thick (see kMaxThicknessPerCell) means the walls are not on one: the error
// names the first wall end that broke the lattice of the ones before it.
double infer_cell_size(const std::vector<Segment> &segments, const Extent &e, double thickness_m,
                       const Source &src) {
  const double tol = kLatticeTolerance * std::max({1.0, e.max_x - e.min_x, e.max_y - e.min_y});
  const double finest = thickness_m / kMaxThicknessPerCell;
  double cell = 0.0;
  for (const Segment &s : segments) {
    const std::pair<const char *, double> ends[] = {{"x1", s.x1}, {"y1", s.y1}, {"x2", s.x2}, {"y2", s.y2}};
    for (const auto &[name, v] : ends) {
      const double offset = v - (name[0] == 'x' ? e.min_x : e.min_y);
      if (offset <= tol) continue;
      const double next = common_divisor(cell, offset, tol);
      if (next > finest) {
        cell = next;
        continue;
      }
      if (cell == 0.0) {
        throw src.error(*s.element, name,
                        fmt::format("wall end {}={} is {} m from the origin ({}, {}): cells that small are no "
                                    "wider than four walls of {} m",
                                    name, v, offset, e.min_x, e.min_y, thickness_m));
      }
      throw src.error(*s.element, name,
                      fmt::format("wall end {}={} is off the grid (cells of {} m from ({}, {}))", name, v, cell,
                                  e.min_x, e.min_y));
    }
  }
  // Measured over the longer side, the cell is as exact as the file: 5 / 10, not 0.49999...
  const double span = std::max(e.max_x - e.min_x, e.max_y - e.min_y);
  return span / std::round(span / cell);
}

double stated_cell_size(const tinyxml2::XMLElement &world, double thickness_m, const Source &src, double stated) {
  if (!(stated > 0.0)) throw src.error(world, "cellSize", fmt::format("cellSize must be positive, got {}", stated));
  if (thickness_m >= kMaxThicknessPerCell * stated) {
    throw src.error(world, "cellSize",
                    fmt::format("wall width {} m is not less than a quarter of the cell size {} m", thickness_m,
                                stated));
  }
  return stated;
}

// The cell size the file states (cellSize, as write_xml writes it: a written maze reads back
// with its very cell size), else the lattice of the wall ends.
Grid infer_grid(const std::vector<Segment> &segments, double thickness_m, const Source &src,
                const tinyxml2::XMLElement &world) {
  const Extent e = extent_of(segments);
  check_thin_walls(segments, thickness_m, src);
  const std::optional<double> stated = number(world, "cellSize", src, false);
  Grid g{e.min_x, e.min_y, 0.0, 0, 0};
  g.cell = stated ? stated_cell_size(world, thickness_m, src, *stated) : infer_cell_size(segments, e, thickness_m, src);
  const double w = std::round((e.max_x - e.min_x) / g.cell);
  const double h = std::round((e.max_y - e.min_y) / g.cell);
  if (w < 1 || h < 1) throw src.error(world, nullptr, "the walls enclose no area: they all lie on one line");
  if (w > kMaxMazeSide || h > kMaxMazeSide) {
    throw src.error(world, nullptr,
                    fmt::format("the walls span {}x{} cells of {} m; each side must be 1 to {}", w, h, g.cell,
                                kMaxMazeSide));
  }
  g.width = static_cast<int>(w);
  g.height = static_cast<int>(h);
  return g;
}

// The grid line index of a wall end, or an "off the grid" error naming the attribute.
int grid_index(double v, double origin, const Grid &g, const Segment &s, const char *name, const Source &src) {
  const double k = (v - origin) / g.cell;
  if (std::abs(k - std::round(k)) > kGridTolerance) {
    throw src.error(*s.element, name,
                    fmt::format("wall end {}={} is off the grid (cells of {} m from ({}, {}))", name, v, g.cell,
                                g.origin_x, g.origin_y));
  }
  return static_cast<int>(std::round(k));
}

void rasterize(const std::vector<Segment> &segments, const Grid &g, const Source &src, RawMaze &raw) {
  for (const Segment &s : segments) {
    const int i1 = grid_index(s.x1, g.origin_x, g, s, "x1", src);
    const int j1 = grid_index(s.y1, g.origin_y, g, s, "y1", src);
    const int i2 = grid_index(s.x2, g.origin_x, g, s, "x2", src);
    const int j2 = grid_index(s.y2, g.origin_y, g, s, "y2", src);
    if (s.horizontal) {
      for (int x = i1; x < i2; ++x) {
        if (j1 < g.height) raw.set({x, j1}, Side::south, true);
        if (j1 > 0) raw.set({x, j1 - 1}, Side::north, true);
      }
    } else {
      for (int y = j1; y < j2; ++y) {
        if (i1 < g.width) raw.set({i1, y}, Side::west, true);
        if (i1 > 0) raw.set({i1 - 1, y}, Side::east, true);
      }
    }
  }
}

// A point's column (or row) index along one axis: the cell holding it; on a grid line (within
// kGridTolerance) the cell on the `ahead` side of it (+1: east or north, -1: west or south).
double index_along(double v, double origin, double cell, int ahead) {
  const double k = (v - origin) / cell;
  const double line = std::round(k);
  if (std::abs(k - line) <= kGridTolerance) return ahead < 0 ? line - 1 : line;
  return std::floor(k);
}

// The cell holding the point, or an error when the point is outside the maze. A point on a
// grid line goes to the cell east or north of it unless `heading` points west or south.
Cell cell_at(const tinyxml2::XMLElement &e, const Grid &g, const Source &src, const char *what,
             Side heading = Side::north) {
  const double x = *number(e, "x", src, true);
  const double y = *number(e, "y", src, true);
  const double i = index_along(x, g.origin_x, g.cell, heading == Side::west ? -1 : 1);
  const double j = index_along(y, g.origin_y, g.cell, heading == Side::south ? -1 : 1);
  if (i < 0 || j < 0 || i >= g.width || j >= g.height) {
    throw src.error(e, "x",
                    fmt::format("{} ({}, {}) is outside the maze, which spans x {} to {} m and y {} to {} m", what, x,
                                y, g.origin_x, g.origin_x + g.width * g.cell, g.origin_y,
                                g.origin_y + g.height * g.cell));
  }
  return {static_cast<int>(i), static_cast<int>(j)};
}

Side heading_of(const tinyxml2::XMLElement &pos, const Source &src) {
  const double theta = number(pos, "theta", src, false).value_or(std::numbers::pi / 2);
  const double quarters = std::round(theta / (std::numbers::pi / 2));
  if (std::abs(theta - quarters * std::numbers::pi / 2) > kHeadingTolerance_rad) {
    throw src.error(pos, "theta",
                    fmt::format("theta {} rad is not a multiple of pi/2; the start faces north, east, south or west",
                                theta));
  }
  constexpr Side kByQuarter[] = {Side::east, Side::north, Side::west, Side::south};
  const auto q = static_cast<long long>(quarters);
  return kByQuarter[((q % 4) + 4) % 4];
}

void read_start_and_goals(const tinyxml2::XMLElement &world, const Grid &g, const Source &src, RawMaze &raw) {
  raw.start_where = src.at(world);
  if (const auto *starts = world.FirstChildElement("startPositions")) {
    if (const auto *pos = starts->FirstChildElement("pos")) {
      raw.start_heading = heading_of(*pos, src);
      raw.start = cell_at(*pos, g, src, "start", raw.start_heading);
      raw.start_where = src.at(*pos, "x");
    }
  }
  Source::Cursor cursor;
  for (auto *e = world.FirstChildElement("goal"); e != nullptr; e = e->NextSiblingElement("goal")) {
    raw.goals.push_back(cell_at(*e, g, src, "goal"));
    raw.goal_where.push_back(src.at(*e, "x", &cursor));
  }
}

// tinyxml2's XML_ERROR_MISMATCHED_ELEMENT as "mismatched element".
std::string error_name(tinyxml2::XMLError id) {
  std::string name = tinyxml2::XMLDocument::ErrorIDToName(id);
  if (name.starts_with("XML_ERROR_")) name.erase(0, 10);
  for (char &c : name) c = c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

const tinyxml2::XMLElement &parse(tinyxml2::XMLDocument &doc, const Source &src) {
  if (doc.Parse(src.text.data(), src.text.size()) != tinyxml2::XML_SUCCESS) {
    throw common::InputError(common::SourceLocation{src.file, doc.ErrorLineNum(), 0},
                             fmt::format("not well-formed XML: {}", error_name(doc.ErrorID())));
  }
  const tinyxml2::XMLElement *root = doc.RootElement();
  if (root == nullptr) throw common::InputError(common::SourceLocation{src.file, 0, 0}, "no XML element: expected <world>");
  if (std::string_view(root->Name()) != "world") {
    throw src.error(*root, nullptr, fmt::format("the root element is <{}>; expected <world>", root->Name()));
  }
  return *root;
}

}  // namespace

Maze read_xml(std::string_view text, const std::string &file) {
  const Source src(text, file);
  tinyxml2::XMLDocument doc(true, tinyxml2::COLLAPSE_WHITESPACE);
  const tinyxml2::XMLElement &world = parse(doc, src);

  double thickness_m = kDefaultWallThickness_m;
  const auto segments = read_segments(world, src, thickness_m);
  const Grid g = infer_grid(segments, thickness_m, src, world);
  RawMaze raw;
  raw.resize(g.width, g.height);
  rasterize(segments, g, src, raw);
  read_start_and_goals(world, g, src, raw);
  raw.cell_size_m = g.cell;
  raw.wall_thickness_m = thickness_m;
  raw.origin_x_m = g.origin_x;
  raw.origin_y_m = g.origin_y;
  const common::SourceLocation world_at = src.at(world);
  raw.where = [world_at](Cell, Side) { return world_at; };
  return build_maze(raw);
}

std::string write_xml(const Maze &maze) {
  const double s = maze.cell_size_m();
  const double ox = maze.origin_x_m();
  const double oy = maze.origin_y_m();
  std::string text = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<!-- maze_mapper world: {}x{} cells of {} m, walls {} m thick -->\n<world cellSize=\"{}\">\n",
      maze.width(), maze.height(), s, maze.wall_thickness_m(), s);
  auto wall = [&](double x1, double y1, double x2, double y2) {
    fmt::format_to(std::back_inserter(text), "  <wall x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" width=\"{}\"/>\n", x1, y1,
                   x2, y2, maze.wall_thickness_m());
  };
  for (int j = 0; j <= maze.height(); ++j) {
    for (int x = 0; x < maze.width(); ++x) {
      const bool present = j < maze.height() ? maze.has_wall({x, j}, Side::south) : maze.has_wall({x, j - 1}, Side::north);
      if (present) wall(ox + x * s, oy + j * s, ox + (x + 1) * s, oy + j * s);
    }
  }
  for (int i = 0; i <= maze.width(); ++i) {
    for (int y = 0; y < maze.height(); ++y) {
      const bool present = i < maze.width() ? maze.has_wall({i, y}, Side::west) : maze.has_wall({i - 1, y}, Side::east);
      if (present) wall(ox + i * s, oy + y * s, ox + i * s, oy + (y + 1) * s);
    }
  }
  constexpr double kTheta[] = {std::numbers::pi / 2, 0.0, -std::numbers::pi / 2, std::numbers::pi};
  const Cell st = maze.start();
  fmt::format_to(std::back_inserter(text),
                 "  <startPositions>\n    <pos x=\"{}\" y=\"{}\" theta=\"{}\"/>\n  </startPositions>\n",
                 ox + (st.x + 0.5) * s, oy + (st.y + 0.5) * s, kTheta[static_cast<int>(maze.start_heading())]);
  int id = 0;
  for (const Cell g : maze.goals()) {
    fmt::format_to(std::back_inserter(text), "  <goal id=\"{}\" x=\"{}\" y=\"{}\"/>\n", id++, ox + (g.x + 0.5) * s,
                   oy + (g.y + 0.5) * s);
  }
  text += "</world>\n";
  return text;
}

}  // namespace maze
