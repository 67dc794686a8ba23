#pragma once
// The text demo localize prints besides the filter's state (app/run/localization_text.hpp):
// the models in words and step 0's correction worked by hand.

#include <string>
#include <vector>

#include "app/run/localization.hpp"
#include "app/run/localization_text.hpp"

namespace app::course {

// The sensor and motion models in one line each.
std::string model_lines(const loc::WallSensor &sensor, double p_move);
// A correction by hand: every cell's walls, the four factors, P(z|cell), the prior, their
// product and the posterior.
std::string correction_by_hand(const loc::WallMap &map, const loc::WallSensor &sensor,
                               const std::vector<double> &prior, const loc::Reading &z);

}  // namespace app::course
