#include "model_options.hpp"

#include "common/error.hpp"

namespace app {

void add_model_options(CLI::App &command, ModelOptionsInput &input) {
  command.add_option("--p-free", input.p_free, "inverse model where a beam passed (default 0.3)");
  command.add_option("--p-occ", input.p_occ, "inverse model where a beam ended (default 0.6)");
  command.add_option("--prior", input.prior, "belief before any measurement (default 0.5)");
  command.add_option("--log-base", input.log_base, "base of the log-odds: e or 10 (default e)");
}

void add_clamp_option(CLI::App &command, ModelOptionsInput &input) {
  command.add_option("--clamp", input.clamp, "hold log-odds within MIN MAX (OctoMap: -2 3.5)")
      ->expected(2)
      ->allow_extra_args(false);
}

mapping::SensorModelOptions to_sensor_model_options(const ModelOptionsInput &input) {
  mapping::SensorModelOptions options;
  options.p_free = input.p_free;
  options.p_occ = input.p_occ;
  options.prior = input.prior;
  if (input.log_base == "e") {
    options.base = mapping::LogBase::e;
  } else if (input.log_base == "10") {
    options.base = mapping::LogBase::ten;
  } else {
    throw common::InputError("--log-base must be e or 10 (got " + input.log_base + ")");
  }
  if (!input.clamp.empty()) options.clamp = mapping::Clamp{input.clamp.at(0), input.clamp.at(1)};
  return options;
}

}  // namespace app
