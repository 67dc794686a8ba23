#pragma once
// The text demo localize prints (demo_localize.hpp): the map with its cell numbers, a grid of
// values north row first, a reading in words and step 0's correction worked by hand.

#include <string>
#include <vector>

#include "app/course/localization.hpp"

namespace app::course {

// The text map (docs/formats.md) with each cell's number inside it.
std::string numbered_map(const loc::WallMap &map);
// One line a row, north first, each cell's value to 3 decimals.
std::string belief_grid(const loc::WallMap &map, const std::vector<double> &belief);
// One line a row, north first, each cell's count.
std::string count_grid(const loc::WallMap &map, const std::vector<int> &counts);
// "N wall, E no wall, S no wall, W wall".
std::string reading_words(const loc::Reading &z);
// The sensor and motion models in one line each.
std::string model_lines(const loc::WallSensor &sensor, double p_move);
// A correction by hand: every cell's walls, the four factors, P(z|cell), the prior, their
// product and the posterior.
std::string correction_by_hand(const loc::WallMap &map, const loc::WallSensor &sensor,
                               const std::vector<double> &prior, const loc::Reading &z);

}  // namespace app::course
