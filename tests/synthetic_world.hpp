#pragma once
// Test helpers: a hand-written maze (the truth, for tests only) drawn as a micromouse text
// map, and a lidar range image cast analytically against its walls (the conventions' geometry:
// each wall a rectangle centred on its side, side length plus thickness long).

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "mapping/grid_types.hpp"
#include "sensing/scan.hpp"
#include "mapping/walls.hpp"

namespace testing_world {

struct TextMaze {
  int width = 0;
  int height = 0;
  std::vector<std::string> lines;  // 2H+1 lines of 4W+1 characters, north first

  // Parses the drawing; lines are separated by '\n'.
  explicit TextMaze(std::string_view drawing) {
    std::size_t start = 0;
    while (start < drawing.size()) {
      const std::size_t end = drawing.find('\n', start);
      const std::size_t stop = end == std::string_view::npos ? drawing.size() : end;
      lines.emplace_back(drawing.substr(start, stop - start));
      start = stop + 1;
    }
    height = static_cast<int>(lines.size() - 1) / 2;
    width = static_cast<int>(lines[0].size() - 1) / 4;
  }

  bool wall(mapping::Cell c, mapping::Heading h) const {
    const int row = 2 * (height - 1 - c.y) + 1;  // the line through the cell's centre
    const int col = 4 * c.x + 2;
    char ch = ' ';
    switch (h) {
      case mapping::Heading::north: ch = lines[static_cast<std::size_t>(row - 1)][static_cast<std::size_t>(col)]; break;
      case mapping::Heading::south: ch = lines[static_cast<std::size_t>(row + 1)][static_cast<std::size_t>(col)]; break;
      case mapping::Heading::east: ch = lines[static_cast<std::size_t>(row)][static_cast<std::size_t>(col + 2)]; break;
      case mapping::Heading::west: ch = lines[static_cast<std::size_t>(row)][static_cast<std::size_t>(col - 2)]; break;
    }
    return ch != ' ';
  }
};

struct Box {
  double x0, y0, x1, y1;
};

// Every wall of the maze as a rectangle (a shared side appears twice; harmless).
inline std::vector<Box> wall_boxes(const TextMaze &maze, double cell_m, double thickness_m) {
  std::vector<Box> boxes;
  const double t = thickness_m / 2.0;
  for (int y = 0; y < maze.height; ++y) {
    for (int x = 0; x < maze.width; ++x) {
      const double x0 = x * cell_m, y0 = y * cell_m, x1 = x0 + cell_m, y1 = y0 + cell_m;
      const mapping::Cell c{x, y};
      if (maze.wall(c, mapping::Heading::north)) boxes.push_back({x0 - t, y1 - t, x1 + t, y1 + t});
      if (maze.wall(c, mapping::Heading::south)) boxes.push_back({x0 - t, y0 - t, x1 + t, y0 + t});
      if (maze.wall(c, mapping::Heading::east)) boxes.push_back({x1 - t, y0 - t, x1 + t, y1 + t});
      if (maze.wall(c, mapping::Heading::west)) boxes.push_back({x0 - t, y0 - t, x0 + t, y1 + t});
    }
  }
  return boxes;
}

// Distance along (dx, dy) from (px, py) to the box (slab method), or +inf.
inline double ray_box(double px, double py, double dx, double dy, const Box &b) {
  double t_min = 0.0, t_max = std::numeric_limits<double>::infinity();
  const double p[2] = {px, py}, d[2] = {dx, dy}, lo[2] = {b.x0, b.y0}, hi[2] = {b.x1, b.y1};
  for (int a = 0; a < 2; ++a) {
    if (std::abs(d[a]) < 1e-15) {
      if (p[a] < lo[a] || p[a] > hi[a]) return std::numeric_limits<double>::infinity();
      continue;
    }
    double t0 = (lo[a] - p[a]) / d[a], t1 = (hi[a] - p[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    t_min = std::max(t_min, t0);
    t_max = std::min(t_max, t1);
  }
  return t_min <= t_max ? t_min : std::numeric_limits<double>::infinity();
}

// The range image a noiseless lidar at `origin` facing yaw would read: n beams over fov,
// the conventions' beam order, +inf outside [min, max].
inline std::vector<float> range_image(const std::vector<Box> &boxes, mapping::Point origin,
                                      double yaw_rad, int n, double fov_rad, double min_m,
                                      double max_m) {
  std::vector<float> ranges(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double a = yaw_rad + fov_rad / 2.0 - i * fov_rad / n;
    double best = std::numeric_limits<double>::infinity();
    for (const Box &b : boxes) best = std::min(best, ray_box(origin.x_m, origin.y_m, std::cos(a), std::sin(a), b));
    ranges[static_cast<std::size_t>(i)] = best >= min_m && best <= max_m
                                              ? static_cast<float>(best)
                                              : std::numeric_limits<float>::infinity();
  }
  return ranges;
}

// A hambot-like scan (360 beams over 2 pi, 0.05 ... 12 m) over the given ranges.
inline sensing::LidarScan hambot_scan(mapping::Point origin, double yaw_rad,
                                      const std::vector<float> &ranges) {
  sensing::LidarScan s;
  s.origin = origin;
  s.yaw_rad = yaw_rad;
  s.fov_rad = 2.0 * std::numbers::pi;
  s.min_range_m = 0.05;
  s.max_range_m = 12.0;
  s.ranges = ranges;
  return s;
}

}  // namespace testing_world
