#pragma once
// The localization filter's state as text (localization.hpp): the known map with its cell
// numbers, the belief as a grid of numbers or as the map shaded, a reading in words. `demo
// localize` and a run with --localize print these.

#include <string>
#include <vector>

#include "app/run/localization.hpp"

namespace app::loc {

// The text map (docs/formats.md) with each cell's number inside it.
std::string numbered_map(const WallMap &map);
// One line a row, north first, each cell's value to 3 decimals.
std::string belief_grid(const WallMap &map, const std::vector<double> &belief);
// One line a row, north first, each cell's count.
std::string count_grid(const WallMap &map, const std::vector<int> &counts);
// "N wall, E no wall, S no wall, W wall".
std::string reading_words(const Reading &z);

// The shade a cell's belief is drawn with (kBeliefShades' legend), from blank (below 0.01)
// to '@' (0.5 and more).
char belief_shade(double p);
// The legend of belief_shade(), one line: "belief: ' ' < 0.01, '.' < 0.05, ...".
std::string belief_legend();
// The text map with each cell filled with its belief's shade, three characters wide; the
// most likely cell (the first of the largest) bracketed: "[@]".
std::string belief_map(const WallMap &map, const std::vector<double> &belief);

}  // namespace app::loc
