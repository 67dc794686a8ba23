#pragma once
// Reading an input file whose reading may wait: a FIFO without a writer yet, a writer that
// pauses. Every wait is a poll(2) in 50 ms slices that gives up when a stop signal is
// recorded (common/interrupt.hpp), so SIGINT, SIGTERM and SIGHUP end it whatever the
// handler's SA_RESTART. A regular file reads as with plain read(2).
//
// The limits of every input the program reads are here, in one place: past one an input is
// refused at once, as the bytes that break it arrive ("not a KIND file: ..."), so that
// /dev/zero or an endless pipe never fills the memory.

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/interrupt.hpp"

namespace common {

inline constexpr std::size_t kMiB = std::size_t{1} << 20;

// A world file, any format: at most 1 GiB, and its first line that is not blank or a comment
// starts within its first 1 MiB (maze/world/format_detector.hpp).
inline constexpr std::size_t kMaxWorldBytes = 1024 * kMiB;
inline constexpr std::size_t kFormatLineWithinBytes = kMiB;

// What a text input may be: its size, the length of a line (its "\n" not counted), and
// whether a NUL byte (which no text the program reads holds) refuses it.
struct InputLimits {
  std::size_t max_bytes = kMaxWorldBytes;
  std::size_t max_line_bytes = std::numeric_limits<std::size_t>::max();
  bool text = true;
};
// A robot profile (JSON): 1 MiB.
inline constexpr InputLimits kRobotProfileLimits{kMiB};
// A CSV file read back (a part of batch merge, map-log's log): 256 MiB, a line at most 1 MiB.
inline constexpr InputLimits kCsvLimits{256 * kMiB, kMiB};

// "1 MiB", "2 GiB", "64 KiB" or "10 bytes".
// Appends `n` bytes to `text`, its memory growing at most to `max_bytes` (a string doubling
// its memory would take twice the limit).
inline void append_within(std::string &text, const char *data, std::size_t n, std::size_t max_bytes) {
  if (text.size() + n > text.capacity()) {
    text.reserve(std::max(text.size() + n, std::min(2 * text.capacity(), max_bytes)));
  }
  text.append(data, n);
}

inline std::string size_text(std::size_t bytes) {
  for (const auto &[unit, name] : {std::pair{1024 * kMiB, "GiB"}, std::pair{kMiB, "MiB"}, std::pair{std::size_t{1024}, "KiB"}}) {
    if (bytes >= unit && bytes % unit == 0) return fmt::format("{} {}", bytes / unit, name);
  }
  return fmt::format("{} bytes", bytes);
}

class InputFile {
 public:
  // Opens `path` for reading without waiting (O_NONBLOCK: a FIFO opens at once). Throws
  // InputError "cannot read PATH: REASON".
  explicit InputFile(const std::string &path)
      : path_(path), fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY)) {
    if (fd_ < 0) fail(errno);
  }
  ~InputFile() { ::close(fd_); }
  InputFile(const InputFile &) = delete;
  InputFile &operator=(const InputFile &) = delete;

  // Reads up to `size` bytes into `data`; 0 at the end (a FIFO: once its writer has come and
  // closed it). Throws InputError "cannot read PATH: REASON", and Interrupted "cannot read
  // PATH: interrupted by SIGTERM while waiting for its writer" when a stop signal comes first.
  std::size_t read(char *data, std::size_t size) {
    for (;;) {
      wait_readable();
      const ssize_t n = ::read(fd_, data, size);
      if (n >= 0) return static_cast<std::size_t>(n);
      if (errno != EINTR && errno != EAGAIN) fail(errno);
    }
  }
  int fd() const { return fd_; }

 private:
  // Until the file has something to say: data, its end, or an error. A FIFO no writer ever
  // opened is none of these (Linux reports no POLLHUP before a first writer).
  void wait_readable() {
    for (;;) {
      if (interrupted()) {
        throw Interrupted(
            fmt::format("cannot read {}: interrupted by {} while waiting for its writer", path_, interrupt_name()));
      }
      pollfd p{fd_, POLLIN, 0};
      const int ready = ::poll(&p, 1, 50);
      if (ready > 0) return;
      if (ready < 0 && errno != EINTR) fail(errno);
    }
  }
  [[noreturn]] void fail(int error_number) const {
    throw InputError(fmt::format("cannot read {}: {}", path_, std::strerror(error_number)));
  }

  std::string path_;
  int fd_;
};

// The whole of `path` within `limits`, read in 64 KiB pieces: "FILE: error: not a KIND file:
// more than 1 GiB", "FILE:LINE: error: not a KIND file: line LINE is longer than 1 MiB" and
// "FILE:LINE:COL: error: not a KIND file: a NUL byte" are thrown (InputError) as soon as the
// bytes read show it, so /dev/zero fails after its first piece; and what InputFile throws.
// `first_line`, when given, is called with the first line (without its "\n") as soon as it
// has come, to refuse a file that is not of its kind before the rest is read.
inline std::string read_text(const std::string &path, std::string_view kind, const InputLimits &limits,
                             const std::function<void(std::string_view)> &first_line = {}) {
  InputFile file(path);
  std::string text;
  struct stat status {};
  if (::fstat(file.fd(), &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0) {
    text.reserve(std::min(static_cast<std::size_t>(status.st_size), limits.max_bytes) + 1);  // no doubling
  }
  const auto refuse = [&](int line, int column, const std::string &why) {
    return InputError(SourceLocation{path, line, column}, fmt::format("not a {} file: {}", kind, why));
  };
  const auto too_long = [&](int line) {
    return refuse(line, 0, fmt::format("line {} is longer than {}", line, size_text(limits.max_line_bytes)));
  };
  int line = 1;
  std::size_t line_start = 0;
  char buffer[1 << 16];
  for (;;) {
    const std::size_t n = file.read(buffer, sizeof buffer);
    if (n == 0) {
      if (line == 1 && first_line) first_line(text);
      return text;
    }
    if (n > limits.max_bytes - text.size()) throw refuse(0, 0, "more than " + size_text(limits.max_bytes));
    const std::size_t start = text.size();
    append_within(text, buffer, n, limits.max_bytes);
    for (std::size_t i = start; i < text.size(); ++i) {
      if (text[i] == '\n') {
        if (i - line_start > limits.max_line_bytes) throw too_long(line);
        if (line == 1 && first_line) first_line(std::string_view(text).substr(0, i));
        ++line;
        line_start = i + 1;
      } else if (text[i] == '\0' && limits.text) {
        throw refuse(line, static_cast<int>(i - line_start) + 1, "a NUL byte");
      }
    }
    if (text.size() - line_start > limits.max_line_bytes) throw too_long(line);
  }
}

}  // namespace common
