#pragma once
// The three standard streams as a command needs them, secured once at the start of main:
//
//   - a stream the caller closed (`maze_mapper run W --out d >&-`) is opened on /dev/null, so
//     no file the program opens later takes its number: a temporary that became fd 1 would
//     receive the printed maps;
//   - std::cout and std::cerr write through common::StdoutBuffer (a full pipe, a stopped
//     terminal or a reader that never reads still end on a stop signal);
//   - a message for standard error goes through print_stderr(), which never throws and never
//     aborts: a message that cannot be shown (stderr closed, /dev/full, a closed pipe) is
//     dropped, and the command ends with the status its work earned.

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <iostream>
#include <streambuf>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "common/stdout_buffer.hpp"

namespace common {

// Opens /dev/null on each of the file descriptors 0, 1 and 2 that is not open (read for 0,
// write for 1 and 2). Call first in main, before any file is opened.
inline void secure_standard_streams() {
  for (const int fd : {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO}) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int opened = ::open("/dev/null", fd == STDIN_FILENO ? O_RDONLY : O_WRONLY);
    if (opened >= 0 && opened != fd) {  // a lower descriptor was closed too and took it
      ::dup2(opened, fd);
      ::close(opened);
    }
  }
}

// Writes `text` to standard error whole, waiting as StdoutBuffer waits (a stop signal ends a
// wait a reader holds); a failed write is ignored.
inline void write_stderr_text(std::string_view text) {
  static const bool may_block = detail::may_block(STDERR_FILENO);
  const int saved_errno = errno;
  (void)write_all_interruptible(STDERR_FILENO, text.data(), text.size(), may_block);
  errno = saved_errno;
}

// fmt::print(stderr, …) that never throws: the text formatted, then write_stderr_text().
template <typename... Args>
void print_stderr(fmt::format_string<Args...> format, Args &&...args) {
  std::string text;
  try {
    text = fmt::format(format, std::forward<Args>(args)...);
  } catch (...) {  // out of memory: the message is dropped, as one that cannot be written
    return;
  }
  write_stderr_text(text);
}

// An input stream buffer over a file descriptor (standard input for --step's prompt) whose
// wait for input notices a stop signal: it waits in poll(2) slices of kWaitSlice_ms and ends
// its input (end of file) once a signal is recorded, as at the input's real end.
class InterruptibleInputBuffer final : public std::streambuf {
 public:
  explicit InterruptibleInputBuffer(int fd) : fd_(fd) { setg(buffer_, buffer_, buffer_); }

 protected:
  int_type underflow() override {
    for (;;) {
      if (interrupted()) return traits_type::eof();
      pollfd p{fd_, POLLIN, 0};
      const int ready = ::poll(&p, 1, kWaitSlice_ms);
      if (ready < 0 && errno != EINTR) return traits_type::eof();
      if (ready <= 0) continue;
      const ssize_t n = ::read(fd_, buffer_, sizeof buffer_);
      if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      if (n <= 0) return traits_type::eof();
      setg(buffer_, buffer_, buffer_ + n);
      return traits_type::to_int_type(buffer_[0]);
    }
  }

 private:
  int fd_;
  char buffer_[4096];
};

// While alive, std::cout and std::cerr write through StdoutBuffers over file descriptors 1
// and 2 (std::cerr still flushed after every output, unitbuf); at the end both are flushed and
// given back their own buffers. One, in main, after secure_standard_streams().
class StandardStreamsThroughBuffers {
 public:
  StandardStreamsThroughBuffers()
      : out_(STDOUT_FILENO), err_(STDERR_FILENO), previous_out_(std::cout.rdbuf(&out_)),
        previous_err_(std::cerr.rdbuf(&err_)) {}
  ~StandardStreamsThroughBuffers() {
    std::cout.flush();
    std::cerr.flush();
    std::cout.rdbuf(previous_out_);
    std::cerr.rdbuf(previous_err_);
  }
  StandardStreamsThroughBuffers(const StandardStreamsThroughBuffers &) = delete;
  StandardStreamsThroughBuffers &operator=(const StandardStreamsThroughBuffers &) = delete;

 private:
  StdoutBuffer out_;
  StdoutBuffer err_;
  std::streambuf *previous_out_;
  std::streambuf *previous_err_;
};

}  // namespace common
