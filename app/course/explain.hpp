#pragma once
// `maze_mapper explain`: the inverse sensor model's numbers, for a teaching demo where every
// number on screen can be checked by hand: the formulas, a table of p and l(p) in base e and
// 10 for this model's probabilities and those the course and the set-ups use, the increments,
// and the beliefs after repeated updates (clamped too when the model clamps).

#include <string>

#include "mapping/sensor_model.hpp"

namespace app::course {

// The text `explain` prints for a valid sensor model.
std::string explain_text(const mapping::SensorModelOptions &options);

}  // namespace app::course
