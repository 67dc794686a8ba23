#include "maze/world.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "common/error.hpp"
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

}  // namespace

Format detect_format(std::string_view text, const std::string &file) {
  if (text.empty()) throw common::InputError(common::SourceLocation{file, 0, 0}, "the file is empty; expected a maze");
  std::string_view body = text;
  if (body.starts_with("\xEF\xBB\xBF")) body.remove_prefix(3);
  if (!body.empty() && (body[0] == 'o' || body[0] == '+')) return Format::text_map;
  const std::size_t first = body.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos) {
    if (body[first] == '<') return Format::xml;
    if (body[first] >= '0' && body[first] <= '9') return Format::num;
  }
  throw common::InputError(common::SourceLocation{file, 1, 1},
                           "cannot tell the format: expected a text map (first line 'o---o...'), num lines "
                           "'X Y N E S W' or XML '<world>'");
}

Maze read_world(std::string_view text, const std::string &file) {
  switch (detect_format(text, file)) {
    case Format::text_map: return read_text_map(text, file);
    case Format::num: return read_num(text, file);
    case Format::xml: return read_xml(text, file);
    case Format::wbt: break;
  }
  throw common::InputError(common::SourceLocation{file, 0, 0}, "cannot read Webots worlds");
}

World load_world(const std::string &path) {
  const std::string text = read_file(path);
  World world{read_world(text, path), path, {}};
  if (const auto summary = unreachable_summary(world.maze)) {
    world.warnings.push_back(fmt::format("{}: warning: {}", path, *summary));
  }
  return world;
}

Format format_for_output(const std::string &path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".txt") return Format::text_map;
  if (ext == ".num") return Format::num;
  if (ext == ".xml") return Format::xml;
  if (ext == ".wbt") return Format::wbt;
  throw common::InputError(
      fmt::format("cannot tell the output format of '{}' from its extension: use .txt, .num, .xml or .wbt", path));
}

std::string format_world(const Maze &maze, Format format, std::string_view title) {
  switch (format) {
    case Format::text_map: return write_text_map(maze);
    case Format::num: return write_num(maze);
    case Format::xml: return write_xml(maze);
    case Format::wbt: return write_wbt(maze, title);
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
