#include "app/cli/model_options.hpp"

#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"

namespace app {

void add_model_options(CLI::App &command, mapping::SensorModelOptions &options) {
  command.add_option("--p-free", options.p_free,
                     fmt::format("inverse model where a beam passed (default {})", options.p_free));
  command.add_option("--p-occ", options.p_occ,
                     fmt::format("inverse model where a beam ended (default {})", options.p_occ));
  command.add_option("--prior", options.prior,
                     fmt::format("belief before any measurement (default {})", options.prior));
  command.add_option_function<std::string>(
      "--log-base",
      [&options](const std::string &base) {
        if (base == "e") {
          options.base = mapping::LogBase::e;
        } else if (base == "10") {
          options.base = mapping::LogBase::ten;
        } else {
          throw common::InputError("--log-base must be e or 10 (got " + base + ")");
        }
      },
      fmt::format("base of the log-odds: e or 10 (default {})", mapping::to_string(options.base)));
}

void add_clamp_option(CLI::App &command, mapping::SensorModelOptions &options) {
  command
      .add_option_function<std::vector<double>>(
          "--clamp",
          [&options](const std::vector<double> &bounds) { options.clamp = mapping::Clamp{bounds.at(0), bounds.at(1)}; },
          "MIN MAX: hold log-odds within MIN and MAX, either side of the prior's (OctoMap: -2 3.5) (default none)")
      ->expected(2)
      ->allow_extra_args(false);
}

}  // namespace app
