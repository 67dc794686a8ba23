#pragma once
// SIGINT (Ctrl-C), SIGTERM (what `timeout`, Slurm and Kubernetes send) and SIGHUP (the
// terminal closed), the same way in every command and every phase:
//
//   - by default (install_signal_handlers(), once, in main) a signal ends the process at
//     once: the handler removes every temporary file an OutputFile holds open
//     (common/atomic_file.hpp), so each output is whole or absent, and exits with
//     128 + the signal's number (130, 143, 129), as a shell reports a killed process;
//   - while a SignalsStopWork is alive (a run loop, a batch), a signal only records itself:
//     the work polls interrupted(), stops at its next step, writes what it finished and
//     returns; interrupted_exit_status() is then its exit status. A signal that comes once
//     the guard is gone (the output phase that follows) ends the process as above.
//
// Everything the handler does is async-signal-safe: atomics, poll(2), unlink(2), write(2), _exit(2).

#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstring>
#include <string>

#include "common/error.hpp"

namespace common {

// Work given up because a stop signal was recorded while it waited (a FIFO without a
// reader). main prints it as one `error:` line; the exit status is interrupted_exit_status().
class Interrupted : public RuntimeFailure {
 public:
  using RuntimeFailure::RuntimeFailure;
};

namespace detail {

// The temporaries to remove when a signal ends the process: fixed slots, so that the
// handler reads them without allocating. A slot is claimed (busy), filled, then published.
struct TemporarySlot {
  std::atomic<int> state{0};  // 0 free, 1 being filled or emptied, 2 holds a path
  std::array<char, 4096> path{};
};
inline std::array<TemporarySlot, 64> g_temporaries;
inline std::atomic<int> g_signal{0};          // the first signal received, 0 none
inline std::atomic<int> g_stop_work_depth{0};  // SignalsStopWork guards alive
static_assert(std::atomic<int>::is_always_lock_free);

inline const char *signal_word(int signal_number) {
  switch (signal_number) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

// Writes `text` (shorter than PIPE_BUF: a pipe takes it whole) to standard error when it can
// take it now; a pipe its reader has filled, or a stopped terminal, is not waited on: the
// message is dropped, so that the process still ends.
inline void write_stderr(const char *text) {
  pollfd p{STDERR_FILENO, POLLOUT, 0};
  if (::poll(&p, 1, 0) != 1 || (p.revents & POLLOUT) == 0) return;
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

// Removes every registered temporary; true when one was removed. Async-signal-safe.
inline bool remove_temporaries() {
  bool removed = false;
  for (TemporarySlot &slot : g_temporaries) {
    if (slot.state.load() == 2 && ::unlink(slot.path.data()) == 0) removed = true;
  }
  return removed;
}

// Removes every registered temporary, says why on standard error and exits with 128 + the
// signal: the handler's default, and what a wait that cannot end on its own does once a stop
// signal is recorded (common/stdout_buffer.hpp). Async-signal-safe.
[[noreturn]] inline void end_process_for(int signal_number) {
  const bool removed = remove_temporaries();
  write_stderr("\nerror: interrupted by ");
  write_stderr(signal_word(signal_number));
  write_stderr(removed ? "; unfinished output files removed\n" : "\n");
  ::_exit(128 + signal_number);
}

extern "C" inline void on_stop_signal(int signal_number) {
  int none = 0;
  g_signal.compare_exchange_strong(none, signal_number);
  if (g_stop_work_depth.load() > 0) return;
  end_process_for(signal_number);
}

}  // namespace detail

// The signals that stop the program.
inline constexpr std::array<int, 3> kStopSignals{SIGINT, SIGTERM, SIGHUP};

// Installs the handler above for the three signals, with SA_RESTART (a write to standard
// output that a recorded signal interrupts goes on; common/stdout_buffer.hpp bounds how long
// it may then wait on a reader). Once, at the start of main.
inline void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = detail::on_stop_signal;
  action.sa_flags = SA_RESTART;
  sigemptyset(&action.sa_mask);
  for (const int s : kStopSignals) sigaddset(&action.sa_mask, s);
  for (const int s : kStopSignals) sigaction(s, &action, nullptr);
}

// The first stop signal received (SIGINT, SIGTERM, SIGHUP), 0 when none.
inline int interrupt_signal() { return detail::g_signal.load(); }
inline bool interrupted() { return interrupt_signal() != 0; }
// 128 + the signal (130 for SIGINT, 143 SIGTERM, 129 SIGHUP); 130 when none was recorded
// (a test that stops a run through its own poll function).
inline int interrupted_exit_status() { return 128 + (interrupted() ? interrupt_signal() : SIGINT); }
// "Ctrl-C", "SIGTERM", "SIGHUP": how a summary names what stopped it.
inline std::string interrupt_name() {
  const int s = interrupt_signal();
  return s == SIGINT || s == 0 ? "Ctrl-C" : detail::signal_word(s);
}
// Ends the process for the recorded stop signal as the handler does when no work polls
// (temporaries removed, one `error: interrupted by SIGTERM` line, exit 128 + the signal).
// Only once a signal is recorded: for a wait that would otherwise never end.
[[noreturn]] inline void end_process_for_recorded_signal() { detail::end_process_for(interrupted_exit_status() - 128); }
// Forgets a recorded signal (tests only).
inline void clear_interrupt_for_tests() { detail::g_signal.store(0); }
// Records `signal_number` as if it had arrived while work polls (tests only).
inline void simulate_interrupt_for_tests(int signal_number) { detail::g_signal.store(signal_number); }

// While alive: a stop signal is recorded for the work to poll (interrupted()) instead of
// ending the process. Nests; the last one destroyed restores the default.
class SignalsStopWork {
 public:
  SignalsStopWork() { detail::g_stop_work_depth.fetch_add(1); }
  ~SignalsStopWork() { detail::g_stop_work_depth.fetch_sub(1); }
  SignalsStopWork(const SignalsStopWork &) = delete;
  SignalsStopWork &operator=(const SignalsStopWork &) = delete;
};

// While alive: a stop signal ends the process (the default), even inside a SignalsStopWork
// (the output phase of a run: its files are whole or absent, never half-written).
class SignalsEndProcess {
 public:
  SignalsEndProcess() : saved_(detail::g_stop_work_depth.exchange(0)) {}
  ~SignalsEndProcess() { detail::g_stop_work_depth.store(saved_); }
  SignalsEndProcess(const SignalsEndProcess &) = delete;
  SignalsEndProcess &operator=(const SignalsEndProcess &) = delete;

 private:
  int saved_;
};

// Registers a temporary file for the handler to remove; returns its slot, or -1 when all
// slots are taken or the path is too long (the file is then not removed on a signal).
// Register a path before creating the file (O_EXCL), so that no signal finds the file
// unknown; unregister it once it is renamed or removed, or when creating it failed.
inline int register_temporary(const std::string &path) {
  if (path.size() + 1 > detail::TemporarySlot{}.path.size()) return -1;
  for (std::size_t i = 0; i < detail::g_temporaries.size(); ++i) {
    detail::TemporarySlot &slot = detail::g_temporaries[i];
    int expected = 0;
    if (!slot.state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(slot.path.data(), path.c_str(), path.size() + 1);
    slot.state.store(2);
    return static_cast<int>(i);
  }
  return -1;
}

inline void unregister_temporary(int slot) {
  if (slot < 0) return;
  detail::g_temporaries[static_cast<std::size_t>(slot)].state.store(0);
}

// Forgets every registered temporary without removing it: in a child the process forked (a
// Python controller's os.fork()), whose registered files are its parent's, never the child's
// to remove.
inline void forget_temporaries() {
  for (detail::TemporarySlot &slot : detail::g_temporaries) slot.state.store(0);
}

}  // namespace common
