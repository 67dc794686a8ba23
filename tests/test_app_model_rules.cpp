#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "app/run/model_rules.hpp"
#include "common/error.hpp"

using sensing::ModelKind;

TEST_CASE("model rules: an option the set-up's model does not read is a warning, named with its readers") {
  const auto warnings = app::check_model_options(sensing::setup(ModelKind::cell), sensing::kHitDepth | sensing::kPieBeta);
  CHECK(warnings == std::vector<std::string>{"warning: --hit-depth has no effect with the cell model (read by ray)",
                                             "warning: --pie-beta has no effect with the cell model (read by pie)"});
  CHECK(app::check_model_options(sensing::setup(ModelKind::ray), sensing::kHitDepth | sensing::kProbabilities).empty());
  CHECK(app::check_model_options(sensing::setup(ModelKind::cone), sensing::kProbabilities).empty());
  CHECK(app::check_model_options(sensing::setup(ModelKind::pie), 0).empty());
}

TEST_CASE("model rules: --p-free/--p-occ with a set-up of fixed course numbers is refused") {
  const auto error_of = [](ModelKind kind) {
    try {
      app::check_model_options(sensing::setup(kind), sensing::kProbabilities);
    } catch (const common::InputError &e) {
      return e.diagnostic();
    }
    return std::string();
  };
  CHECK(error_of(ModelKind::pie) ==
        "error: --p-free and --p-occ do not apply to the pie model: it marks with the course's numbers "
        "(p 0.4 free, 0.7 occupied); --prior, --log-base and --clamp do apply");
  CHECK(error_of(ModelKind::depth) ==
        "error: --p-free and --p-occ do not apply to the depth model: it marks with the course's numbers "
        "(p 0.4 free, 0.99999 occupied, 0.3 at the robot); --prior, --log-base and --clamp do apply");
  CHECK(error_of(ModelKind::bump).starts_with("error: --p-free and --p-occ do not apply to the bump model"));
}
