#pragma once
// Log-odds arithmetic: the handful of free functions every mapping model is built on.
//
//   l(p) = log_b(p / (1 - p))          log_odds(p, base)
//   p(l) = 1 - 1 / (1 + b^l)           probability(l, base)
//   l   <- clamp(l + delta)            apply(l, delta, clamp)
//
// Base e is the default; base 10 reproduces the course reports' numbers
// (l(0.3) = -0.368, l(0.4) = -0.176, l(0.99999) = 5.000).

#include <optional>
#include <string_view>

namespace mapping {

enum class LogBase { e, ten };

std::string_view to_string(LogBase base);

// Lower and upper bound a log-odds value is held within (OctoMap's preset: -2, 3.5).
struct Clamp {
  double min = -2.0;
  double max = 3.5;
};

// Log-odds of a probability p in (0, 1).
double log_odds(double p, LogBase base = LogBase::e);

// Probability of a log-odds value, the inverse of log_odds; exact at +-infinity.
double probability(double log_odds_value, LogBase base = LogBase::e);

// l + delta, held within clamp when one is given.
double apply(double log_odds_value, double delta, const std::optional<Clamp> &clamp);

}  // namespace mapping
