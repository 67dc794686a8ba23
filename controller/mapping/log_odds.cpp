#include "mapping/log_odds.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace mapping {

std::string_view to_string(LogBase base) { return base == LogBase::e ? "e" : "10"; }

double log_odds(double p, LogBase base) {
  assert(p > 0.0 && p < 1.0);
  const double natural = std::log(p / (1.0 - p));
  return base == LogBase::e ? natural : natural / std::log(10.0);
}

double probability(double log_odds_value, LogBase base) {
  const double natural = base == LogBase::e ? log_odds_value : log_odds_value * std::log(10.0);
  // 1 / (1 + e^-l) written so that neither tail overflows.
  if (natural >= 0.0) return 1.0 / (1.0 + std::exp(-natural));
  const double e = std::exp(natural);
  return e / (1.0 + e);
}

double apply(double log_odds_value, double delta, const std::optional<Clamp> &clamp) {
  const double sum = log_odds_value + delta;
  if (!clamp) return sum;
  return std::clamp(sum, clamp->min, clamp->max);
}

}  // namespace mapping
