#pragma once
// The sensor-model options every command shares (--p-free, --p-occ, --prior, --log-base,
// --clamp MIN MAX), registered the same way everywhere so they read the same everywhere,
// parsed straight into mapping::SensorModelOptions. Their user validates the result once
// (mapping::validate, or the SensorModel constructor).

#include <CLI/CLI.hpp>

#include "mapping/sensor_model.hpp"

namespace app {

// --p-free, --p-occ, --prior, --log-base e|10 (anything else: common::InputError "--log-base
// must be e or 10 (got 2)"). The defaults shown are the values `options` holds.
void add_model_options(CLI::App &command, mapping::SensorModelOptions &options);

// --clamp MIN MAX.
void add_clamp_option(CLI::App &command, mapping::SensorModelOptions &options);

}  // namespace app
