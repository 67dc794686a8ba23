#pragma once
// A time limit in seconds turned into a point on a clock without overflowing it: a limit
// longer than half of what the clock can still count (about 146 years on a 64-bit
// nanosecond clock), and +inf, is no limit (the clock's last instant), as coreutils'
// `timeout` saturates its timer.

#include <chrono>

namespace common {

// `seconds` after `from`; seconds >= 0 and not NaN (the caller has checked the limit).
template <typename Clock>
typename Clock::time_point deadline_after(typename Clock::time_point from, double seconds) {
  using Point = typename Clock::time_point;
  const double room_s = std::chrono::duration<double>(Point::max() - from).count();
  if (!(seconds < room_s / 2.0)) return Point::max();
  return from + std::chrono::duration_cast<typename Clock::duration>(std::chrono::duration<double>(seconds));
}

}  // namespace common
