#include "app/run/model_rules.hpp"

#include <fmt/format.h>

#include "common/error.hpp"

namespace app {
namespace {

// "ray", "cell, ray and cone": the set-ups whose model reads the option.
std::string readers_of(sensing::ModelOption option) {
  std::vector<std::string_view> names;
  for (const sensing::SetUp &s : sensing::setups()) {
    if (s.uses(option)) names.push_back(s.name);
  }
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? " and " : ", ";
    text += names[i];
  }
  return text;
}

std::string fixed_numbers(const sensing::MarkProbabilities &p) {
  std::string text = fmt::format("p {} free, {} occupied", p.p_free, p.p_occ);
  if (p.p_robot) text += fmt::format(", {} at the robot", *p.p_robot);
  return text;
}

}  // namespace

std::vector<std::string> check_model_options(const sensing::SetUp &setup, unsigned given) {
  std::vector<std::string> warnings;
  for (const sensing::ModelOption option : sensing::kModelOptions) {
    if ((given & option) == 0 || setup.uses(option)) continue;
    if (option == sensing::kProbabilities && setup.fixed) {
      throw common::InputError(fmt::format("--p-free and --p-occ do not apply to the {} model: it marks with the "
                                           "course's numbers ({}); --prior, --log-base and --clamp do apply",
                                           setup.name, fixed_numbers(*setup.fixed)));
    }
    warnings.push_back(fmt::format("warning: {} has no effect with the {} model (read by {})",
                                   sensing::option_name(option), setup.name, readers_of(option)));
  }
  return warnings;
}

}  // namespace app
