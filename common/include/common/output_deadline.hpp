#pragma once
// The time a run's files get once a stop signal has ended the run. A scheduler sends SIGTERM
// and SIGKILL some seconds later (Slurm and Kubernetes 30 s by default); the pictures and the
// replay of a large map take longer than that, and a SIGKILL leaves temporaries behind. So
// once a stop signal is recorded, the files still to be written get kStoppedOutputBudget_ms:
// at its end the process ends as the stop signal's handler ends it (the temporary being
// written removed, every file written before kept whole, exit 128 + the signal), and its one
// `error:` line names the files that were written, so the rest are known to be left out.
// A writer writes the files that matter most first (summary.json, trace.csv).

#include <signal.h>
#include <sys/time.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstring>
#include <string_view>

#include "common/interrupt.hpp"

namespace common {

inline constexpr int kStoppedOutputBudget_ms = 2000;

namespace detail {

inline std::array<char, 2048> g_written_names{};  // "summary.json, trace.csv", published by length
inline std::atomic<std::size_t> g_written_length{0};

// At the budget's end: async-signal-safe, as the stop signal's handler; the line is written
// whole or not at all (common::detail::write_stderr).
extern "C" inline void on_output_deadline(int) {
  remove_temporaries();
  std::array<char, 2400> line{};
  std::size_t at = 0;
  const auto append = [&line, &at](const char *text, std::size_t size) {
    size = std::min(size, line.size() - 1 - at);
    std::memcpy(line.data() + at, text, size);
    at += size;
  };
  const auto append_text = [&append](const char *text) { append(text, std::strlen(text)); };
  append_text("\nerror: interrupted by ");
  append_text(signal_word(g_signal.load()));
  append_text("; the files not written within 2 s of it are left out (written: ");
  const std::size_t length = g_written_length.load();
  if (length == 0) append_text("none");
  append(g_written_names.data(), length);
  append_text(")\n");
  line[at] = '\0';
  write_stderr(line.data());
  ::_exit(128 + g_signal.load());
}

}  // namespace detail

// While alive, the budget runs (a real-time timer, SIGALRM): armed when constructed, disarmed
// when destroyed. One at a time; only once a stop signal is recorded (interrupted()).
class StoppedOutputDeadline {
 public:
  StoppedOutputDeadline() {
    detail::g_written_length.store(0);
    struct sigaction action {};
    action.sa_handler = detail::on_output_deadline;
    sigemptyset(&action.sa_mask);
    for (const int s : kStopSignals) sigaddset(&action.sa_mask, s);
    sigaction(SIGALRM, &action, &previous_);
    itimerval budget{};
    budget.it_value.tv_sec = kStoppedOutputBudget_ms / 1000;
    budget.it_value.tv_usec = (kStoppedOutputBudget_ms % 1000) * 1000;
    setitimer(ITIMER_REAL, &budget, nullptr);
  }
  ~StoppedOutputDeadline() {
    const itimerval off{};
    setitimer(ITIMER_REAL, &off, nullptr);
    sigaction(SIGALRM, &previous_, nullptr);
  }
  StoppedOutputDeadline(const StoppedOutputDeadline &) = delete;
  StoppedOutputDeadline &operator=(const StoppedOutputDeadline &) = delete;

  // Adds `name` to the files the deadline's line says were written (what does not fit is
  // left out of the line).
  void written(std::string_view name) {
    std::size_t length = detail::g_written_length.load();
    const std::string_view separator = length == 0 ? "" : ", ";
    if (length + separator.size() + name.size() > detail::g_written_names.size()) return;
    std::memcpy(detail::g_written_names.data() + length, separator.data(), separator.size());
    length += separator.size();
    std::memcpy(detail::g_written_names.data() + length, name.data(), name.size());
    detail::g_written_length.store(length + name.size());
  }

 private:
  struct sigaction previous_ {};
};

}  // namespace common
