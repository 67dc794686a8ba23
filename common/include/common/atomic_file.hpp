#pragma once
// Writing an output file so that a reader never sees half of it: the content goes to a
// temporary file in the same directory, which is then renamed over the target (rename is
// atomic within one file system). On any failure the temporary file is removed and nothing
// is left behind.

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "common/error.hpp"

namespace common {

namespace detail {

[[noreturn]] inline void fail_write(const std::string &path, int error_number) {
  throw InputError(fmt::format("cannot write {}: {}", path, std::strerror(error_number)));
}

// ".NAME.tmp.PID" beside the target.
inline std::string temporary_path_for(const std::string &path) {
  const std::filesystem::path target(path);
  // fmt rather than operator+: g++ 12 -O3 warns falsely (-Wrestrict) on "." + string.
  const std::string name = fmt::format(".{}.tmp.{}", target.filename().string(), ::getpid());
  return (target.parent_path() / name).string();
}

inline bool write_all(int fd, std::string_view content) {
  while (!content.empty()) {
    const ssize_t written = ::write(fd, content.data(), content.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) return false;
    if (written == 0) {
      errno = EIO;
      return false;
    }
    content.remove_prefix(static_cast<std::size_t>(written));
  }
  return true;
}

}  // namespace detail

// Writes `content` to `path` atomically. Throws InputError "cannot write PATH: REASON" (the
// system's reason, e.g. "No such file or directory") when it cannot; then no file is created
// and an existing file at `path` is unchanged.
inline void write_file_atomically(const std::string &path, std::string_view content) {
  const std::string temporary = detail::temporary_path_for(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) detail::fail_write(path, errno);
  const bool written = detail::write_all(fd, content);
  const int write_errno = errno;
  const bool closed = ::close(fd) == 0;
  const int close_errno = errno;
  if (!written || !closed) {
    ::unlink(temporary.c_str());
    detail::fail_write(path, !written ? write_errno : close_errno);
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int rename_errno = errno;
    ::unlink(temporary.c_str());
    detail::fail_write(path, rename_errno);
  }
}

// Throws what write_file_atomically(path, ...) would for a path it cannot write (a folder
// missing or not writable, the path a directory), before the work that makes the content:
// creates and removes the temporary file beside the target; the target is not touched.
inline void check_writable(const std::string &path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) detail::fail_write(path, EISDIR);
  const std::string temporary = detail::temporary_path_for(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) detail::fail_write(path, errno);
  ::close(fd);
  ::unlink(temporary.c_str());
}

}  // namespace common
