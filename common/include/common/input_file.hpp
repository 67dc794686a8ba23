#pragma once
// Reading an input file whose reading may wait: a FIFO without a writer yet, a writer that
// pauses. Every wait is a poll(2) in 50 ms slices that gives up when a stop signal is
// recorded (common/interrupt.hpp), so SIGINT, SIGTERM and SIGHUP end it whatever the
// handler's SA_RESTART. A regular file reads as with plain read(2).

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/interrupt.hpp"

namespace common {

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

}  // namespace common
