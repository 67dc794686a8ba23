#pragma once
// The one rule for reading a number from text, shared by every reader (options, files,
// protocols, controllerArgs): the text is the number and nothing else. Decimal, in the C
// locale (std::from_chars), a '-' sign allowed and no '+', no blanks around it, in the
// type's range (no silent clamping or wrapping), and for a floating-point type finite ("nan"
// and "inf" are no number here; parse_real reads them, for a caller that says "must be
// finite" apart from "is not a number"). Callers that accept blanks around a list's items
// trim them with parse_number_trimmed.

#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>
#include <system_error>
#include <type_traits>

namespace common {

namespace detail {
template <typename Number>
std::optional<Number> parse_whole_text(std::string_view text) {
  static_assert(std::is_arithmetic_v<Number> && !std::is_same_v<Number, bool>);
  Number value{};
  const char *end = text.data() + text.size();
  const auto [at, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || at != end) return std::nullopt;
  return value;
}
}  // namespace detail

template <typename Number>
std::optional<Number> parse_number(std::string_view text) {
  const std::optional<Number> value = detail::parse_whole_text<Number>(text);
  if constexpr (std::is_floating_point_v<Number>) {
    if (value && !std::isfinite(*value)) return std::nullopt;
  }
  return value;
}

// The same rule for a double, but "inf", "-inf" and "nan" read as themselves.
inline std::optional<double> parse_real(std::string_view text) { return detail::parse_whole_text<double>(text); }

// Whether `text` has the form of a Number but lies past its range: "1e999" or "1e-999" for a
// double (what strtod would turn into inf or 0), 2^63 for a long long. A reader says "out of
// range" for it rather than "not a number".
template <typename Number>
bool out_of_range(std::string_view text) {
  Number value{};
  const char *end = text.data() + text.size();
  const auto [at, ec] = std::from_chars(text.data(), end, value);
  return !text.empty() && ec == std::errc::result_out_of_range && at == end;
}

// How a reader names what it wanted when `text` is no Number: "a number" becomes
// "a number (got '1e999', out of range)" or "a number (got 'abc')".
template <typename Number>
std::string_view range_note(std::string_view text) {
  return out_of_range<Number>(text) ? ", out of range" : "";
}

// Spaces and tabs at both ends removed.
inline std::string_view trim_blanks(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// parse_number after trim_blanks: "3, 5" reads as 3 and 5.
template <typename Number>
std::optional<Number> parse_number_trimmed(std::string_view text) {
  return parse_number<Number>(trim_blanks(text));
}

}  // namespace common
