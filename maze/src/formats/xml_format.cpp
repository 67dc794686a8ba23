#include "maze/formats/xml_format.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "maze/world/geometry.hpp"
#include "maze/world/validate.hpp"
#include "lattice.hpp"
#include "xml_source.hpp"

namespace maze {

namespace {

// How far (in cells) a wall end may sit from a grid point; files round to a few decimals.
constexpr double kGridTolerance = 1e-3;
constexpr double kHeadingTolerance_rad = 0.01;

using xml::number;
using xml::Source;
using xml::read_landmark;

struct Segment {
  xml::Element element;
  double x1, y1, x2, y2;
  bool horizontal;
};

std::vector<Segment> read_segments(const xml::Element &world, const Source &src, double &thickness_m) {
  std::vector<Segment> segments;
  std::optional<xml::Element> first;
  const std::vector<xml::Element> elements = world.children("wall");
  segments.reserve(elements.size());
  for (const xml::Element &e : elements) {
    Segment s{e, *number(e, "x1", src, true), *number(e, "y1", src, true), *number(e, "x2", src, true),
              *number(e, "y2", src, true), false};
    const double width = number(e, "width", src, false).value_or(kDefaultWallThickness_m);
    if (width <= 0.0) throw src.error(e, "width", fmt::format("width must be positive, got {}", width));
    if (!first) {
      first = e;
      thickness_m = width;
    } else if (width != thickness_m) {
      throw src.error(e, "width",
                      fmt::format("wall width {} m differs from the {} m of the first wall (line {}); a maze has one "
                                  "wall thickness",
                                  width, thickness_m, first->line()));
    }
    const bool flat = s.y1 == s.y2;
    const bool upright = s.x1 == s.x2;
    if (flat && upright) throw src.error(e, nullptr, "wall has zero length");
    if (!flat && !upright) {
      throw src.error(e, nullptr,
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
    throw src.error(shortest.element, "width",
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
      const double next = lattice::common_divisor(cell, offset, tol);
      if (next > finest) {
        cell = next;
        continue;
      }
      if (cell == 0.0) {
        throw src.error(s.element, name,
                        fmt::format("wall end {}={} is {} m from the origin ({}, {}): cells that small are no "
                                    "wider than four walls of {} m",
                                    name, v, offset, e.min_x, e.min_y, thickness_m));
      }
      throw src.error(s.element, name,
                      fmt::format("wall end {}={} is off the grid (cells of {} m from ({}, {}))", name, v, cell,
                                  e.min_x, e.min_y));
    }
  }
  // Measured over the longer side, the cell is as exact as the file: 5 / 10, not 0.49999...
  const double span = std::max(e.max_x - e.min_x, e.max_y - e.min_y);
  return span / std::round(span / cell);
}

double stated_cell_size(const xml::Element &world, double thickness_m, const Source &src, double stated) {
  if (!(stated > 0.0)) throw src.error(world, "cellSize", fmt::format("cellSize must be positive, got {}", stated));
  if (thickness_m >= kMaxThicknessPerCell * stated) {
    throw src.error(world, "cellSize",
                    fmt::format("wall width {} m is not less than a quarter of the cell size {} m", thickness_m,
                                stated));
  }
  return stated;
}

struct StartPoint {
  xml::Element element;
  double x, y;
};

std::vector<StartPoint> read_start_points(const xml::Element &world, const Source &src) {
  std::vector<StartPoint> points;
  for (const xml::Element &starts : world.children("startPositions")) {
    for (const xml::Element &pos : starts.children("pos")) {
      points.push_back({pos, *number(pos, "x", src, true), *number(pos, "y", src, true)});
    }
  }
  return points;
}

// The coarsest lattice from the origin that puts every start position on a cell centre
// (lattice::centres_lattice), or nothing without start positions.
std::optional<double> start_lattice(const std::vector<StartPoint> &starts, const Extent &e, double thickness_m,
                                    double tol) {
  if (starts.empty()) return std::nullopt;
  std::vector<double> offsets;
  for (const StartPoint &p : starts) {
    offsets.push_back(p.x - e.min_x);
    offsets.push_back(p.y - e.min_y);
  }
  const double span = std::max(e.max_x - e.min_x, e.max_y - e.min_y);
  return lattice::centres_lattice(offsets, thickness_m / kMaxThicknessPerCell, span, tol);
}

// The walls with an end off the lattice of `cell` from the origin.
std::vector<const Segment *> walls_off(const std::vector<Segment> &segments, const Extent &e, double cell,
                                       double tol) {
  std::vector<const Segment *> off;
  for (const Segment &s : segments) {
    if (!lattice::on_lattice(s.x1 - e.min_x, cell, tol) || !lattice::on_lattice(s.y1 - e.min_y, cell, tol) ||
        !lattice::on_lattice(s.x2 - e.min_x, cell, tol) || !lattice::on_lattice(s.y2 - e.min_y, cell, tol)) {
      off.push_back(&s);
    }
  }
  return off;
}

// "the wall (-1, -2.5)-(-1, -1.5) at line 9" for the first three, then "and N more".
std::string named_walls(const std::vector<const Segment *> &walls) {
  constexpr std::size_t kNamed = 3;
  std::string text = walls.size() == 1 ? "the wall " : "the walls ";
  for (std::size_t i = 0; i < std::min(kNamed, walls.size()); ++i) {
    const Segment &w = *walls[i];
    const bool last = i + 1 == walls.size();
    text += fmt::format("{}({}, {})-({}, {}) at line {}", i == 0 ? "" : last ? " and " : ", ", w.x1, w.y1, w.x2,
                        w.y2, w.element.line());
  }
  if (walls.size() > kNamed) text += fmt::format(" and {} more", walls.size() - kNamed);
  return text;
}

// The cell size the file states (cellSize, as write_xml writes it: a written maze reads back
// with its very cell size), else the one chosen (--cell-size), else the lattice of the start
// positions when every wall lies on it, else the lattice of the wall ends; in that last case,
// when the start positions have a lattice of their own, a warning names the walls off it.
Grid infer_grid(const std::vector<Segment> &segments, const std::vector<StartPoint> &starts, double thickness_m,
                const Source &src, const xml::Element &world, const XmlReadOptions &options,
                std::vector<std::string> &warnings) {
  const Extent e = extent_of(segments);
  check_thin_walls(segments, thickness_m, src);
  const std::optional<double> stated = number(world, "cellSize", src, false);
  Grid g{e.min_x, e.min_y, 0.0, 0, 0};
  if (stated) {
    g.cell = stated_cell_size(world, thickness_m, src, *stated);
    if (options.cell_size_m && std::abs(*options.cell_size_m - g.cell) > 1e-9 * g.cell) {
      throw common::InputError(fmt::format("--cell-size {} m disagrees with the cellSize {} m that {} states; leave "
                                           "--cell-size out",
                                           *options.cell_size_m, g.cell, src.file));
    }
  } else if (options.cell_size_m) {
    g.cell = *options.cell_size_m;
    if (thickness_m >= kMaxThicknessPerCell * g.cell) {
      throw common::InputError(fmt::format("--cell-size {} m is not more than four walls of {} m", g.cell, thickness_m));
    }
  } else {
    const double tol = kLatticeTolerance * std::max({1.0, e.max_x - e.min_x, e.max_y - e.min_y});
    const double walls_cell = infer_cell_size(segments, e, thickness_m, src);
    g.cell = walls_cell;
    if (const std::optional<double> starts_cell = start_lattice(starts, e, thickness_m, tol)) {
      const double span = std::max(e.max_x - e.min_x, e.max_y - e.min_y);
      const std::optional<double> shared =
          lattice::shared_lattice(*starts_cell, walls_cell, thickness_m / kMaxThicknessPerCell, span, tol);
      const std::vector<const Segment *> off = walls_off(segments, e, *starts_cell, tol);
      if (shared && walls_off(segments, e, *shared, tol).empty()) {
        g.cell = span / std::round(span / *shared);
      } else if (!off.empty()) {
        warnings.push_back(fmt::format(
            "{}: warning: the start positions sit on the centres of {} m cells, but {} {} off that lattice: read "
            "as {}x{} cells of {} m, the walls' own lattice; --cell-size {} keeps this reading without the warning, "
            "--cell-size {} asks for {} m cells (the walls off them are then errors)",
            src.file, *starts_cell, named_walls(off), off.size() == 1 ? "is" : "are",
            std::round((e.max_x - e.min_x) / walls_cell), std::round((e.max_y - e.min_y) / walls_cell), walls_cell,
            walls_cell, *starts_cell, *starts_cell));
      }
    }
  }
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
    throw src.error(s.element, name,
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
Cell cell_at(const xml::Element &e, const Grid &g, const Source &src, const char *what,
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

Side heading_of(const xml::Element &pos, const Source &src) {
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

void read_start_and_goals(const xml::Element &world, const Grid &g, const Source &src, RawMaze &raw) {
  raw.start_where = src.at(world);
  for (const xml::Element &starts : world.children("startPositions")) {
    for (const xml::Element &pos : starts.children("pos")) {
      const Side heading = heading_of(pos, src);
      raw.start_positions.push_back({cell_at(pos, g, src, "start", heading), heading});
      raw.start_positions_where.push_back(src.at(pos, "x"));
    }
  }
  if (!raw.start_positions.empty()) {
    raw.start = raw.start_positions.front().cell;
    raw.start_heading = raw.start_positions.front().heading;
    raw.start_where = raw.start_positions_where.front();
  }
  for (const xml::Element &e : world.children("landmark")) {
    raw.landmarks.push_back(read_landmark(e, src));
  }
  for (const xml::Element &e : world.children("goal")) {
    raw.goals.push_back(cell_at(e, g, src, "goal"));
    raw.goal_where.push_back(src.at(e, "x"));
  }
}

}  // namespace

Maze read_xml(std::string_view text, const std::string &file) { return read_xml(text, file, {}).maze; }

XmlRead read_xml(std::string_view text, const std::string &file, const XmlReadOptions &options) {
  const Source src(text, file);
  const xml::Document doc = xml::Document::parse(text, file);
  const xml::Element world = xml::world_of(doc, src);

  double thickness_m = kDefaultWallThickness_m;
  const auto segments = read_segments(world, src, thickness_m);
  std::vector<std::string> warnings;
  const Grid g = infer_grid(segments, read_start_points(world, src), thickness_m, src, world, options, warnings);
  RawMaze raw;
  raw.resize(g.width, g.height);
  rasterize(segments, g, src, raw);
  read_start_and_goals(world, g, src, raw);
  raw.cell_size_m = g.cell;
  raw.wall_thickness_m = thickness_m;
  raw.wall_height_m = kCourseWallHeight_m;
  raw.origin_x_m = g.origin_x;
  raw.origin_y_m = g.origin_y;
  const common::SourceLocation world_at = src.at(world);
  raw.where = [world_at](Cell, Side) { return world_at; };
  return {build_maze(raw), std::move(warnings)};
}

}  // namespace maze
