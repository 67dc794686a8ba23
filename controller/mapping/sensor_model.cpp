#include "mapping/sensor_model.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/error.hpp"

namespace mapping {
namespace {

void require_probability(const char *option, double p) {
  if (!std::isfinite(p) || p <= 0.0 || p >= 1.0) {
    throw common::InputError(
        fmt::format("{} must be a probability strictly between 0 and 1 (got {})", option, p));
  }
}

}  // namespace

void validate(const SensorModelOptions &options) {
  require_probability("--p-free", options.p_free);
  require_probability("--p-occ", options.p_occ);
  require_probability("--prior", options.prior);
  if (!(options.p_free < options.prior)) {
    throw common::InputError(fmt::format("--p-free must be less than --prior (got {} >= {})",
                                         options.p_free, options.prior));
  }
  if (!(options.p_occ > options.prior)) {
    throw common::InputError(fmt::format("--p-occ must be greater than --prior (got {} <= {})",
                                         options.p_occ, options.prior));
  }
  if (options.clamp) {
    const Clamp &c = *options.clamp;
    if (!std::isfinite(c.min) || !std::isfinite(c.max)) {
      throw common::InputError(
          fmt::format("--clamp bounds must be finite numbers (got {} {})", c.min, c.max));
    }
    if (!(c.min < c.max)) {
      throw common::InputError(
          fmt::format("--clamp MIN must be less than MAX (got {} >= {})", c.min, c.max));
    }
    // A new sub-cell starts at l(prior): outside the bounds the first update would jump
    // to a bound, and the map would read unobserved cells as observed.
    const double l0 = log_odds(options.prior, options.base);
    if (!(c.min < l0 && l0 < c.max)) {
      throw common::InputError(fmt::format(
          "--clamp must hold the prior's log-odds {:.4g} (--prior {}) between MIN and MAX (got {} {})", l0,
          options.prior, c.min, c.max));
    }
  }
}

SensorModel::SensorModel(const SensorModelOptions &options) : options_(options) {
  validate(options_);
  prior_ = log_odds(options_.prior, options_.base);
  free_delta_ = log_odds(options_.p_free, options_.base) - prior_;
  occ_delta_ = log_odds(options_.p_occ, options_.base) - prior_;
}

double SensorModel::increment_for(double p) const {
  require_probability("inverse-model probability", p);
  return log_odds(p, options_.base) - prior_;
}

}  // namespace mapping
