#include "maze/generate/generator.hpp"

#include <cassert>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <span>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"

namespace maze {

namespace {

// An interior side: the east or north side of a cell.
struct Door {
  Cell cell;
  Side side;  // east or north
};

std::size_t index_of(const Maze &m, Cell c) {
  return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(m.width()) + static_cast<std::size_t>(c.x);
}

Maze walled(int width, int height) {
  Maze m(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      m.set_wall({x, y}, Side::east, true);
      m.set_wall({x, y}, Side::north, true);
    }
  }
  return m;
}

void carve_dfs(Maze &m, common::Rng &rng) {
  std::vector<bool> seen(static_cast<std::size_t>(m.width()) * static_cast<std::size_t>(m.height()), false);
  std::vector<Cell> stack{{0, 0}};
  seen[0] = true;
  while (!stack.empty()) {
    const Cell c = stack.back();
    Side options[4];
    std::size_t n = 0;
    for (const Side s : kSides) {
      const Cell next = neighbour(c, s);
      if (m.contains(next) && !seen[index_of(m, next)]) options[n++] = s;
    }
    if (n == 0) {
      stack.pop_back();
      continue;
    }
    const Side s = options[rng.below(n)];
    const Cell next = neighbour(c, s);
    m.set_wall(c, s, false);
    seen[index_of(m, next)] = true;
    stack.push_back(next);
  }
}

std::vector<Door> interior_doors(const Maze &m) {
  std::vector<Door> doors;
  doors.reserve(m.interior_side_count());
  for (int y = 0; y < m.height(); ++y) {
    for (int x = 0; x < m.width(); ++x) {
      if (x + 1 < m.width()) doors.push_back({{x, y}, Side::east});
      if (y + 1 < m.height()) doors.push_back({{x, y}, Side::north});
    }
  }
  return doors;
}

std::size_t find_root(std::vector<std::size_t> &parent, std::size_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

void carve_kruskal(Maze &m, common::Rng &rng) {
  auto doors = interior_doors(m);
  rng.shuffle(std::span<Door>(doors));
  std::vector<std::size_t> parent(static_cast<std::size_t>(m.width()) * static_cast<std::size_t>(m.height()));
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (const Door &d : doors) {
    const std::size_t a = find_root(parent, index_of(m, d.cell));
    const std::size_t b = find_root(parent, index_of(m, neighbour(d.cell, d.side)));
    if (a == b) continue;
    parent[a] = b;
    m.set_wall(d.cell, d.side, false);
  }
}

void carve_prim(Maze &m, common::Rng &rng) {
  std::vector<bool> in(static_cast<std::size_t>(m.width()) * static_cast<std::size_t>(m.height()), false);
  std::vector<Door> frontier;  // sides from a cell in the maze to one maybe not yet in it
  auto add = [&](Cell c) {
    in[index_of(m, c)] = true;
    for (const Side s : kSides) {
      const Cell next = neighbour(c, s);
      if (m.contains(next) && !in[index_of(m, next)]) frontier.push_back({c, s});
    }
  };
  add({0, 0});
  while (!frontier.empty()) {
    const auto pick = static_cast<std::size_t>(rng.below(frontier.size()));
    const Door d = frontier[pick];
    frontier[pick] = frontier.back();
    frontier.pop_back();
    const Cell next = neighbour(d.cell, d.side);
    if (in[index_of(m, next)]) continue;
    m.set_wall(d.cell, d.side, false);
    add(next);
  }
}

void remove_loop_walls(Maze &m, common::Rng &rng, std::size_t count) {
  std::vector<Door> walls;
  for (const Door &d : interior_doors(m)) {
    if (m.has_wall(d.cell, d.side)) walls.push_back(d);
  }
  assert(count <= walls.size());
  // A partial Fisher-Yates: the first `count` entries become a uniform random choice.
  for (std::size_t i = 0; i < count; ++i) {
    const auto j = i + static_cast<std::size_t>(rng.below(walls.size() - i));
    std::swap(walls[i], walls[j]);
    m.set_wall(walls[i].cell, walls[i].side, false);
  }
}

void set_centre_goals(Maze &m) {
  const int xs[] = {(m.width() - 1) / 2, m.width() / 2};
  const int ys[] = {(m.height() - 1) / 2, m.height() / 2};
  for (const int y : ys) {
    for (const int x : xs) {
      m.add_goal({x, y});
    }
  }
}

int parse_side(std::string_view text, std::string_view whole) {
  int value = 0;
  const auto [stop, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || stop != text.data() + text.size() || value < 1 || value > kMaxMazeSide) {
    throw common::InputError(
        fmt::format("size must be WxH with W and H from 1 to {} (e.g. 16x16), got '{}'", kMaxMazeSide, whole));
  }
  return value;
}

}  // namespace

void GeneratorOptions::validate() const {
  if (width < 1 || height < 1 || width > kMaxMazeSide || height > kMaxMazeSide) {
    throw common::InputError(fmt::format("maze size {}x{}: each side must be 1 to {}", width, height, kMaxMazeSide));
  }
  if (!(loops >= 0.0 && loops <= 1.0)) {
    throw common::InputError(fmt::format("--loops must be a fraction from 0 to 1, got {}", loops));
  }
}

Algorithm parse_algorithm(std::string_view name) {
  if (name == "dfs") return Algorithm::dfs;
  if (name == "kruskal") return Algorithm::kruskal;
  if (name == "prim") return Algorithm::prim;
  throw common::InputError(fmt::format("--algorithm must be dfs, kruskal or prim, got '{}'", name));
}

Cell parse_size(std::string_view text) {
  const std::size_t x = text.find('x');
  if (x == std::string_view::npos) {
    throw common::InputError(
        fmt::format("size must be WxH with W and H from 1 to {} (e.g. 16x16), got '{}'", kMaxMazeSide, text));
  }
  return {parse_side(text.substr(0, x), text), parse_side(text.substr(x + 1), text)};
}

std::size_t loop_walls_removed(const GeneratorOptions &options) {
  const auto cells = static_cast<std::size_t>(options.width) * static_cast<std::size_t>(options.height);
  const auto w = static_cast<std::size_t>(options.width);
  const auto h = static_cast<std::size_t>(options.height);
  const std::size_t walls_left = w * (h - 1) + h * (w - 1) - (cells - 1);
  return static_cast<std::size_t>(std::llround(options.loops * static_cast<double>(walls_left)));
}

Maze generate_maze(const GeneratorOptions &options) {
  Maze m = walled(options.width, options.height);
  common::Rng rng(options.seed);
  switch (options.algorithm) {
    case Algorithm::dfs: carve_dfs(m, rng); break;
    case Algorithm::kruskal: carve_kruskal(m, rng); break;
    case Algorithm::prim: carve_prim(m, rng); break;
  }
  remove_loop_walls(m, rng, loop_walls_removed(options));
  m.set_start({0, 0}, Side::north);
  set_centre_goals(m);
  return m;
}

}  // namespace maze
