#include "maze/world/world.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <filesystem>
#include <utility>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/random.hpp"
#include "maze/formats/solids_format.hpp"
#include "maze/formats/xml_solids.hpp"
#include "maze/formats/xml_format.hpp"
#include "maze/world/truth_raster.hpp"
#include "maze/world/validate.hpp"

namespace maze {

World::World(Maze maze, std::string file_path, Format file_format)
    : file(std::move(file_path)), format(file_format), shape_(std::move(maze)) {}

World::World(Arena arena, std::string file_path, Format file_format, std::optional<common::InputError> why_not_a_maze)
    : file(std::move(file_path)), format(file_format), shape_(std::move(arena)), why_not_a_maze_(std::move(why_not_a_maze)) {}

namespace {

[[noreturn]] void refuse_arena_as_maze(const std::string &file, const std::optional<common::InputError> &why) {
  const common::InputError reason =
      why ? *why : common::InputError(common::SourceLocation{file, 0, 0}, "an arena (obstacles in metres), not a grid maze");
  throw common::InputError(reason.where(), fmt::format("{}; it reads as an arena (a room of obstacles): map it with "
                                                       "`maze_mapper room {}`",
                                                       reason.message(), file));
}

}  // namespace

const Maze &World::maze() const {
  if (const Maze *m = lattice()) return *m;
  refuse_arena_as_maze(file, why_not_a_maze_);
}

Maze &World::maze() {
  if (Maze *m = std::get_if<Maze>(&shape_)) return *m;
  refuse_arena_as_maze(file, why_not_a_maze_);
}

const Arena &World::arena() const {
  assert(!on_lattice());
  return std::get<Arena>(shape_);
}

Arena &World::arena() {
  assert(!on_lattice());
  return std::get<Arena>(shape_);
}

World world_of(Maze maze) { return World(std::move(maze), "", Format::text_map); }

World world_of(Arena arena) { return World(std::move(arena), "", Format::room); }

Arena World::geometry() const { return on_lattice() ? arena_from_maze(maze()) : arena(); }

std::string World::name() const {
  if (!on_lattice() && !arena().name.empty()) return arena().name;
  return std::filesystem::path(file).stem().string();
}

namespace {

constexpr double kEnclosureCell_m = 0.05;

void require_inside(const Maze &maze, Cell c, std::string_view option) {
  if (!maze.contains(c)) {
    throw common::InputError(
        fmt::format("{} {},{} is outside the {}x{} maze", option, c.x, c.y, maze.width(), maze.height()));
  }
}

// An XML world reads --cell-size itself (read_xml's options).
void apply_cell_size(World &world, double cell_size_m) {
  if (world.format != Format::xml) world.maze().set_physical(cell_size_m, kDefaultWallThickness_m, 0.0, 0.0);
}

void apply_start_position(World &world, const WorldOverrides &o) {
  const std::vector<StartPosition> positions = world.maze().start_positions();
  std::size_t index = 0;
  if (o.start_position) {
    if (*o.start_position < 1 || static_cast<std::size_t>(*o.start_position) > positions.size()) {
      throw common::InputError(fmt::format("--start pos:{}: {} states {} start position{} (pos:1 to pos:{})",
                                           *o.start_position, world.file, positions.size(),
                                           positions.size() == 1 ? "" : "s", positions.size()));
    }
    index = static_cast<std::size_t>(*o.start_position - 1);
  } else if (o.random_start) {
    index = random_start_index(o.random_start_seed, positions.size());
  } else {
    return;
  }
  world.maze().set_start(positions[index].cell, positions[index].heading);
}

void apply(World &world, const WorldOverrides &o) {
  if (o.cell_size_m) apply_cell_size(world, *o.cell_size_m);
  apply_start_position(world, o);
  Maze &maze = world.maze();
  if (o.start) {
    require_inside(maze, *o.start, "--start");
    maze.set_start(*o.start, o.start_heading);
  }
  if (o.start_m) {
    const Maze &m = maze;
    const double column = std::floor(((*o.start_m)[0] - m.origin_x_m()) / m.cell_size_m());
    const double row = std::floor(((*o.start_m)[1] - m.origin_y_m()) / m.cell_size_m());
    if (!(column >= 0 && column < m.width() && row >= 0 && row < m.height())) {
      throw common::InputError(fmt::format("--start {:g}m,{:g}m is outside the maze ({:g} to {:g} m east, {:g} to {:g} m north)",
                                           (*o.start_m)[0], (*o.start_m)[1], m.origin_x_m(),
                                           m.origin_x_m() + m.width() * m.cell_size_m(), m.origin_y_m(),
                                           m.origin_y_m() + m.height() * m.cell_size_m()));
    }
    maze.set_start(Cell{static_cast<int>(column), static_cast<int>(row)}, o.start_heading);
  }
  if (o.goals) {
    for (const Cell g : *o.goals) require_inside(maze, g, "--goal");
    maze.clear_goals();
    for (const Cell g : *o.goals) maze.add_goal(g);
  }
  if (o.centre_goals) {
    maze.clear_goals();
    const int w = maze.width();
    const int h = maze.height();
    for (int y = (h - 1) / 2; y <= h / 2; ++y) {
      for (int x = (w - 1) / 2; x <= w / 2; ++x) maze.add_goal({x, y});
    }
  }
}

bool has_boundary(const Arena &a) { return a.x_min_m != a.x_max_m || a.y_min_m != a.y_max_m; }

void set_boundary(Arena &a, const std::array<double, 4> &b) {
  a.x_min_m = b[0];
  a.x_max_m = b[1];
  a.y_min_m = b[2];
  a.y_max_m = b[3];
}

void refuse_maze_overrides(const WorldOverrides &o, const std::string &path) {
  const char *option = o.cell_size_m                                ? "--cell-size"
                       : (o.start || o.start_m || o.start_position || o.random_start) ? "--start"
                       : (o.goals || o.centre_goals)                 ? "--goal"
                                                                     : nullptr;
  if (option != nullptr) {
    throw common::InputError(fmt::format("{} names cells of a grid maze; {} is an arena (obstacles in metres)",
                                         option, path));
  }
}

}  // namespace

std::size_t random_start_index(std::uint64_t seed, std::size_t count) {
  common::Rng rng(seed ^ 0x7374617274ULL);
  return static_cast<std::size_t>(rng.next_u64() % count);
}

namespace {

World read_maze_world(std::string_view text, const std::string &path, const WorldOverrides &overrides,
                      Format format) {
  std::vector<std::string> warnings;
  const auto read = [&]() -> Maze {
    if (format != Format::xml) return read_world(text, path, format);
    XmlRead xml = read_xml(text, path, XmlReadOptions{overrides.cell_size_m});
    warnings = std::move(xml.warnings);
    return std::move(xml.maze);
  };
  World world(read(), path, format);
  world.warnings = std::move(warnings);
  apply(world, overrides);
  if (const auto summary = unreachable_summary(world.maze())) {
    world.warnings.push_back(fmt::format("{}: warning: {}", path, *summary));
  }
  return world;
}

// What reading an arena's text as a grid maze says.
std::optional<common::InputError> why_not_a_maze(std::string_view text, const std::string &path, Format format) {
  try {
    (void)read_world(text, path, format);
  } catch (const common::InputError &e) {
    return e;
  }
  return std::nullopt;
}

World read_arena_world(std::string_view text, const std::string &path, const WorldOverrides &overrides,
                       Format format) {
  Arena arena;
  std::vector<std::string> warnings;
  if (format == Format::room) {
    arena = read_room(text, path);
  } else {
    XmlArenaRead read = read_xml_arena(text, path);
    arena = std::move(read.arena);
    warnings = std::move(read.warnings);
  }
  if (arena.name.empty()) arena.name = std::filesystem::path(path).stem().string();
  if (overrides.boundary_m) {
    set_boundary(arena, *overrides.boundary_m);
    arena.boundary_where = common::SourceLocation{};
    if (const ArenaCheck failure = check_arena_boundary(arena)) {
      throw common::InputError(fmt::format("--boundary {},{},{},{}: XS < XE and YS < YE", (*overrides.boundary_m)[0],
                                           (*overrides.boundary_m)[1], (*overrides.boundary_m)[2],
                                           (*overrides.boundary_m)[3]));
    }
  } else if (!has_boundary(arena)) {
    apply_default_boundary(arena);
  }
  validate_arena(arena, overrides.robot_radius_m);
  World world(std::move(arena), path, format, why_not_a_maze(text, path, format));
  world.warnings = std::move(warnings);
  return world;
}

}  // namespace

World load_world(const std::string &path, const WorldOverrides &overrides) {
  const WorldText file = read_world_file(path);
  return load_world_text(file.text, path, overrides, file.format);
}

World load_world_text(std::string_view text, const std::string &path, const WorldOverrides &overrides) {
  return load_world_text(text, path, overrides, detect_format(text, path));
}

World load_world_text(std::string_view text, const std::string &path, const WorldOverrides &overrides,
                      Format format) {
  if (!holds_arena(text, format, path, overrides.cell_size_m)) {
    if (overrides.boundary_m) {
      throw common::InputError(fmt::format("--boundary applies to arenas; {} is a grid maze", path));
    }
    return read_maze_world(text, path, overrides, format);
  }
  refuse_maze_overrides(overrides, path);
  return read_arena_world(text, path, overrides, format);
}

bool holds_arena(std::string_view text, Format format, const std::string &file, std::optional<double> cell_size_m) {
  return format == Format::room || (format == Format::xml && xml_world_is_arena(text, file, {cell_size_m}));
}

void apply_default_boundary(Arena &arena) {
  const double half = kCourseFloorSide_m / 2.0;
  const std::array<double, 4> floor{-half, half, -half, half};
  if (arena.obstacles.empty()) {
    set_boundary(arena, floor);
    return;
  }
  std::array<double, 4> box = arena.obstacles.front().bounds();
  for (const Obstacle &o : arena.obstacles) {
    const auto b = o.bounds();
    box = {std::min(box[0], b[0]), std::min(box[1], b[1]), std::max(box[2], b[2]), std::max(box[3], b[3])};
  }
  Arena enclosed = arena;
  set_boundary(enclosed, {box[0], box[2], box[1], box[3]});
  const ArenaPose start = arena.start();
  if (!(enclosed.width_m() > 0.0 && enclosed.height_m() > 0.0) || !enclosed.inside_boundary(start.x_m, start.y_m) ||
      enclosed.width_m() > kMaxArenaSide_m || enclosed.height_m() > kMaxArenaSide_m) {
    set_boundary(arena, floor);
    return;
  }
  const int nx = cells_along(enclosed.width_m(), kEnclosureCell_m);
  const int ny = cells_along(enclosed.height_m(), kEnclosureCell_m);
  const TruthRaster truth = rasterise_truth(enclosed, nx, ny, 0.0);
  bool open = false;
  for (int x = 0; x < nx && !open; ++x) open = truth.is_reachable(x, 0) || truth.is_reachable(x, ny - 1);
  for (int y = 0; y < ny && !open; ++y) open = truth.is_reachable(0, y) || truth.is_reachable(nx - 1, y);
  set_boundary(arena, open ? floor : std::array<double, 4>{box[0], box[2], box[1], box[3]});
}

}  // namespace maze
