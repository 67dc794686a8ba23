#include "maze/world/world_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cctype>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "common/angles.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/input_file.hpp"
#include "maze/formats/maz_format.hpp"
#include "maze/formats/num_format.hpp"
#include "maze/formats/solids_format.hpp"
#include "maze/formats/text_map.hpp"
#include "maze/formats/wbt_format.hpp"
#include "maze/formats/xml_solids.hpp"
#include "maze/formats/xml_format.hpp"
#include "maze/world/format_detector.hpp"

namespace maze {

namespace {

common::InputError cannot(std::string_view what, const std::string &path, int error) {
  return common::InputError(fmt::format("cannot {} {}: {}", what, path, std::strerror(error)));
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

// The location of byte `offset` of `text`, line and column from 1.
common::SourceLocation location_of(std::string_view text, std::size_t offset, const std::string &file) {
  const std::string_view before = text.substr(0, offset);
  const auto line = static_cast<int>(std::count(before.begin(), before.end(), '\n')) + 1;
  const std::size_t line_start = before.rfind('\n');
  const std::size_t column = line_start == std::string_view::npos ? offset + 1 : offset - line_start;
  return common::SourceLocation{file, line, static_cast<int>(column)};
}

// "text map", "num", "XML", "Webots .wbt", ".maz", "room".
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

}  // namespace


Format detect_format(std::string_view text, const std::string &file) {
  return *FormatDetector(file).look(text, true);  // at the end the bytes always tell, or it throws
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

std::string read_world_text(const std::string &path) { return read_world_file(path).text; }

WorldText read_world_file(const std::string &path) {
  common::InputFile file(path);  // a FIFO's wait for its writer ends on a stop signal
  std::string text;
  struct stat status {};
  if (::fstat(file.fd(), &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0) {
    text.reserve(std::min(static_cast<std::size_t>(status.st_size), common::kMaxWorldBytes) + 1);  // no doubling
  }
  FormatDetector detector(path);
  std::optional<Format> format;
  char buffer[1 << 16];
  for (;;) {
    const std::size_t n = file.read(buffer, sizeof buffer);
    if (n > common::kMaxWorldBytes - text.size()) throw cannot("read", path, EFBIG);
    const std::size_t start = text.size();
    common::append_within(text, buffer, n, common::kMaxWorldBytes);
    if (!format) format = detector.look(text, n == 0);  // throws when the first meaningful line is no format
    if (format == Format::maz) {
      if (n == 0 || text.size() > kMazBytes) return {std::move(text), *format};  // read_maz says what is wrong with the size
      continue;
    }
    if (const std::size_t nul = text.find('\0', start); nul != std::string::npos) {
      throw common::InputError(location_of(text, nul, path), "a NUL byte: a maze file is text");
    }
    if (n == 0) return {std::move(text), *format};
  }
}

Format read_world_format(const std::string &path) {
  common::InputFile file(path);
  FormatDetector detector(path);
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const std::size_t n = file.read(buffer, sizeof buffer);
    text.append(buffer, n);
    if (const std::optional<Format> format = detector.look(text, n == 0)) return *format;
  }
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

std::optional<std::string> dropped_by(const Arena &arena, Format format) {
  const auto landmarks = std::count_if(arena.discs.begin(), arena.discs.end(),
                                       [](const ArenaDisc &d) { return d.landmark.has_value(); });
  if (format != Format::room || landmarks == 0) return std::nullopt;
  return fmt::format("dropped {} landmark{}: a room file holds the walls as rectangles, the start and the goals",
                     landmarks, landmarks == 1 ? "" : "s");
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
  // Walls of a stated height stand on an open floor (the course's); the outer walls close it.
  a.boundary_walled = !std::isfinite(maze.wall_height_m());
  for (const WallSegment &w : maze.wall_segments()) {
    a.obstacles.push_back(
        Obstacle::from_segment(w.x1_m, w.y1_m, w.x2_m, w.y2_m, maze.wall_thickness_m(), WallEnds::capped));
    a.obstacles.back().height_m = maze.wall_height_m();
  }
  for (const Landmark &l : maze.landmarks()) {
    a.discs.push_back({l.x_m, l.y_m, kLandmarkRadius_m, ArenaDisc::Look{l.height_m, l.red, l.green, l.blue}});
  }
  const auto centre = [&](Cell c) { return ArenaPoint{a.x_min_m + (c.x + 0.5) * s, a.y_min_m + (c.y + 0.5) * s}; };
  const ArenaPoint start = centre(maze.start());
  a.starts.push_back({start.x_m, start.y_m, common::compass_yaw_rad(static_cast<int>(maze.start_heading()))});
  for (const Cell g : maze.goals()) a.goals.push_back(centre(g));
  return a;
}

std::string read_file(const std::string &path) {
  common::InputFile file(path);
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const std::size_t n = file.read(buffer, sizeof buffer);
    if (n == 0) return text;
    if (n > common::kMaxWorldBytes - text.size()) throw cannot("read", path, EFBIG);
    common::append_within(text, buffer, n, common::kMaxWorldBytes);
  }
}

void write_file_atomically(const std::string &path, std::string_view content) {
  common::write_file_atomically(path, content);
}

}  // namespace maze
