#include "maze/world.hpp"

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
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "maze/maz_format.hpp"
#include "maze/num_format.hpp"
#include "maze/text_map.hpp"
#include "maze/validate.hpp"
#include "maze/wbt_format.hpp"
#include "maze/xml_format.hpp"

namespace maze {

namespace {

constexpr std::size_t kMaxFileBytes = std::size_t{1} << 30;

// Closes a file descriptor when it goes out of scope.
struct FileDescriptor {
  int fd = -1;
  explicit FileDescriptor(int f) : fd(f) {}
  FileDescriptor(const FileDescriptor &) = delete;
  FileDescriptor &operator=(const FileDescriptor &) = delete;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

common::InputError cannot(std::string_view what, const std::string &path, int error) {
  return common::InputError(fmt::format("cannot {} {}: {}", what, path, std::strerror(error)));
}

bool write_all(int fd, std::string_view content) {
  while (!content.empty()) {
    const ssize_t n = ::write(fd, content.data(), content.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    content.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

mode_t file_mode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return static_cast<mode_t>(0666 & ~mask);
}


void require_inside(const Maze &maze, Cell c, std::string_view option) {
  if (!maze.contains(c)) {
    throw common::InputError(
        fmt::format("{} {},{} is outside the {}x{} maze", option, c.x, c.y, maze.width(), maze.height()));
  }
}

void apply_cell_size(World &world, double cell_size_m) {
  Maze &m = world.maze;
  if (world.format != Format::xml) {
    m.set_physical(cell_size_m, kDefaultWallThickness_m, 0.0, 0.0);
    return;
  }
  if (std::abs(cell_size_m - m.cell_size_m()) > 1e-9 * m.cell_size_m()) {
    throw common::InputError(fmt::format("--cell-size {} m disagrees with the {} m cells of {}; an XML world has "
                                         "its own size: leave --cell-size out",
                                         cell_size_m, m.cell_size_m(), world.file));
  }
}

void apply(World &world, const WorldOverrides &o) {
  if (o.cell_size_m) apply_cell_size(world, *o.cell_size_m);
  if (o.start) {
    require_inside(world.maze, *o.start, "--start");
    world.maze.set_start(*o.start, o.start_heading);
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

Format detect_format(std::string_view text, const std::string &file) {
  if (text.empty()) throw common::InputError(common::SourceLocation{file, 0, 0}, "the file is empty; expected a maze");
  if (looks_like_maz(text)) return Format::maz;
  std::string_view body = text;
  if (body.starts_with("\xEF\xBB\xBF")) body.remove_prefix(3);
  if (!body.empty() && (body[0] == 'o' || body[0] == '+')) return Format::text_map;
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
                           "'X Y N E S W', XML '<world>' or a 256-byte binary .maz");
}

Maze read_world(std::string_view text, const std::string &file) {
  switch (detect_format(text, file)) {
    case Format::text_map: return read_text_map(text, file);
    case Format::num: return read_num(text, file);
    case Format::xml: return read_xml(text, file);
    case Format::maz: return read_maz(text, file);
    case Format::wbt: break;
  }
  throw common::InputError(common::SourceLocation{file, 0, 0}, "cannot read Webots worlds");
}

World load_world(const std::string &path) { return load_world(path, WorldOverrides{}); }

World load_world(const std::string &path, const WorldOverrides &overrides) {
  const std::string text = read_file(path);
  const Format format = detect_format(text, path);
  World world{read_world(text, path), path, {}, format};
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
  throw common::InputError(
      fmt::format("cannot tell the output format of '{}' from its extension: use .txt, .num, .xml, .wbt or .maz", path));
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
  } else if (format == Format::text_map) {
    holds = "a text map holds walls, start cell and goals; its start faces north";
    if (maze.start_heading() != Side::north) {
      parts.push_back(fmt::format("the start's heading ({})", to_string(maze.start_heading())));
    }
  } else {
    return std::nullopt;
  }
  if (!default_physical(maze)) parts.push_back(physical_of(maze));
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
  }
  return {};
}

void save_world(const Maze &maze, const std::string &path) {
  const Format format = format_for_output(path);
  write_file_atomically(path, format_world(maze, format, std::filesystem::path(path).stem().string()));
}

std::string read_file(const std::string &path) {
  const FileDescriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (file.fd < 0) throw cannot("read", path, errno);
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw cannot("read", path, errno);
    if (n == 0) return text;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > kMaxFileBytes) throw cannot("read", path, EFBIG);
  }
}

void write_file_atomically(const std::string &path, std::string_view content) {
  const std::filesystem::path target(path);
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::string temp = (dir / fmt::format(".{}.tmp.XXXXXX", target.filename().string())).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) throw cannot("write", path, errno);
  int error = 0;
  {
    const FileDescriptor file(fd);
    if (::fchmod(fd, file_mode()) != 0 || !write_all(fd, content) || ::fsync(fd) != 0) error = errno;
  }
  if (error == 0 && ::rename(temp.c_str(), path.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temp.c_str());
    throw cannot("write", path, error);
  }
}

}  // namespace maze
