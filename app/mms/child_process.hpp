#pragma once
// A child process spoken to line by line: its standard input and output on pipes, its
// standard error the same as ours (what it logs shows where we print), in a process group
// of its own so that ending it ends what it started too. Linux only.
//
// What it starts in a session or group of its own (setsid) is ended with it too: the child
// gets MAZE_MAPPER_CHILD_PID_N=1 in its environment, which its descendants inherit, and ending
// it kills every process that holds that mark (found in /proc). This process is made a
// subreaper (PR_SET_CHILD_SUBREAPER), so such orphans are its children to reap. A
// descendant that clears its environment escapes this; a cgroup would not be escaped.
//
// Reading waits with a deadline and a line-length cap, so a child that hangs, floods or
// writes one endless line is noticed; writing never blocks (what the child does not read
// yet waits in a buffer, flushed while reading). Destroying a ChildProcess that still runs
// kills its group and reaps it: no child outlives its owner's scope.

#include <signal.h>
#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace app {

// How a child ended.
struct ChildExit {
  bool exited = false;   // by exit(): code holds its status
  int code = 0;
  int signal = 0;        // killed by this signal (when not exited)
  bool ok() const { return exited && code == 0; }
};
// "exit status 0", "exit status 3", "killed by signal 11 (SIGSEGV)".
std::string describe(const ChildExit &e);

class ChildProcess {
 public:
  using Clock = std::chrono::steady_clock;

  // Starts argv[0], searched on PATH, with argv. Throws common::InputError when it cannot
  // be started (not found, not executable). SIGPIPE is ignored in this process from then on
  // (a child that closed its input must not end us).
  explicit ChildProcess(const std::vector<std::string> &argv);
  ~ChildProcess();
  ChildProcess(const ChildProcess &) = delete;
  ChildProcess &operator=(const ChildProcess &) = delete;

  enum class Read {
    line,         // a whole line, without its "\n" or "\r\n"
    closed,       // the child closed its output, or exited with nothing more in it (a
                  // grandchild may hold it open: the child's end is what counts)
    timeout,      // the deadline passed first
    too_long,     // max_bytes arrived without a line end
    interrupted,  // interrupted() said so (Ctrl-C, SIGTERM)
  };
  // The next line of the child's output; flushes what waits for its input meanwhile.
  // interrupted may be null; it is asked every 50 ms.
  Read read_line(std::string &line, Clock::time_point deadline, std::size_t max_bytes, bool (*interrupted)());
  // Queues text for the child's input. Text to a child that closed its input is dropped.
  void write(std::string_view text);

  // Waits until the deadline for the child to exit on its own, then kills its group and
  // its marked descendants; reaps them either way.
  ChildExit finish(Clock::time_point deadline);
  // Kills its group and its marked descendants now and reaps them.
  ChildExit kill();
  pid_t pid() const { return pid_; }

 private:
  void flush_input();
  bool reap(int options);
  bool exited() const;        // it exited (or was killed) and is not reaped yet
  bool readable_now() const;  // its output holds bytes (or its end) this instant

  std::string mark_;     // MAZE_MAPPER_CHILD_PID_N=1 in its environment and its descendants'

  pid_t pid_ = -1;
  int to_child_ = -1;    // its standard input
  int from_child_ = -1;  // its standard output
  std::string pending_input_;
  std::string buffer_;   // output read past the last line
  bool output_closed_ = false;
  bool reaped_ = false;
  ChildExit exit_;
};

}  // namespace app
