#include "app/run/localization_text.hpp"

#include <algorithm>
#include <array>
#include <iterator>

#include <fmt/format.h>

namespace app::loc {

namespace {

struct Shade {
  double below;  // drawn for a belief below this
  char shade;
};
constexpr std::array<Shade, 5> kBeliefShades{{{0.01, ' '}, {0.05, '.'}, {0.1, ':'}, {0.25, '+'}, {0.5, '#'}}};
constexpr char kSureShade = '@';  // 0.5 and more

// A row of cell tops: "o---o   o" (wall or opening on the north of each cell of `row`).
std::string tops(const WallMap &map, std::size_t row, std::size_t side) {
  const auto w = static_cast<std::size_t>(map.width);
  std::string out = "o";
  for (std::size_t col = 0; col < w; ++col) out += map.walls[row * w + col][side] ? "---o" : "   o";
  return out + "\n";
}

// The text map with each cell's inside (three characters) from fill(index).
template <typename Fill>
std::string drawn_map(const WallMap &map, Fill fill) {
  const auto w = static_cast<std::size_t>(map.width), h = static_cast<std::size_t>(map.height);
  std::string out;
  for (std::size_t row = 0; row < h; ++row) {
    out += tops(map, row, 0);
    out += map.walls[row * w][3] ? "|" : " ";
    for (std::size_t col = 0; col < w; ++col) {
      const std::size_t i = row * w + col;
      out += fill(i);
      out += map.walls[i][1] ? "|" : " ";
    }
    out += "\n";
  }
  return out + tops(map, h - 1, 2);
}

}  // namespace

std::string numbered_map(const WallMap &map) {
  return drawn_map(map, [](std::size_t i) { return fmt::format("{:>3}", i + 1); });
}

std::string belief_grid(const WallMap &map, const std::vector<double> &belief) {
  const auto w = static_cast<std::size_t>(map.width);
  std::string out;
  for (std::size_t i = 0; i < map.cells(); ++i) {
    out += fmt::format("{}{:.3f}{}", i % w == 0 ? "  " : " ", belief[i], i % w == w - 1 ? "\n" : "");
  }
  return out;
}

std::string count_grid(const WallMap &map, const std::vector<int> &counts) {
  const auto w = static_cast<std::size_t>(map.width);
  std::string out;
  for (std::size_t i = 0; i < map.cells(); ++i) {
    out += fmt::format(" {:>4}{}", counts[i], i % w == w - 1 ? "\n" : "");
  }
  return out;
}

std::string reading_words(const Reading &z) {
  return fmt::format("N {}, E {}, S {}, W {}", z[0] ? "wall" : "no wall", z[1] ? "wall" : "no wall",
                     z[2] ? "wall" : "no wall", z[3] ? "wall" : "no wall");
}

char belief_shade(double p) {
  for (const Shade &s : kBeliefShades) {
    if (p < s.below) return s.shade;
  }
  return kSureShade;
}

std::string belief_legend() {
  std::string out = "shades:";
  for (const Shade &s : kBeliefShades) out += fmt::format(" '{}' < {:g},", s.shade, s.below);
  return out + fmt::format(" '{}' from {:g}; [ ] the most likely cell\n", kSureShade, kBeliefShades.back().below);
}

std::string belief_map(const WallMap &map, const std::vector<double> &belief) {
  const auto likeliest = static_cast<std::size_t>(std::distance(belief.begin(), std::max_element(belief.begin(), belief.end())));
  return drawn_map(map, [&](std::size_t i) {
    const char c = belief_shade(belief[i]);
    return i == likeliest ? fmt::format("[{}]", c) : std::string(3, c);
  });
}

}  // namespace app::loc
