#pragma once
// Standard output that a stop signal always ends. Writing to a pipe whose reader reads
// nothing (`maze_mapper run ... | (sleep 100)`) blocks once the pipe is full; a signal that
// only records itself (common::SignalsStopWork) would leave that write blocked for ever, as
// the handler restarts it (SA_RESTART). Here every write to a pipe, socket or terminal first
// waits in poll(2) slices of kWaitSlice_ms, so a wait notices a recorded signal, and then
// writes at most PIPE_BUF bytes, which a pipe that polls writable takes without blocking:
//
//   - no signal recorded: the wait lasts as long as the reader takes (as a plain write);
//   - a signal recorded: the reader has kStoppedOutputGrace_ms from the last progress to
//     take more (a reader that drains the pipe as it goes still gets the whole summary);
//     after it, the process ends as the handler ends it (unfinished temporaries removed,
//     finished files kept, one `error: interrupted by SIGTERM` line, exit 128 + the signal).
//
// A regular file is written with plain write(2) calls.

#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstddef>
#include <cstring>
#include <streambuf>
#include <vector>

#include "common/interrupt.hpp"

namespace common {

inline constexpr int kWaitSlice_ms = 50;
inline constexpr int kStoppedOutputGrace_ms = 2000;

namespace detail {

// Whether writes to `fd` may wait on a reader (a pipe, socket or terminal).
inline bool may_block(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) return false;
  return S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode) || S_ISCHR(st.st_mode);
}

// Waits until `fd` takes a write (or reports an error, which the write then returns). With a
// stop signal recorded, ends the process after kStoppedOutputGrace_ms without progress.
inline void wait_writable(int fd) {
  using Clock = std::chrono::steady_clock;
  const auto started = Clock::now();
  for (;;) {
    pollfd p{fd, POLLOUT, 0};
    const int ready = ::poll(&p, 1, kWaitSlice_ms);
    if (ready > 0 || (ready < 0 && errno != EINTR)) return;
    if (interrupted() && Clock::now() - started >= std::chrono::milliseconds(kStoppedOutputGrace_ms)) {
      end_process_for_recorded_signal();
    }
  }
}

}  // namespace detail

// Writes all of data[0, size) to `fd`; `may_block`: detail::may_block(fd). False (errno
// set) when a write fails (ENOSPC, EPIPE with SIGPIPE ignored, ...).
inline bool write_all_interruptible(int fd, const char *data, std::size_t size, bool may_block) {
  while (size > 0) {
    if (may_block) detail::wait_writable(fd);
    const std::size_t chunk = may_block ? std::min<std::size_t>(size, PIPE_BUF) : size;
    const ssize_t written = ::write(fd, data, chunk);
    if (written < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      return false;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

// A stream buffer over a file descriptor written with write_all_interruptible: 64 KiB
// buffered, flushed at each newline on a terminal (as stdio's line buffering). A failed
// write makes the stream bad (errno kept for the caller's message).
class StdoutBuffer final : public std::streambuf {
 public:
  explicit StdoutBuffer(int fd)
      : fd_(fd), may_block_(detail::may_block(fd)), line_buffered_(::isatty(fd) == 1), buffer_(kBufferBytes) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  ~StdoutBuffer() override { flush_buffer(); }
  StdoutBuffer(const StdoutBuffer &) = delete;
  StdoutBuffer &operator=(const StdoutBuffer &) = delete;

 protected:
  int_type overflow(int_type ch) override {
    if (!flush_buffer()) return traits_type::eof();
    if (traits_type::eq_int_type(ch, traits_type::eof())) return traits_type::not_eof(ch);
    const char c = traits_type::to_char_type(ch);
    return xsputn(&c, 1) == 1 ? ch : traits_type::eof();
  }

  std::streamsize xsputn(const char *data, std::streamsize count) override {
    const auto size = static_cast<std::size_t>(count);
    if (size > static_cast<std::size_t>(epptr() - pptr())) {
      if (!flush_buffer()) return 0;
      if (size >= buffer_.size()) return write_all_interruptible(fd_, data, size, may_block_) ? count : 0;
    }
    std::memcpy(pptr(), data, size);
    pbump(static_cast<int>(size));
    if (line_buffered_ && std::memchr(data, '\n', size) != nullptr && !flush_buffer()) return 0;
    return count;
  }

  int sync() override { return flush_buffer() ? 0 : -1; }

 private:
  static constexpr std::size_t kBufferBytes = 64 * 1024;

  bool flush_buffer() {
    const auto size = static_cast<std::size_t>(pptr() - pbase());
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return size == 0 || write_all_interruptible(fd_, buffer_.data(), size, may_block_);
  }

  int fd_;
  bool may_block_;
  bool line_buffered_;
  std::vector<char> buffer_;
};

}  // namespace common
