#include "maze/world/maze.hpp"

#include <algorithm>
#include <cassert>
#include <deque>

namespace maze {

Maze::Maze(int width, int height)
    : width_(width),
      height_(height),
      horizontal_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height + 1), 0),
      vertical_(static_cast<std::size_t>(width + 1) * static_cast<std::size_t>(height), 0) {
  assert(width >= 1 && height >= 1 && width <= kMaxMazeSide && height <= kMaxMazeSide);
  for (int x = 0; x < width_; ++x) {
    horizontal_[horizontal_index(x, 0)] = 1;
    horizontal_[horizontal_index(x, height_)] = 1;
  }
  for (int y = 0; y < height_; ++y) {
    vertical_[vertical_index(0, y)] = 1;
    vertical_[vertical_index(width_, y)] = 1;
  }
}

std::size_t Maze::horizontal_index(int x, int y_line) const {
  return static_cast<std::size_t>(y_line) * static_cast<std::size_t>(width_) +
         static_cast<std::size_t>(x);
}

std::size_t Maze::vertical_index(int x_line, int y) const {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_ + 1) +
         static_cast<std::size_t>(x_line);
}

bool Maze::has_wall(Cell c, Side s) const {
  assert(contains(c));
  switch (s) {
    case Side::north: return horizontal_[horizontal_index(c.x, c.y + 1)] != 0;
    case Side::south: return horizontal_[horizontal_index(c.x, c.y)] != 0;
    case Side::west: return vertical_[vertical_index(c.x, c.y)] != 0;
    case Side::east: return vertical_[vertical_index(c.x + 1, c.y)] != 0;
  }
  return true;
}

void Maze::set_wall(Cell c, Side s, bool present) {
  assert(contains(c));
  const std::uint8_t v = present ? 1 : 0;
  switch (s) {
    case Side::north: horizontal_[horizontal_index(c.x, c.y + 1)] = v; break;
    case Side::south: horizontal_[horizontal_index(c.x, c.y)] = v; break;
    case Side::west: vertical_[vertical_index(c.x, c.y)] = v; break;
    case Side::east: vertical_[vertical_index(c.x + 1, c.y)] = v; break;
  }
}

std::vector<StartPosition> Maze::start_positions() const {
  if (start_positions_.empty()) return {StartPosition{start_, start_heading_}};
  return start_positions_;
}

void Maze::set_start_positions(std::vector<StartPosition> positions) {
  if (positions.size() <= 1) {
    start_positions_.clear();
    return;
  }
  start_positions_ = std::move(positions);
}

void Maze::set_physical(double cell_size_m, double wall_thickness_m, double origin_x_m,
                        double origin_y_m) {
  cell_size_m_ = cell_size_m;
  wall_thickness_m_ = wall_thickness_m;
  origin_x_m_ = origin_x_m;
  origin_y_m_ = origin_y_m;
}

std::vector<bool> Maze::reachable_from_start() const {
  std::vector<bool> seen(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), false);
  if (!contains(start_)) return seen;
  auto at = [this](Cell c) {
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.x);
  };
  std::deque<Cell> queue{start_};
  seen[at(start_)] = true;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    for (const Side s : kSides) {
      const Cell n = neighbour(c, s);
      if (has_wall(c, s) || !contains(n) || seen[at(n)]) continue;
      seen[at(n)] = true;
      queue.push_back(n);
    }
  }
  return seen;
}

std::size_t Maze::reachable_count() const {
  std::size_t count = 0;
  for (const bool r : reachable_from_start()) count += r ? 1 : 0;
  return count;
}

std::size_t Maze::passage_count() const {
  std::size_t open = 0;
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      if (x + 1 < width_ && !has_wall({x, y}, Side::east)) ++open;
      if (y + 1 < height_ && !has_wall({x, y}, Side::north)) ++open;
    }
  }
  return open;
}

std::size_t Maze::interior_side_count() const {
  const auto w = static_cast<std::size_t>(width_);
  const auto h = static_cast<std::size_t>(height_);
  return w * (h - 1) + h * (w - 1);
}

void Maze::add_goal(Cell c) {
  const auto at = std::lower_bound(goals_.begin(), goals_.end(), c);
  if (at == goals_.end() || *at != c) goals_.insert(at, c);
}

bool Maze::is_goal(Cell c) const {
  for (const Cell g : goals_) {
    if (g == c) return true;
  }
  return false;
}

std::vector<WallSegment> Maze::wall_segments() const {
  std::vector<WallSegment> segments;
  const double s = cell_size_m_;
  for (int y_line = 0; y_line <= height_; ++y_line) {
    int x = 0;
    while (x < width_) {
      if (horizontal_[horizontal_index(x, y_line)] == 0) {
        ++x;
        continue;
      }
      const int begin = x;
      while (x < width_ && horizontal_[horizontal_index(x, y_line)] != 0) ++x;
      segments.push_back({origin_x_m_ + begin * s, origin_y_m_ + y_line * s, origin_x_m_ + x * s,
                          origin_y_m_ + y_line * s});
    }
  }
  for (int x_line = 0; x_line <= width_; ++x_line) {
    int y = 0;
    while (y < height_) {
      if (vertical_[vertical_index(x_line, y)] == 0) {
        ++y;
        continue;
      }
      const int begin = y;
      while (y < height_ && vertical_[vertical_index(x_line, y)] != 0) ++y;
      segments.push_back({origin_x_m_ + x_line * s, origin_y_m_ + begin * s, origin_x_m_ + x_line * s,
                          origin_y_m_ + y * s});
    }
  }
  return segments;
}

namespace {

// Whether the landmark's disc overlaps (not just touches) the square [x0, x1] x [y0, y1].
bool disc_overlaps(const Landmark &l, double x0, double y0, double x1, double y1) {
  const double dx = l.x_m - std::clamp(l.x_m, x0, x1);
  const double dy = l.y_m - std::clamp(l.y_m, y0, y1);
  return dx * dx + dy * dy < kLandmarkRadius_m * kLandmarkRadius_m;
}

// Whether a landmark overlaps a sub-cell of cell c on the robot's path from its centre to
// side s: along the middle row or column, from the sub-cell after the centre to the band
// middle (k odd; at K = 3 the band middle alone; the rule of controller/mapping/walls.hpp).
bool path_holds_solid(const Maze &maze, Cell c, Side s, int k) {
  const double size = maze.cell_size_m();
  const double sub = size / k;
  const int mid = k / 2;
  const int step_column = s == Side::east ? 1 : s == Side::west ? -1 : 0;
  const int step_row = s == Side::north ? 1 : s == Side::south ? -1 : 0;
  for (int n = 1; n <= mid; ++n) {
    // The sub-cell's column from the west and row from the south, in sub-cells of the cell.
    const double x0 = maze.origin_x_m() + c.x * size + (mid + step_column * n) * sub;
    const double y0 = maze.origin_y_m() + c.y * size + (mid + step_row * n) * sub;
    const bool hit = std::any_of(maze.landmarks().begin(), maze.landmarks().end(),
                                 [&](const Landmark &l) { return disc_overlaps(l, x0, y0, x0 + sub, y0 + sub); });
    if (hit) return true;
  }
  return false;
}

}  // namespace

Maze with_solid_sides(const Maze &maze, int subcells) {
  Maze scored = maze;
  if (maze.landmarks().empty()) return scored;
  for (int y = 0; y < maze.height(); ++y) {
    for (int x = 0; x < maze.width(); ++x) {
      for (const Side s : kSides) {
        if (path_holds_solid(maze, {x, y}, s, subcells)) scored.set_wall({x, y}, s, true);
      }
    }
  }
  return scored;
}

}  // namespace maze
