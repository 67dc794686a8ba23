#include "maze/world/arena_world.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "common/angles.hpp"
#include "common/error.hpp"
#include "maze/world/arena_truth.hpp"
#include "maze/formats/room_format.hpp"
#include "maze/formats/xml_arena.hpp"
#include "maze/formats/xml_format.hpp"

namespace maze {

namespace {

constexpr double kEnclosureCell_m = 0.05;

std::string format_name(Format format) {
  switch (format) {
    case Format::text_map: return "text map";
    case Format::num: return "num";
    case Format::xml: return "XML";
    case Format::wbt: return "Webots .wbt";
    case Format::maz: return ".maz";
    case Format::room: return "room";
  }
  return "";
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
  const ArenaTruth truth = rasterise_arena(enclosed, nx, ny, 0.0);
  bool open = false;
  for (int x = 0; x < nx && !open; ++x) open = truth.is_reachable(x, 0) || truth.is_reachable(x, ny - 1);
  for (int y = 0; y < ny && !open; ++y) open = truth.is_reachable(0, y) || truth.is_reachable(nx - 1, y);
  set_boundary(arena, open ? floor : std::array<double, 4>{box[0], box[2], box[1], box[3]});
}

bool holds_arena(std::string_view text, Format format, const std::string &file, std::optional<double> cell_size_m) {
  return format == Format::room || (format == Format::xml && xml_world_is_arena(text, file, {cell_size_m}));
}

ArenaWorld read_arena_world(std::string_view text, const std::string &file, const ArenaOverrides &overrides) {
  return read_arena_world(text, file, overrides, detect_format(text, file));
}

ArenaWorld read_arena_world(std::string_view text, const std::string &file, const ArenaOverrides &overrides,
                            Format format) {
  ArenaWorld world;
  world.file = file;
  world.format = format;
  if (world.format == Format::room) {
    world.arena = read_room(text, file);
  } else if (holds_arena(text, world.format, file)) {
    XmlArenaRead read = read_xml_arena(text, file);
    world.arena = std::move(read.arena);
    world.warnings = std::move(read.warnings);
  } else {
    throw common::InputError(common::SourceLocation{file, 0, 0},
                             fmt::format("a {} file holds a grid maze, not an arena", format_name(world.format)));
  }
  if (world.arena.name.empty()) world.arena.name = std::filesystem::path(file).stem().string();
  if (overrides.boundary_m) {
    set_boundary(world.arena, *overrides.boundary_m);
    world.arena.boundary_where = common::SourceLocation{};
    if (const ArenaCheck failure = check_arena_boundary(world.arena)) {
      throw common::InputError(fmt::format("--boundary {},{},{},{}: XS < XE and YS < YE", (*overrides.boundary_m)[0],
                                           (*overrides.boundary_m)[1], (*overrides.boundary_m)[2],
                                           (*overrides.boundary_m)[3]));
    }
  } else if (!has_boundary(world.arena)) {
    apply_default_boundary(world.arena);
  }
  validate_arena(world.arena, overrides.robot_radius_m);
  return world;
}

AnyWorld load_any_world(const std::string &path, const WorldOverrides &maze_overrides,
                        const ArenaOverrides &arena_overrides) {
  const WorldText file = read_world_file(path);
  if (!holds_arena(file.text, file.format, path, maze_overrides.cell_size_m)) {
    if (arena_overrides.boundary_m) {
      throw common::InputError(fmt::format("--boundary applies to arenas; {} is a grid maze", path));
    }
    return load_world_text(file.text, path, maze_overrides, file.format);
  }
  refuse_maze_overrides(maze_overrides, path);
  return read_arena_world(file.text, path, arena_overrides, file.format);
}

bool is_arena(const AnyWorld &world) { return std::holds_alternative<ArenaWorld>(world); }

Arena world_geometry(const AnyWorld &world) {
  if (const auto *arena = std::get_if<ArenaWorld>(&world)) return arena->arena;
  return arena_from_maze(std::get<World>(world).maze);
}

const Maze *lattice_view(const AnyWorld &world) {
  const auto *maze = std::get_if<World>(&world);
  return maze == nullptr ? nullptr : &maze->maze;
}

const std::vector<std::string> &world_warnings(const AnyWorld &world) {
  return std::visit([](const auto &w) -> const std::vector<std::string> & { return w.warnings; }, world);
}

std::string format_arena(const Arena &arena, Format format) {
  if (format == Format::room) return write_room(arena);
  if (format == Format::xml) return write_xml_arena(arena);
  throw common::InputError(
      fmt::format("a {} file holds a grid maze; an arena is written as .room or .xml", format_name(format)));
}

void save_arena(const Arena &arena, const std::string &path) {
  write_file_atomically(path, format_arena(arena, format_for_output(path)));
}

Arena arena_from_maze(const Maze &maze) {
  Arena a;
  const double s = maze.cell_size_m();
  a.x_min_m = maze.origin_x_m();
  a.y_min_m = maze.origin_y_m();
  a.x_max_m = a.x_min_m + maze.width() * s;
  a.y_max_m = a.y_min_m + maze.height() * s;
  for (const WallSegment &w : maze.wall_segments()) {
    a.obstacles.push_back(
        Obstacle::from_segment(w.x1_m, w.y1_m, w.x2_m, w.y2_m, maze.wall_thickness_m(), WallEnds::capped));
  }
  const auto centre = [&](Cell c) { return ArenaPoint{a.x_min_m + (c.x + 0.5) * s, a.y_min_m + (c.y + 0.5) * s}; };
  const ArenaPoint start = centre(maze.start());
  a.starts.push_back({start.x_m, start.y_m, common::compass_yaw_rad(static_cast<int>(maze.start_heading()))});
  for (const Cell g : maze.goals()) a.goals.push_back(centre(g));
  return a;
}

}  // namespace maze
