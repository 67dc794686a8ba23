#include "app/mms/child_process.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "common/error.hpp"

extern char **environ;

namespace app {
namespace {

constexpr auto kPollSlice = std::chrono::milliseconds(50);

void close_fd(int &fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

// A pipe whose ends are closed in every child but the one they are handed to.
std::array<int, 2> make_pipe() {
  std::array<int, 2> fds{-1, -1};
  if (::pipe2(fds.data(), O_CLOEXEC) != 0) throw common::InputError(fmt::format("cannot make a pipe: {}", std::strerror(errno)));
  return fds;
}

// posix_spawn's attributes and file actions, destroyed whatever happens.
struct SpawnSetup {
  posix_spawnattr_t attr{};
  posix_spawn_file_actions_t actions{};
  SpawnSetup() {
    posix_spawnattr_init(&attr);
    posix_spawn_file_actions_init(&actions);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
  }
  SpawnSetup(const SpawnSetup &) = delete;
  SpawnSetup &operator=(const SpawnSetup &) = delete;
};

// This process adopts its orphaned descendants (prctl PR_SET_CHILD_SUBREAPER): a grandchild
// whose parent died is ours to end and reap, not init's. Once per process.
void adopt_orphans() {
  static std::once_flag once;
  std::call_once(once, [] { ::prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0); });
}

// "MAZE_MAPPER_CHILD_PID_N=1": unique to one ChildProcess of this process, inherited by all
// its child's descendants (a grandchild that left the group with setsid(2) too). A name of
// its own, so that the marks of an mms run inside an mms run's program are both kept.
std::string descendant_mark() {
  static std::atomic<unsigned> serial{0};
  return fmt::format("MAZE_MAPPER_CHILD_{}_{}=1", ::getpid(), serial.fetch_add(1));
}

// Our environment with `mark` added.
std::vector<char *> environment_with(const std::string &mark) {
  std::vector<char *> env;
  for (char **e = environ; *e != nullptr; ++e) env.push_back(*e);
  env.push_back(const_cast<char *>(mark.c_str()));
  env.push_back(nullptr);
  return env;
}

// Whether process `pid`'s environment holds `mark` (false once it is a zombie: /proc shows
// no environment then).
bool has_mark(pid_t pid, const std::string &mark) {
  std::ifstream file(fmt::format("/proc/{}/environ", pid), std::ios::binary);
  std::string entry;
  while (std::getline(file, entry, '\0')) {
    if (entry == mark) return true;
  }
  return false;
}

// The live processes (ours excepted) whose environment holds `mark`.
std::vector<pid_t> marked_processes(const std::string &mark) {
  std::vector<pid_t> found;
  DIR *proc = ::opendir("/proc");
  if (proc == nullptr) return found;
  const pid_t self = ::getpid();
  while (const dirent *entry = ::readdir(proc)) {
    char *end = nullptr;
    const long pid = std::strtol(entry->d_name, &end, 10);
    if (end == entry->d_name || *end != '\0' || pid <= 0 || pid == self) continue;
    if (has_mark(static_cast<pid_t>(pid), mark)) found.push_back(static_cast<pid_t>(pid));
  }
  ::closedir(proc);
  return found;
}

// Kills every live process holding `mark` until none is left (what is killed may fork
// meanwhile: scanned again), then reaps those that became our children (orphans adopted).
// Gives up after about a second.
void end_marked(const std::string &mark) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  std::vector<pid_t> killed;
  for (;;) {
    const std::vector<pid_t> alive = marked_processes(mark);
    if (alive.empty() || std::chrono::steady_clock::now() >= give_up) break;
    for (const pid_t pid : alive) {
      ::kill(pid, SIGKILL);
      if (std::find(killed.begin(), killed.end(), pid) == killed.end()) killed.push_back(pid);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  while (!killed.empty() && std::chrono::steady_clock::now() < give_up) {
    std::erase_if(killed, [](pid_t pid) {
      const pid_t r = ::waitpid(pid, nullptr, WNOHANG);
      return r == pid || (r < 0 && errno == ECHILD && ::kill(pid, 0) != 0);  // reaped, or gone elsewhere
    });
    if (!killed.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

}  // namespace

std::string describe(const ChildExit &e) {
  if (e.exited) return fmt::format("exit status {}", e.code);
  const char *name = sigabbrev_np(e.signal);
  return name != nullptr ? fmt::format("killed by signal {} (SIG{})", e.signal, name)
                         : fmt::format("killed by signal {}", e.signal);
}

ChildProcess::ChildProcess(const std::vector<std::string> &argv) {
  if (argv.empty()) throw common::InputError("no command to run");
  ::signal(SIGPIPE, SIG_IGN);
  std::array<int, 2> in = make_pipe();
  std::array<int, 2> out{-1, -1};
  try {
    out = make_pipe();
  } catch (...) {
    close_fd(in[0]);
    close_fd(in[1]);
    throw;
  }
  SpawnSetup setup;
  posix_spawn_file_actions_adddup2(&setup.actions, in[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&setup.actions, out[1], STDOUT_FILENO);
  // Its own process group (ended as a whole), the signals we catch or ignore back to default.
  sigset_t defaults;
  sigemptyset(&defaults);
  for (const int s : {SIGPIPE, SIGINT, SIGTERM}) sigaddset(&defaults, s);
  posix_spawnattr_setsigdefault(&setup.attr, &defaults);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&setup.attr, &none);
  posix_spawnattr_setpgroup(&setup.attr, 0);
  posix_spawnattr_setflags(&setup.attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  std::vector<char *> args;
  for (const std::string &a : argv) args.push_back(const_cast<char *>(a.c_str()));
  args.push_back(nullptr);
  adopt_orphans();
  mark_ = descendant_mark();
  std::vector<char *> env = environment_with(mark_);
  const int error = posix_spawnp(&pid_, args[0], &setup.actions, &setup.attr, args.data(), env.data());
  close_fd(in[0]);
  close_fd(out[1]);
  if (error != 0) {
    close_fd(in[1]);
    close_fd(out[0]);
    throw common::InputError(fmt::format("cannot start '{}': {}", argv[0], std::strerror(error)));
  }
  to_child_ = in[1];
  from_child_ = out[0];
  ::fcntl(to_child_, F_SETFL, ::fcntl(to_child_, F_GETFL) | O_NONBLOCK);
}

ChildProcess::~ChildProcess() {
  if (!reaped_) kill();
  close_fd(to_child_);
  close_fd(from_child_);
}

void ChildProcess::write(std::string_view text) {
  if (to_child_ < 0) return;
  pending_input_ += text;
  flush_input();
}

void ChildProcess::flush_input() {
  while (to_child_ >= 0 && !pending_input_.empty()) {
    const ssize_t n = ::write(to_child_, pending_input_.data(), pending_input_.size());
    if (n > 0) {
      pending_input_.erase(0, static_cast<std::size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else if (n < 0 && errno == EAGAIN) {
      return;
    } else {  // EPIPE: it closed its input
      pending_input_.clear();
      close_fd(to_child_);
    }
  }
}

ChildProcess::Read ChildProcess::read_line(std::string &line, Clock::time_point deadline, std::size_t max_bytes,
                                           bool (*interrupted)()) {
  for (;;) {
    if (const std::size_t end = buffer_.find('\n'); end != std::string::npos) {
      if (end > max_bytes) return Read::too_long;
      line.assign(buffer_, 0, end);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      buffer_.erase(0, end + 1);
      return Read::line;
    }
    if (buffer_.size() > max_bytes) return Read::too_long;
    if (output_closed_) return Read::closed;
    if (interrupted != nullptr && interrupted()) return Read::interrupted;
    const auto now = Clock::now();
    if (now >= deadline) return Read::timeout;
    const auto wait = std::min<Clock::duration>(deadline - now, kPollSlice);
    std::array<pollfd, 2> fds{pollfd{from_child_, POLLIN, 0}, pollfd{to_child_, POLLOUT, 0}};
    const nfds_t count = (to_child_ >= 0 && !pending_input_.empty()) ? 2 : 1;
    const int ms = static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(wait).count()) + 1;
    const int ready = ::poll(fds.data(), count, ms);
    if (ready < 0 && errno != EINTR) throw std::runtime_error(fmt::format("poll: {}", std::strerror(errno)));
    if (ready == 0 && exited() && !readable_now()) {
      // It ended and said all it will: a grandchild holding its output open is not it.
      output_closed_ = true;
      if (!buffer_.empty()) buffer_ += '\n';
      continue;
    }
    if (count == 2 && (fds[1].revents & (POLLOUT | POLLERR | POLLHUP)) != 0) flush_input();
    if ((fds[0].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
      std::array<char, 65536> chunk{};
      const ssize_t n = ::read(from_child_, chunk.data(), chunk.size());
      if (n > 0) {
        buffer_.append(chunk.data(), static_cast<std::size_t>(n));
      } else if (n == 0 || (errno != EINTR && errno != EAGAIN)) {
        output_closed_ = true;
        if (!buffer_.empty()) buffer_ += '\n';  // a last line without its line end
      }
    }
  }
}

bool ChildProcess::readable_now() const {
  pollfd p{from_child_, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0;
}

bool ChildProcess::reap(int options) {
  if (reaped_) return true;
  int status = 0;
  pid_t r = 0;
  do {
    r = ::waitpid(pid_, &status, options);
  } while (r < 0 && errno == EINTR);
  if (r != pid_) return false;
  reaped_ = true;
  exit_.exited = WIFEXITED(status);
  exit_.code = exit_.exited ? WEXITSTATUS(status) : 0;
  exit_.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return true;
}

ChildExit ChildProcess::finish(Clock::time_point deadline) {
  close_fd(to_child_);  // end of its input: a child reading more sees it
  for (;;) {
    // Exited, not reaped yet: its group id stays its own while what it left behind is killed.
    if (exited()) break;
    if (Clock::now() >= deadline) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return kill();
}

ChildExit ChildProcess::kill() {
  if (!reaped_) {
    ::kill(-pid_, SIGKILL);  // the group: what it started too
    reap(0);
    end_marked(mark_);       // and what left the group (setsid), orphaned to us by now
  }
  close_fd(to_child_);
  return exit_;
}

bool ChildProcess::exited() const {
  siginfo_t info{};
  return ::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid_;
}

}  // namespace app
