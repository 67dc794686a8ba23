// write_xml and write_xml_keeping_origin (maze/xml_format.hpp): a maze as the course writes
// its XML worlds.
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "maze/formats/xml_format.hpp"

namespace maze {

namespace {

// The course's layout: every merged wall, every start position, the goals, the landmarks,
// with the maze's south-west corner at (ox, oy).
std::string write_xml_at(const Maze &maze, double ox, double oy) {
  const double s = maze.cell_size_m();
  const double dx = ox - maze.origin_x_m();
  const double dy = oy - maze.origin_y_m();
  std::string text = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<!-- maze_mapper world: {}x{} cells of {} m, walls {} m thick -->\n<world cellSize=\"{}\">\n",
      maze.width(), maze.height(), s, maze.wall_thickness_m(), s);
  for (const WallSegment &w : maze.wall_segments()) {
    fmt::format_to(std::back_inserter(text), "  <wall x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" width=\"{}\"/>\n",
                   w.x1_m + dx, w.y1_m + dy, w.x2_m + dx, w.y2_m + dy, maze.wall_thickness_m());
  }
  for (const Landmark &l : maze.landmarks()) {
    fmt::format_to(std::back_inserter(text),
                   "  <landmark x=\"{}\" y=\"{}\" height=\"{}\" red=\"{}\" green=\"{}\" blue=\"{}\"/>\n",
                   l.x_m + dx, l.y_m + dy, l.height_m, l.red, l.green, l.blue);
  }
  constexpr double kTheta[] = {std::numbers::pi / 2, 0.0, -std::numbers::pi / 2, std::numbers::pi};
  const auto pos = [&](Cell c, Side heading) {
    fmt::format_to(std::back_inserter(text), "    <pos x=\"{}\" y=\"{}\" theta=\"{}\"/>\n", ox + (c.x + 0.5) * s,
                   oy + (c.y + 0.5) * s, kTheta[static_cast<int>(heading)]);
  };
  // The start first (a file's first position is its start), then the others in order.
  text += "  <startPositions>\n";
  pos(maze.start(), maze.start_heading());
  const std::vector<StartPosition> positions = maze.start_positions();
  bool start_written = false;
  for (const StartPosition &p : positions) {
    if (!start_written && p.cell == maze.start() && p.heading == maze.start_heading()) {
      start_written = true;
      continue;
    }
    pos(p.cell, p.heading);
  }
  text += "  </startPositions>\n";
  int id = 0;
  for (const Cell g : maze.goals()) {
    fmt::format_to(std::back_inserter(text), "  <goal id=\"{}\" x=\"{}\" y=\"{}\"/>\n", id++, ox + (g.x + 0.5) * s,
                   oy + (g.y + 0.5) * s);
  }
  text += "</world>\n";
  return text;
}

}  // namespace

std::string write_xml(const Maze &maze) {
  const double s = maze.cell_size_m();
  return write_xml_at(maze, -maze.width() * s / 2.0, -maze.height() * s / 2.0);
}

std::string write_xml_keeping_origin(const Maze &maze) {
  return write_xml_at(maze, maze.origin_x_m(), maze.origin_y_m());
}

}  // namespace maze
