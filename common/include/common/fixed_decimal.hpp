#pragma once
// Numbers appended to a text the way fmt's "{}" (an integer) and "{:.Nf}" (a double, N
// decimals) write them, byte for byte, at a fraction of the cost: a long CSV (trace.csv) is
// mostly such numbers, and parsing fmt's format string and its exact decimal conversion took
// most of the time of writing it. A double whose decimal rounding is close to a tie, or too
// big for the fast path, or not finite, is written by fmt itself.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

#include <fmt/format.h>

namespace common {

template <typename Integer>
void append_int(std::string &text, Integer v) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, v).ptr;
  text.append(digits, static_cast<std::size_t>(end - digits));
}

// `v` with `decimals` (0 to 9) digits after the point, as fmt::format("{:.{}f}", v, decimals).
inline void append_fixed(std::string &text, double v, int decimals) {
  static constexpr double kScale[10] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
  const double scaled = std::abs(v) * kScale[decimals];
  // Below 2^31 the product is within 2^-22 of |v| x 10^N, far inside the margin to a tie.
  const double whole = std::floor(scaled);
  const double fraction = scaled - whole;
  if (!(scaled < 2147483648.0) || std::abs(fraction - 0.5) < 1e-6) {
    fmt::format_to(std::back_inserter(text), "{:.{}f}", v, decimals);
    return;
  }
  const auto units = static_cast<std::uint64_t>(whole) + (fraction > 0.5 ? 1 : 0);
  if (std::signbit(v)) text += '-';
  std::uint64_t power = 1;
  for (int i = 0; i < decimals; ++i) power *= 10;
  append_int(text, units / power);
  if (decimals == 0) return;
  text += '.';
  char digits[9];
  std::uint64_t rest = units % power;
  for (int i = decimals - 1; i >= 0; --i) {
    digits[i] = static_cast<char>('0' + rest % 10);
    rest /= 10;
  }
  text.append(digits, static_cast<std::size_t>(decimals));
}

}  // namespace common
