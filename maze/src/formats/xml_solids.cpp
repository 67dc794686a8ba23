#include "maze/formats/xml_solids.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>

#include "common/error.hpp"
#include "common/xml_text.hpp"
#include "maze/world/maze.hpp"
#include "metres_text.hpp"
#include "xml_source.hpp"

namespace maze {

namespace {

using xml::number;
using xml::Source;

// A grid maze's walls are thinner than a quarter of the shortest wall (xml_format.cpp's rule).
constexpr double kMaxThicknessPerLength = 0.25;

struct XmlWall {
  xml::Element element;
  double x1, y1, x2, y2, width;
};

// Every <wall>, its numbers read in the maze reader's order and words.
std::vector<XmlWall> read_walls(const xml::Element &world, const Source &src) {
  std::vector<XmlWall> walls;
  const std::vector<xml::Element> elements = world.children("wall");
  walls.reserve(elements.size());
  for (const xml::Element &e : elements) {
    XmlWall w{e, *number(e, "x1", src, true), *number(e, "y1", src, true), *number(e, "x2", src, true),
              *number(e, "y2", src, true), number(e, "width", src, false).value_or(kDefaultWallThickness_m)};
    if (w.width <= 0.0) throw src.error(e, "width", fmt::format("width must be positive, got {}", w.width));
    walls.push_back(w);
  }
  return walls;
}

}  // namespace

bool xml_world_is_arena(std::string_view text, const std::string &file, const XmlReadOptions &options) {
  const Source src(text, file);
  const xml::Document doc = xml::Document::parse(text, file);
  const xml::Element world = xml::world_of(doc, src);
  if (options.cell_size_m || world.attribute("cellSize")) return false;
  const std::vector<XmlWall> walls = read_walls(world, src);
  if (walls.empty()) return true;
  double shortest = std::numeric_limits<double>::infinity();
  double thickest = 0.0;
  for (const XmlWall &w : walls) {
    const bool flat = w.y1 == w.y2;
    const bool upright = w.x1 == w.x2;
    if (!flat && !upright) return true;
    const double length = std::abs(w.x2 - w.x1) + std::abs(w.y2 - w.y1);
    if (length > 0.0) shortest = std::min(shortest, length);
    thickest = std::max(thickest, w.width);
  }
  return thickest >= kMaxThicknessPerLength * shortest;
}

XmlArenaRead read_xml_arena(std::string_view text, const std::string &file) {
  const Source src(text, file);
  const xml::Document doc = xml::Document::parse(text, file);
  const xml::Element world = xml::world_of(doc, src);
  XmlArenaRead read;
  Arena &arena = read.arena;
  arena.source = file;
  if (const auto name = world.attribute("name")) arena.name = *name;
  for (const XmlWall &w : read_walls(world, src)) {
    if (w.x1 == w.x2 && w.y1 == w.y2) throw src.error(w.element, nullptr, "wall has zero length");
    Obstacle o = Obstacle::from_segment(w.x1, w.y1, w.x2, w.y2, w.width, WallEnds::flush);
    o.where = src.at(w.element);
    o.height_m = kCourseWallHeight_m;
    arena.obstacles.push_back(o);
    if (arena.obstacles.size() > kMaxObstacles) {
      throw src.error(w.element, nullptr, fmt::format("more than {} walls: an arena holds at most {}", kMaxObstacles,
                                                       kMaxObstacles));
    }
  }
  if (const std::optional<xml::Element> b = world.first_child("boundary")) {
    arena.x_min_m = *number(*b, "xs", src, true);
    arena.x_max_m = *number(*b, "xe", src, true);
    arena.y_min_m = *number(*b, "ys", src, true);
    arena.y_max_m = *number(*b, "ye", src, true);
    arena.boundary_where = src.at(*b);
  }
  for (const xml::Element &starts : world.children("startPositions")) {
    for (const xml::Element &pos : starts.children("pos")) {
      const double x = *number(pos, "x", src, true);
      const double y = *number(pos, "y", src, true);
      const double theta = number(pos, "theta", src, false).value_or(std::numbers::pi / 2.0);
      arena.starts.push_back({x, y, theta});
      arena.start_where.push_back(src.at(pos, "x"));
    }
  }
  for (const xml::Element &e : world.children("goal")) {
    arena.goals.push_back({*number(e, "x", src, true), *number(e, "y", src, true)});
    arena.goal_where.push_back(src.at(e, "x"));
  }
  for (const xml::Element &e : world.children("landmark")) {
    const Landmark l = xml::read_landmark(e, src);
    arena.discs.push_back({l.x_m, l.y_m, kLandmarkRadius_m, ArenaDisc::Look{l.height_m, l.red, l.green, l.blue}});
  }
  return read;
}

std::string write_xml_arena(const Arena &arena) {
  std::string text = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<!-- maze_mapper arena: {} obstacle{}, boundary {} x {} m -->\n<world{}>\n"
      "  <boundary xs=\"{}\" xe=\"{}\" ys=\"{}\" ye=\"{}\"/>\n",
      arena.obstacles.size(), arena.obstacles.size() == 1 ? "" : "s", metres_text(arena.width_m()),
      metres_text(arena.height_m()),
      arena.name.empty() ? std::string() : fmt::format(" name=\"{}\"", common::xml_escaped(arena.name)),
      metres_text(arena.x_min_m), metres_text(arena.x_max_m), metres_text(arena.y_min_m), metres_text(arena.y_max_m));
  for (const Obstacle &o : arena.obstacles) {
    const auto l = o.centre_line();
    fmt::format_to(std::back_inserter(text), "  <wall x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" width=\"{}\"/>\n",
                   metres_text(l[0]), metres_text(l[1]), metres_text(l[2]), metres_text(l[3]), metres_text(l[4]));
  }
  if (!arena.starts.empty()) {
    text += "  <startPositions>\n";
    for (const ArenaPose &s : arena.starts) {
      fmt::format_to(std::back_inserter(text), "    <pos x=\"{}\" y=\"{}\" theta=\"{}\"/>\n", metres_text(s.x_m),
                     metres_text(s.y_m), s.yaw_rad);
    }
    text += "  </startPositions>\n";
  }
  for (const ArenaDisc &d : arena.discs) {
    if (!d.landmark) continue;  // a supervisor's cylinder: no element of the course's holds it
    fmt::format_to(std::back_inserter(text),
                   "  <landmark x=\"{}\" y=\"{}\" height=\"{}\" red=\"{}\" green=\"{}\" blue=\"{}\"/>\n",
                   metres_text(d.centre_x_m), metres_text(d.centre_y_m), metres_text(d.landmark->height_m),
                   d.landmark->red, d.landmark->green, d.landmark->blue);
  }
  int id = 0;
  for (const ArenaPoint &g : arena.goals) {
    fmt::format_to(std::back_inserter(text), "  <goal id=\"{}\" x=\"{}\" y=\"{}\"/>\n", id++, metres_text(g.x_m),
                   metres_text(g.y_m));
  }
  text += "</world>\n";
  return text;
}

}  // namespace maze
