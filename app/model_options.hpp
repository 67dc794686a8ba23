#pragma once
// The sensor-model options every command shares (--p-free, --p-occ, --prior, --log-base,
// --clamp MIN MAX), registered the same way everywhere so they read the same everywhere.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "mapping/sensor_model.hpp"

namespace app {

// The options as typed; to_sensor_model_options() turns them into the validated struct.
struct ModelOptionsInput {
  double p_free = mapping::SensorModelOptions{}.p_free;
  double p_occ = mapping::SensorModelOptions{}.p_occ;
  double prior = mapping::SensorModelOptions{}.prior;
  std::string log_base = "e";
  std::vector<double> clamp;  // empty, or MIN MAX
};

// --p-free, --p-occ, --prior, --log-base e|10.
void add_model_options(CLI::App &command, ModelOptionsInput &input);

// --clamp MIN MAX.
void add_clamp_option(CLI::App &command, ModelOptionsInput &input);

// Parses --log-base and --clamp; throws common::InputError ("--log-base must be e or 10
// (got 2)"). The result still has to be validated (mapping::validate) by its user.
mapping::SensorModelOptions to_sensor_model_options(const ModelOptionsInput &input);

}  // namespace app
