#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "common/error.hpp"
#include "mapping/log_odds.hpp"
#include "mapping/sensor_model.hpp"
#include "validation_error.hpp"

using mapping::LogBase;

TEST_CASE("log_odds: the classroom numbers in base e and base 10") {
  CHECK(mapping::log_odds(0.5) == 0.0);
  CHECK(mapping::log_odds(0.6) == doctest::Approx(0.405465).epsilon(1e-6));
  CHECK(mapping::log_odds(0.3) == doctest::Approx(-0.847298).epsilon(1e-6));
  CHECK(mapping::log_odds(0.3, LogBase::ten) == doctest::Approx(-0.367977).epsilon(1e-6));
  CHECK(mapping::log_odds(0.4, LogBase::ten) == doctest::Approx(-0.176091).epsilon(1e-6));
  CHECK(mapping::log_odds(0.99999, LogBase::ten) == doctest::Approx(4.999996).epsilon(1e-6));
}

TEST_CASE("log_odds and probability are inverse over a sweep of p, both bases") {
  for (const LogBase base : {LogBase::e, LogBase::ten}) {
    for (int i = 1; i < 1000; ++i) {
      const double p = i / 1000.0;
      CHECK(mapping::probability(mapping::log_odds(p, base), base) == doctest::Approx(p).epsilon(1e-12));
    }
  }
}

TEST_CASE("probability: tails do not overflow") {
  CHECK(mapping::probability(1000.0) == 1.0);
  CHECK(mapping::probability(-1000.0) == 0.0);
  CHECK(mapping::probability(INFINITY) == 1.0);
  CHECK(mapping::probability(-INFINITY) == 0.0);
}

TEST_CASE("apply: adds, and clamps only when asked") {
  CHECK(mapping::apply(1.0, 0.5, std::nullopt) == 1.5);
  CHECK(mapping::apply(3.0, 1.0, mapping::Clamp{-2.0, 3.5}) == 3.5);
  CHECK(mapping::apply(-1.5, -1.0, mapping::Clamp{-2.0, 3.5}) == -2.0);
}

TEST_CASE("SensorModel: increments are l(p) - l(prior)") {
  const mapping::SensorModel model;
  CHECK(model.prior_log_odds() == 0.0);
  CHECK(model.occupied_increment() == doctest::Approx(0.405465).epsilon(1e-6));
  CHECK(model.free_increment() == doctest::Approx(-0.847298).epsilon(1e-6));
  mapping::SensorModelOptions o;
  o.prior = 0.4;
  const mapping::SensorModel shifted(o);
  CHECK(shifted.occupied_increment() ==
        doctest::Approx(mapping::log_odds(0.6) - mapping::log_odds(0.4)));
}

TEST_CASE("SensorModelOptions: each violation names the option and its value") {
  mapping::SensorModelOptions o;
  CHECK(validation_error(o) == "");

  o = {};
  o.p_occ = 0.4;
  CHECK(validation_error(o) == "error: --p-occ must be greater than --prior (got 0.4 <= 0.5)");
  o = {};
  o.p_free = 0.5;
  CHECK(validation_error(o) == "error: --p-free must be less than --prior (got 0.5 >= 0.5)");
  o = {};
  o.p_occ = 1.5;
  CHECK(validation_error(o) == "error: --p-occ must be a probability strictly between 0 and 1 (got 1.5)");
  o = {};
  o.p_free = 0.0;
  CHECK(validation_error(o) == "error: --p-free must be a probability strictly between 0 and 1 (got 0)");
  o = {};
  o.prior = 1.0;
  CHECK(validation_error(o) == "error: --prior must be a probability strictly between 0 and 1 (got 1)");
  o = {};
  o.p_occ = NAN;
  CHECK(validation_error(o) == "error: --p-occ must be a probability strictly between 0 and 1 (got nan)");
  o = {};
  o.clamp = mapping::Clamp{3.0, -2.0};
  CHECK(validation_error(o) == "error: --clamp MIN must be less than MAX (got 3 >= -2)");
  o = {};
  o.clamp = mapping::Clamp{-INFINITY, 2.0};
  CHECK(validation_error(o) == "error: --clamp bounds must be finite numbers (got -inf 2)");
}
