#pragma once
// Writing an output file so that a reader never sees half of it, and so that what the user
// pointed at is respected:
//
//   a regular file, or a new one   the content goes to a temporary ".NAME.tmp.PID" in the
//                                  same directory, renamed over the target when complete
//                                  (rename is atomic within one file system);
//   a symbolic link                followed (to its final target, links of links too): the
//                                  target is written as above, the link stays a link;
//   a device, FIFO or socket       written directly, never replaced or removed (/dev/null
//                                  stays a device; a FIFO's reader gets the content);
//   a directory                    refused (EISDIR).
//
// On any failure the temporary is removed and the target is unchanged; a signal that ends
// the process removes it too (common/interrupt.hpp).

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/interrupt.hpp"

namespace common {

// The exit status of a write that failed because the disk (or the quota) is full: its own
// number, so that a script tells "no space" from bad input (2) or a failed run (1).
inline constexpr int kExitNoSpace = 4;

// A write that failed for lack of space (ENOSPC, EDQUOT): "cannot write PATH: No space left
// on device". Its exit status is kExitNoSpace.
class NoSpaceError : public RuntimeFailure {
 public:
  using RuntimeFailure::RuntimeFailure;
};

namespace detail {

[[noreturn]] inline void fail_write(const std::string &path, int error_number) {
  const std::string message = fmt::format("cannot write {}: {}", path, std::strerror(error_number));
  if (error_number == ENOSPC || error_number == EDQUOT) throw NoSpaceError(message);
  throw InputError(message);
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

// Opens a device, FIFO or socket for writing. A FIFO waits for its reader, and gives up
// (EINTR) when a stop signal is recorded meanwhile (common/interrupt.hpp): polled every
// 50 ms with O_NONBLOCK, which fails with ENXIO while no reader is there.
inline int open_special(const std::string &path) {
  for (;;) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
    if (fd >= 0) {
      const int flags = ::fcntl(fd, F_GETFL);
      if (flags < 0 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) {
        const int fcntl_errno = errno;
        ::close(fd);
        errno = fcntl_errno;
        return -1;
      }
      return fd;
    }
    const int open_errno = errno;
    struct stat st {};
    if (open_errno != ENXIO || ::stat(path.c_str(), &st) != 0 || !S_ISFIFO(st.st_mode)) {
      errno = open_errno;  // ENXIO: a socket, or a device without its driver
      return -1;
    }
    if (interrupted()) {
      errno = EINTR;
      return -1;
    }
    ::usleep(50'000);
  }
}

}  // namespace detail

// Where a write to `path` lands: `path` with its symbolic links followed (a dangling link
// names the file to create), and how it is written.
struct WriteTarget {
  enum class Kind { replace, direct };
  std::string path;  // the final target
  Kind kind = Kind::replace;
};

// Throws InputError "cannot write PATH: REASON" for a directory or a loop of links.
inline WriteTarget resolve_write_target(const std::string &path) {
  std::filesystem::path at(path);
  for (int hops = 0;; ++hops) {
    struct stat st {};
    if (::lstat(at.c_str(), &st) != 0) {
      if (errno == ENOENT) return {at.string(), WriteTarget::Kind::replace};
      detail::fail_write(path, errno);
    }
    if (S_ISLNK(st.st_mode)) {
      if (hops >= 40) detail::fail_write(path, ELOOP);
      std::vector<char> buffer(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : PATH_MAX) + 1);
      const ssize_t n = ::readlink(at.c_str(), buffer.data(), buffer.size());
      if (n < 0) detail::fail_write(path, errno);
      const std::filesystem::path link(std::string(buffer.data(), static_cast<std::size_t>(n)));
      at = link.is_absolute() ? link : at.parent_path() / link;
      continue;
    }
    if (S_ISDIR(st.st_mode)) detail::fail_write(path, EISDIR);
    return {at.string(), S_ISREG(st.st_mode) ? WriteTarget::Kind::replace : WriteTarget::Kind::direct};
  }
}

// One output written in pieces (a trace as the run goes) or at once. Until commit() the
// target is untouched (a regular file) and the content lies in the temporary; destroying an
// OutputFile that was not committed removes the temporary. A special file (device, FIFO) is
// written as the pieces come. Errors throw as write_file_atomically's do.
class OutputFile {
 public:
  explicit OutputFile(const std::string &path) : path_(path), target_(resolve_write_target(path)) {
    if (target_.kind == WriteTarget::Kind::direct) {
      fd_ = detail::open_special(target_.path);
      if (fd_ < 0 && errno == EINTR && interrupted()) {
        throw Interrupted(fmt::format("cannot write {}: interrupted by {} while waiting for a reader", path_,
                                      interrupt_name()));
      }
      if (fd_ < 0) detail::fail_write(path_, errno);
      return;
    }
    // Known to the signal handler before it exists: a signal in between finds it registered.
    const std::string temporary = detail::temporary_path_for(target_.path);
    slot_ = register_temporary(temporary);
    fd_ = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0) {
      const int open_errno = errno;
      unregister_temporary(slot_);  // not ours (EEXIST) or not made: never to be removed
      slot_ = -1;
      detail::fail_write(path_, open_errno);
    }
    temporary_ = temporary;
  }
  ~OutputFile() { discard(); }
  OutputFile(const OutputFile &) = delete;
  OutputFile &operator=(const OutputFile &) = delete;

  // Appends `content` (buffered; written out by 1 MiB).
  void write(std::string_view content) {
    buffer_.append(content);
    if (buffer_.size() >= kBufferBytes) flush();
  }
  // Writes out what is buffered, closes the file and renames the temporary over the target.
  void commit() {
    flush();
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) {
      const int close_errno = errno;
      discard();
      detail::fail_write(path_, close_errno);
    }
    if (!temporary_.empty() && std::rename(temporary_.c_str(), target_.path.c_str()) != 0) {
      const int rename_errno = errno;
      discard();
      detail::fail_write(path_, rename_errno);
    }
    unregister_temporary(slot_);
    slot_ = -1;
    temporary_.clear();
  }
  const std::string &path() const { return path_; }

 private:
  static constexpr std::size_t kBufferBytes = std::size_t{1} << 20;

  void flush() {
    if (detail::write_all(fd_, buffer_)) {
      buffer_.clear();
      return;
    }
    const int write_errno = errno;
    discard();
    detail::fail_write(path_, write_errno);
  }
  void discard() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!temporary_.empty()) ::unlink(temporary_.c_str());
    temporary_.clear();
    unregister_temporary(slot_);
    slot_ = -1;
    buffer_.clear();
  }

  std::string path_;
  WriteTarget target_;
  std::string temporary_;  // empty for a special file, and once committed
  int fd_ = -1;
  int slot_ = -1;
  std::string buffer_;
};

// Writes `content` to `path` as the header says. Throws InputError "cannot write PATH:
// REASON" (the system's reason, e.g. "No such file or directory"), NoSpaceError when the
// disk is full; then no file is created and an existing regular file at `path` is unchanged.
inline void write_file_atomically(const std::string &path, std::string_view content) {
  OutputFile file(path);
  file.write(content);
  file.commit();
}

// Throws what write_file_atomically(path, ...) would for a path it cannot write (a folder
// missing or not writable, the path a directory), before the work that makes the content:
// creates and removes the temporary file beside the target; the target is not touched (a
// special file is only checked for write permission, not opened: a FIFO would wait).
inline void check_writable(const std::string &path) {
  const WriteTarget target = resolve_write_target(path);
  if (target.kind == WriteTarget::Kind::direct) {
    if (::access(target.path.c_str(), W_OK) != 0) detail::fail_write(path, errno);
    return;
  }
  const std::string temporary = detail::temporary_path_for(target.path);
  const int slot = register_temporary(temporary);  // before it exists, as OutputFile does
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  const int open_errno = errno;
  if (fd >= 0) {
    ::close(fd);
    ::unlink(temporary.c_str());
  }
  unregister_temporary(slot);
  if (fd < 0) detail::fail_write(path, open_errno);
}

// Whether `a` and `b` are one file (device and inode, links followed); false when either
// does not exist.
inline bool same_file(const std::string &a, const std::string &b) {
  struct stat sa {};
  struct stat sb {};
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

// Throws InputError "OPTION OUTPUT is also an input (INPUT): refusing to overwrite it" when
// `output` is the same file as one of `inputs` (device and inode, links followed). A
// character device (/dev/null as both) is no one's content and is let through.
inline void refuse_output_over_input(const std::string &option, const std::string &output,
                                     const std::vector<std::string> &inputs) {
  struct stat st {};
  if (::stat(output.c_str(), &st) != 0 || S_ISCHR(st.st_mode)) return;
  for (const std::string &input : inputs) {
    if (!same_file(output, input)) continue;
    const std::string where = input == output ? std::string() : fmt::format(" ({})", input);
    throw InputError(fmt::format("{}{}{} is also an input{}: refusing to overwrite it", option,
                                 option.empty() ? "" : " ", output, where));
  }
}

}  // namespace common
