// Standard output through common::StdoutBuffer: every byte in order, and a write that a full
// pipe holds ends the process once a stop signal is recorded (in a child process: it exits).

#include <doctest/doctest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <ostream>
#include <string>
#include <thread>

#include "common/interrupt.hpp"
#include "common/stdout_buffer.hpp"

namespace {

// Fills the pipe whose write end is `fd` until it takes no more.
void fill_pipe_full(int fd) {
  const int flags = ::fcntl(fd, F_GETFL);
  ::fcntl(fd, F_SETFL, flags | O_NONBLOCK);
  const std::string block(4096, 'x');
  while (::write(fd, block.data(), block.size()) > 0) {
  }
  ::fcntl(fd, F_SETFL, flags);
}

// Reads `fd` to its end.
std::string read_to_end(int fd) {
  std::string text;
  char chunk[4096];
  for (;;) {
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n > 0) {
      text.append(chunk, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      return text;
    }
  }
}

}  // namespace

TEST_CASE("stdout buffer: a pipe gets every byte in order, small and large writes alike") {
  int ends[2];
  REQUIRE(::pipe(ends) == 0);
  std::string expected;
  std::thread writer([&ends, &expected] {
    {
      common::StdoutBuffer buffer(ends[1]);
      std::ostream out(&buffer);
      for (int i = 0; i < 20000; ++i) {
        const std::string line = std::to_string(i) + '\n';
        out << line;
        expected += line;
      }
      const std::string big(300000, 'b');  // more than the buffer: written past it
      out << big << std::flush;
      expected += big;
      CHECK(out.good());
    }
    ::close(ends[1]);
  });
  const std::string got = read_to_end(ends[0]);
  writer.join();
  ::close(ends[0]);
  CHECK(got.size() == expected.size());
  CHECK(got == expected);
}

TEST_CASE("stdout buffer: a full pipe never read ends the process 2 s after a stop signal, 128 + the signal") {
  int ends[2];
  REQUIRE(::pipe(ends) == 0);
  int errors[2];
  REQUIRE(::pipe(errors) == 0);
  fill_pipe_full(ends[1]);
  const auto started = std::chrono::steady_clock::now();
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::dup2(errors[1], STDERR_FILENO);
    common::simulate_interrupt_for_tests(SIGTERM);
    common::write_all_interruptible(ends[1], "held\n", 5, true);
    ::_exit(0);  // not reached: the wait ends the process
  }
  ::close(errors[1]);
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  const double waited_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const std::string said = read_to_end(errors[0]);
  ::close(errors[0]);
  ::close(ends[0]);
  ::close(ends[1]);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 143);
  CHECK(said == "\nerror: interrupted by SIGTERM\n");
  CHECK(waited_s >= common::kStoppedOutputGrace_ms / 1000.0);
}

TEST_CASE("stdout buffer: without a stop signal, a full pipe's write waits for its reader and goes on") {
  int ends[2];
  REQUIRE(::pipe(ends) == 0);
  fill_pipe_full(ends[1]);
  bool written = false;
  std::thread writer([&ends, &written] { written = common::write_all_interruptible(ends[1], "after\n", 6, true); });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the writer waits meanwhile
  std::string got;
  char chunk[4096];
  while (got.find("after\n") == std::string::npos) {
    const ssize_t n = ::read(ends[0], chunk, sizeof chunk);
    REQUIRE(n > 0);
    got.append(chunk, static_cast<std::size_t>(n));
  }
  writer.join();
  ::close(ends[0]);
  ::close(ends[1]);
  CHECK(written);
  CHECK(got.ends_with("after\n"));
}
