#pragma once
// How the arena writers (solids_format.cpp, xml_solids.cpp) write a length or a coordinate.

#include <cmath>
#include <string>

#include <fmt/format.h>

namespace maze {

// 12 significant digits (a picometre on a metre; the rounding of sums and halves in doubles
// left out), -0 as 0.
inline std::string metres_text(double v) { return fmt::format("{:.12g}", v + 0.0); }

// `v` rounded to the 12th significant digit of `scale_m` (the largest magnitude among the
// numbers it is written with), then as metres_text: a coordinate computed from others (a
// wall's end from its centre, half length and angle) drops the rounding noise that 12 digits
// of its own would keep (1.9e-15 for an end at 0 on a wall 50 m long), so that what is read
// back writes the same text again.
inline std::string metres_text_on_scale(double v, double scale_m) {
  if (!(scale_m > 0.0) || !std::isfinite(scale_m)) return metres_text(v);
  const double step = std::pow(10.0, std::floor(std::log10(scale_m)) - 11.0);
  return metres_text(std::round(v / step) * step);
}

}  // namespace maze
