#include "maze/world/world.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/input_file.hpp"
#include "maze/world/arena_world.hpp"
#include "maze/formats/maz_format.hpp"
#include "common/random.hpp"
#include "maze/formats/num_format.hpp"
#include "maze/formats/room_format.hpp"
#include "maze/formats/text_map.hpp"
#include "maze/world/validate.hpp"
#include "maze/formats/wbt_format.hpp"
#include "maze/formats/xml_format.hpp"

namespace maze {

namespace {

constexpr std::size_t kMaxFileBytes = std::size_t{1} << 30;

// Closes a file descriptor when it goes out of scope.
common::InputError cannot(std::string_view what, const std::string &path, int error) {
  return common::InputError(fmt::format("cannot {} {}: {}", what, path, std::strerror(error)));
}

void require_inside(const Maze &maze, Cell c, std::string_view option) {
  if (!maze.contains(c)) {
    throw common::InputError(
        fmt::format("{} {},{} is outside the {}x{} maze", option, c.x, c.y, maze.width(), maze.height()));
  }
}

// An XML world reads --cell-size itself (read_xml's options).
void apply_cell_size(World &world, double cell_size_m) {
  if (world.format != Format::xml) world.maze.set_physical(cell_size_m, kDefaultWallThickness_m, 0.0, 0.0);
}

void apply_start_position(World &world, const WorldOverrides &o) {
  const std::vector<StartPosition> positions = world.maze.start_positions();
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
  world.maze.set_start(positions[index].cell, positions[index].heading);
}

void apply(World &world, const WorldOverrides &o) {
  if (o.cell_size_m) apply_cell_size(world, *o.cell_size_m);
  apply_start_position(world, o);
  if (o.start) {
    require_inside(world.maze, *o.start, "--start");
    world.maze.set_start(*o.start, o.start_heading);
  }
  if (o.start_m) {
    const Maze &m = world.maze;
    const double column = std::floor(((*o.start_m)[0] - m.origin_x_m()) / m.cell_size_m());
    const double row = std::floor(((*o.start_m)[1] - m.origin_y_m()) / m.cell_size_m());
    if (!(column >= 0 && column < m.width() && row >= 0 && row < m.height())) {
      throw common::InputError(fmt::format("--start {:g}m,{:g}m is outside the maze ({:g} to {:g} m east, {:g} to {:g} m north)",
                                           (*o.start_m)[0], (*o.start_m)[1], m.origin_x_m(),
                                           m.origin_x_m() + m.width() * m.cell_size_m(), m.origin_y_m(),
                                           m.origin_y_m() + m.height() * m.cell_size_m()));
    }
    world.maze.set_start(Cell{static_cast<int>(column), static_cast<int>(row)}, o.start_heading);
  }
  if (o.goals) {
    for (const Cell g : *o.goals) require_inside(world.maze, g, "--goal");
    world.maze.clear_goals();
    for (const Cell g : *o.goals) world.maze.add_goal(g);
  }
  if (o.centre_goals) {
    world.maze.clear_goals();
    const int w = world.maze.width();
    const int h = world.maze.height();
    for (int y = (h - 1) / 2; y <= h / 2; ++y) {
      for (int x = (w - 1) / 2; x <= w / 2; ++x) world.maze.add_goal({x, y});
    }
  }
}

bool default_physical(const Maze &m) {
  return m.cell_size_m() == kDefaultCellSize_m && m.wall_thickness_m() == kDefaultWallThickness_m &&
         m.origin_x_m() == 0.0 && m.origin_y_m() == 0.0;
}

std::string physical_of(const Maze &m) {
  return fmt::format("the size (cells of {} m, walls {} m thick, origin ({}, {}))", m.cell_size_m(),
                     m.wall_thickness_m(), m.origin_x_m(), m.origin_y_m());
}

std::string goals_of(const Maze &m) {
  constexpr std::size_t kShown = 4;
  std::string text = m.goals().size() == 1 ? "the goal " : "the goals ";
  for (std::size_t i = 0; i < std::min(kShown, m.goals().size()); ++i) {
    text += fmt::format("{}({},{})", i == 0 ? "" : ", ", m.goals()[i].x, m.goals()[i].y);
  }
  if (m.goals().size() > kShown) text += fmt::format(" and {} more", m.goals().size() - kShown);
  return text;
}

std::string joined(const std::vector<std::string> &parts) {
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    text += i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ";
    text += parts[i];
  }
  return text;
}

}  // namespace

std::size_t random_start_index(std::uint64_t seed, std::size_t count) {
  common::Rng rng(seed ^ 0x7374617274ULL);
  return static_cast<std::size_t>(rng.next_u64() % count);
}

Format detect_format(std::string_view text, const std::string &file) {
  if (text.empty()) throw common::InputError(common::SourceLocation{file, 0, 0}, "the file is empty; expected a maze");
  if (looks_like_maz(text)) return Format::maz;
  std::string_view body = text;
  if (body.starts_with("\xEF\xBB\xBF")) body.remove_prefix(3);
  if (!body.empty() && (body[0] == 'o' || body[0] == '+')) return Format::text_map;
  if (looks_like_room(body)) return Format::room;
  const std::size_t first = body.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos) {
    if (body[first] == '<') return Format::xml;
    if (body[first] >= '0' && body[first] <= '9') return Format::num;
  }
  if (body.starts_with("#VRML_SIM")) {
    throw common::InputError(common::SourceLocation{file, 1, 1},
                             "a Webots .wbt world, which maze_mapper writes but does not read: use the text map, "
                             "num or XML world it was made from");
  }
  throw common::InputError(common::SourceLocation{file, 1, 1},
                           "cannot tell the format: expected a text map (first line 'o---o...'), num lines "
                           "'X Y N E S W', XML '<world>', a room file ('boundary XS XE YS YE', 'rect ...') or a 256-byte "
                           "binary .maz");
}

Maze read_world(std::string_view text, const std::string &file) {
  return read_world(text, file, detect_format(text, file));
}

Maze read_world(std::string_view text, const std::string &file, Format format) {
  switch (format) {
    case Format::text_map: return read_text_map(text, file);
    case Format::num: return read_num(text, file);
    case Format::xml: return read_xml(text, file);
    case Format::maz: return read_maz(text, file);
    case Format::room:
      throw common::InputError(common::SourceLocation{file, 0, 0},
                               "a room file holds an arena (obstacles in metres), not a grid maze");
    case Format::wbt: break;
  }
  throw common::InputError(common::SourceLocation{file, 0, 0}, "cannot read Webots worlds");
}

World load_world(const std::string &path) { return load_world(path, WorldOverrides{}); }

namespace {

// The location of byte `offset` of `text`, line and column from 1.
common::SourceLocation location_of(std::string_view text, std::size_t offset, const std::string &file) {
  const std::string_view before = text.substr(0, offset);
  const auto line = static_cast<int>(std::count(before.begin(), before.end(), '\n')) + 1;
  const std::size_t line_start = before.rfind('\n');
  const std::size_t column = line_start == std::string_view::npos ? offset + 1 : offset - line_start;
  return common::SourceLocation{file, line, static_cast<int>(column)};
}

}  // namespace

std::string read_world_text(const std::string &path) { return read_world_file(path).text; }

WorldText read_world_file(const std::string &path) {
  common::InputFile file(path);  // a FIFO's wait for its writer ends on a stop signal
  std::string text;
  struct stat status {};
  if (::fstat(file.fd(), &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0) {
    text.reserve(std::min(static_cast<std::size_t>(status.st_size), kMaxFileBytes) + 1);  // no doubling
  }
  std::optional<Format> format;
  char buffer[1 << 16];
  for (;;) {
    const std::size_t n = file.read(buffer, sizeof buffer);
    const std::size_t start = text.size();
    text.append(buffer, n);
    if (!format && (n == 0 || text.find_first_not_of(" \t\r\n\xEF\xBB\xBF") != std::string::npos)) {
      format = detect_format(text, path);  // throws when the first bytes are no format at all
    }
    if (format == Format::maz) {
      if (n == 0 || text.size() > kMazBytes) return {std::move(text), *format};  // read_maz says what is wrong with the size
      continue;
    }
    if (const std::size_t nul = text.find('\0', start); nul != std::string::npos) {
      throw common::InputError(location_of(text, nul, path), "a NUL byte: a maze file is text");
    }
    if (n == 0) return {std::move(text), format ? *format : detect_format(text, path)};
    if (text.size() > kMaxFileBytes) throw cannot("read", path, EFBIG);
  }
}

World load_world(const std::string &path, const WorldOverrides &overrides) {
  const WorldText file = read_world_file(path);
  return load_world_text(file.text, path, overrides, file.format);
}

World load_world_text(const std::string &text, const std::string &path, const WorldOverrides &overrides) {
  return load_world_text(text, path, overrides, detect_format(text, path));
}

World load_world_text(const std::string &text, const std::string &path, const WorldOverrides &overrides,
                      Format format) {
  std::vector<std::string> warnings;
  const auto read = [&]() -> Maze {
    if (format != Format::xml) return read_world(text, path, format);
    XmlRead xml = read_xml(text, path, XmlReadOptions{overrides.cell_size_m});
    warnings = std::move(xml.warnings);
    return std::move(xml.maze);
  };
  World world{read(), path, std::move(warnings), format};
  apply(world, overrides);
  if (const auto summary = unreachable_summary(world.maze)) {
    world.warnings.push_back(fmt::format("{}: warning: {}", path, *summary));
  }
  return world;
}

Format format_for_output(const std::string &path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char &c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".txt") return Format::text_map;
  if (ext == ".num") return Format::num;
  if (ext == ".xml") return Format::xml;
  if (ext == ".wbt") return Format::wbt;
  if (ext == ".maz") return Format::maz;
  if (ext == ".room") return Format::room;
  throw common::InputError(fmt::format(
      "cannot tell the output format of '{}' from its extension: use .txt, .num, .xml, .wbt, .maz or .room", path));
}

std::optional<std::string> dropped_by(const Maze &maze, Format format) {
  std::vector<std::string> parts;
  const char *holds = "";
  if (format == Format::num || format == Format::maz) {
    holds = format == Format::num ? "a num file holds only the walls" : "a .maz file holds only the walls";
    if (maze.start() != Cell{0, 0} || maze.start_heading() != Side::north) {
      parts.push_back(fmt::format("the start ({},{}) facing {}", maze.start().x, maze.start().y,
                                  to_string(maze.start_heading())));
    }
    // A .maz maze's goal is the classic centre 2 x 2, which it keeps.
    std::vector<Cell> centre;
    for (const int x : {maze.width() / 2 - 1, maze.width() / 2}) {
      for (const int y : {maze.height() / 2 - 1, maze.height() / 2}) centre.push_back({x, y});
    }
    std::vector<Cell> goals = maze.goals();
    std::sort(goals.begin(), goals.end());
    const bool kept = format == Format::maz && goals == centre;
    if (!maze.goals().empty() && !kept) parts.push_back(goals_of(maze));
  } else if (format == Format::room) {
    holds = "a room file holds the walls as rectangles, the start and the goals";
  } else if (format == Format::text_map) {
    holds = "a text map holds walls, start cell and goals; its start faces north";
    if (maze.start_heading() != Side::north) {
      parts.push_back(fmt::format("the start's heading ({})", to_string(maze.start_heading())));
    }
  } else {
    return std::nullopt;
  }
  if (!default_physical(maze) && format != Format::room) parts.push_back(physical_of(maze));
  if (const std::size_t n = maze.start_positions().size(); n > 1) {
    parts.push_back(fmt::format("the other {} start position{}", n - 1, n == 2 ? "" : "s"));
  }
  if (const std::size_t n = maze.landmarks().size(); n > 0) {
    parts.push_back(fmt::format("{} landmark{}", n, n == 1 ? "" : "s"));
  }
  if (parts.empty()) return std::nullopt;
  return fmt::format("dropped {}: {}", joined(parts), holds);
}

std::string format_world(const Maze &maze, Format format, std::string_view title) {
  switch (format) {
    case Format::text_map: return write_text_map(maze);
    case Format::num: return write_num(maze);
    case Format::xml: return write_xml(maze);
    case Format::wbt: return write_wbt(maze, title);
    case Format::maz: return write_maz(maze);
    case Format::room: return write_room(arena_from_maze(maze));
  }
  return {};
}

void save_world(const Maze &maze, const std::string &path) {
  const Format format = format_for_output(path);
  write_file_atomically(path, format_world(maze, format, std::filesystem::path(path).stem().string()));
}

std::string read_file(const std::string &path) {
  common::InputFile file(path);
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const std::size_t n = file.read(buffer, sizeof buffer);
    if (n == 0) return text;
    text.append(buffer, n);
    if (text.size() > kMaxFileBytes) throw cannot("read", path, EFBIG);
  }
}

void write_file_atomically(const std::string &path, std::string_view content) {
  common::write_file_atomically(path, content);
}

}  // namespace maze
