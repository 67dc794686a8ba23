#pragma once
// The inverse sensor model's numbers, as options and as precomputed increments.
//
// Options are checked once, in the SensorModel constructor; the hot loops only add the
// precomputed increments  l(inv(z)) - l(prior)  (the update rule l <- l + l(inv(z)) - l0).

#include <optional>

#include "mapping/log_odds.hpp"

namespace mapping {

// What a user sets with --p-free, --p-occ, --prior, --log-base and --clamp.
struct SensorModelOptions {
  double p_free = 0.3;   // inverse model where a beam passed: "probably free"
  double p_occ = 0.6;    // inverse model where a beam ended: "probably occupied"
  double prior = 0.5;    // belief before any measurement
  LogBase base = LogBase::e;
  std::optional<Clamp> clamp;  // none by default
};

// Throws common::InputError with the option's name and value when the options cannot be
// used: every p strictly inside (0, 1), p_free < prior < p_occ, clamp min < l(prior) < max (a range that excludes
// the prior would pin every sub-cell at a bound after one update), all finite.
void validate(const SensorModelOptions &options);

class SensorModel {
 public:
  // Validates the options (throws common::InputError) and computes the increments once.
  explicit SensorModel(const SensorModelOptions &options = {});

  const SensorModelOptions &options() const { return options_; }

  double prior_log_odds() const { return prior_; }      // l(prior), the value of a new sub-cell
  double free_increment() const { return free_delta_; } // l(p_free) - l(prior) < 0
  double occupied_increment() const { return occ_delta_; }  // l(p_occ) - l(prior) > 0

  // The increment for any other inverse-model probability p (bump, pie and depth models
  // use their own p's), in this model's base and relative to its prior.
  double increment_for(double p) const;

  double update_free(double l) const { return apply(l, free_delta_, options_.clamp); }
  double update_occupied(double l) const { return apply(l, occ_delta_, options_.clamp); }

  // Probability of a log-odds value in this model's base.
  double probability_of(double l) const { return probability(l, options_.base); }

 private:
  SensorModelOptions options_;
  double prior_ = 0.0;
  double free_delta_ = 0.0;
  double occ_delta_ = 0.0;
};

}  // namespace mapping
