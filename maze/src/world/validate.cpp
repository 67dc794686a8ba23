#include "maze/world/validate.hpp"

#include <cassert>
#include <cstddef>

#include <fmt/format.h>

namespace maze {

namespace {

std::size_t index_of(const RawMaze &raw, Cell c) {
  return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(raw.width) +
         static_cast<std::size_t>(c.x);
}

common::SourceLocation where_is(const RawMaze &raw, Cell c, Side s) {
  if (raw.where) return raw.where(c, s);
  return {};
}


}  // namespace

void RawMaze::resize(int w, int h) {
  assert(w >= 1 && h >= 1 && w <= kMaxMazeSide && h <= kMaxMazeSide);
  width = w;
  height = h;
  walls.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), {false, false, false, false});
}

bool RawMaze::wall(Cell c, Side s) const { return walls[index_of(*this, c)][static_cast<std::size_t>(s)]; }

void RawMaze::set(Cell c, Side s, bool present) {
  walls[index_of(*this, c)][static_cast<std::size_t>(s)] = present;
}

CheckResult check_size(const RawMaze &raw) {
  if (raw.width >= 1 && raw.height >= 1 && raw.width <= kMaxMazeSide && raw.height <= kMaxMazeSide)
    return std::nullopt;
  return common::InputError(where_is(raw, {0, 0}, Side::north),
                            fmt::format("maze is {}x{} cells; each side must be 1 to {}", raw.width,
                                        raw.height, kMaxMazeSide));
}

CheckResult check_enclosed(const RawMaze &raw) {
  // Reading order of a text map: north edge, then each row's west and east sides, south edge.
  auto missing = [&raw](Cell c, Side s) -> CheckResult {
    if (raw.wall(c, s)) return std::nullopt;
    return common::InputError(where_is(raw, c, s),
                              fmt::format("cell ({},{}): {} wall missing on the maze's edge", c.x,
                                          c.y, to_string(s)));
  };
  for (int x = 0; x < raw.width; ++x) {
    if (auto e = missing({x, raw.height - 1}, Side::north)) return e;
  }
  for (int y = raw.height - 1; y >= 0; --y) {
    if (auto e = missing({0, y}, Side::west)) return e;
    if (auto e = missing({raw.width - 1, y}, Side::east)) return e;
  }
  for (int x = 0; x < raw.width; ++x) {
    if (auto e = missing({x, 0}, Side::south)) return e;
  }
  return std::nullopt;
}

CheckResult check_consistent(const RawMaze &raw) {
  auto compare = [&raw](Cell a, Side s) -> CheckResult {
    const Cell b = neighbour(a, s);
    const Side t = opposite(s);
    if (raw.wall(a, s) == raw.wall(b, t)) return std::nullopt;
    const Cell walled = raw.wall(a, s) ? a : b;
    const Cell open = raw.wall(a, s) ? b : a;
    const Side walled_side = raw.wall(a, s) ? s : t;
    return common::InputError(
        where_is(raw, open, opposite(walled_side)),
        fmt::format("cell ({},{}): {} wall missing on the {} side of ({},{})", walled.x, walled.y,
                    to_string(walled_side), to_string(opposite(walled_side)), open.x, open.y));
  };
  for (int y = 0; y < raw.height; ++y) {
    for (int x = 0; x < raw.width; ++x) {
      if (x + 1 < raw.width) {
        if (auto e = compare({x, y}, Side::east)) return e;
      }
      if (y + 1 < raw.height) {
        if (auto e = compare({x, y}, Side::north)) return e;
      }
    }
  }
  return std::nullopt;
}

namespace {
bool inside(const RawMaze &raw, Cell c) {
  return c.x >= 0 && c.y >= 0 && c.x < raw.width && c.y < raw.height;
}
}  // namespace

CheckResult check_start_inside(const RawMaze &raw) {
  if (inside(raw, raw.start)) return std::nullopt;
  return common::InputError(raw.start_where,
                            fmt::format("start ({},{}) is outside the {}x{} maze", raw.start.x,
                                        raw.start.y, raw.width, raw.height));
}

CheckResult check_goals_inside(const RawMaze &raw) {
  assert(raw.goals.size() == raw.goal_where.size());
  for (std::size_t i = 0; i < raw.goals.size(); ++i) {
    const Cell g = raw.goals[i];
    if (!inside(raw, g)) {
      return common::InputError(raw.goal_where[i],
                                fmt::format("goal ({},{}) is outside the {}x{} maze", g.x, g.y,
                                            raw.width, raw.height));
    }
  }
  return std::nullopt;
}

Maze build_maze(const RawMaze &raw) {
  if (auto e = check_size(raw)) throw *e;
  for (const auto check : {check_enclosed, check_consistent, check_start_inside, check_goals_inside}) {
    if (auto e = check(raw)) throw *e;
  }
  Maze maze(raw.width, raw.height);
  for (int y = 0; y < raw.height; ++y) {
    for (int x = 0; x < raw.width; ++x) {
      // Consistent, so the east and north sides of every cell say everything inside.
      if (x + 1 < raw.width) maze.set_wall({x, y}, Side::east, raw.wall({x, y}, Side::east));
      if (y + 1 < raw.height) maze.set_wall({x, y}, Side::north, raw.wall({x, y}, Side::north));
    }
  }
  maze.set_start(raw.start, raw.start_heading);
  maze.set_start_positions(raw.start_positions);
  maze.set_landmarks(raw.landmarks);
  for (const Cell g : raw.goals) maze.add_goal(g);
  maze.set_physical(raw.cell_size_m, raw.wall_thickness_m, raw.origin_x_m, raw.origin_y_m);
  maze.set_wall_height_m(raw.wall_height_m);
  return maze;
}

std::optional<std::string> unreachable_summary(const Maze &maze) {
  constexpr std::size_t kShown = 5;
  const auto reachable = maze.reachable_from_start();
  std::size_t count = 0;
  std::string cells;
  // North row first, west to east, as the text map shows them.
  for (int y = maze.height() - 1; y >= 0; --y) {
    for (int x = 0; x < maze.width(); ++x) {
      const auto i = static_cast<std::size_t>(y) * static_cast<std::size_t>(maze.width()) +
                     static_cast<std::size_t>(x);
      if (reachable[i]) continue;
      ++count;
      if (count <= kShown) cells += fmt::format("{}({},{})", count == 1 ? "" : ", ", x, y);
    }
  }
  if (count == 0) return std::nullopt;
  return fmt::format("{} cell{} cannot be reached from the start: {}{}", count, count == 1 ? "" : "s",
                     cells, count > kShown ? ", ..." : "");
}

std::string describe_byte(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (c == '\t') return "tab";
  if (u >= 0x20 && u < 0x7f) return fmt::format("'{}'", c);
  return fmt::format("byte 0x{:02x}", u);
}

}  // namespace maze
