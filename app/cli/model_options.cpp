#include "app/cli/model_options.hpp"

#include "app/run/option_fields.hpp"

#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli/option_binding.hpp"

namespace app {

void add_model_options(CLI::App &command, mapping::SensorModelOptions &options) {
  add_field_options(command, options, {"--p-free", "--p-occ", "--prior", "--log-base"});
}

void add_clamp_option(CLI::App &command, mapping::SensorModelOptions &options) {
  command
      .add_option_function<std::vector<double>>(
          "--clamp",
          [&options](const std::vector<double> &bounds) { options.clamp = mapping::Clamp{bounds.at(0), bounds.at(1)}; },
          option_help("--clamp"))
      ->expected(2)
      ->allow_extra_args(false);
}

}  // namespace app
