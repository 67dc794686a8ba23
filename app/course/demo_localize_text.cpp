#include "app/course/demo_localize_text.hpp"

#include <fmt/format.h>

namespace app::course {

std::string numbered_map(const loc::WallMap &map) {
  const auto w = static_cast<std::size_t>(map.width), h = static_cast<std::size_t>(map.height);
  std::string out;
  for (std::size_t row = 0; row < h; ++row) {
    out += "o";
    for (std::size_t col = 0; col < w; ++col) out += map.walls[row * w + col][0] ? "---o" : "   o";
    out += "\n";
    out += map.walls[row * w][3] ? "|" : " ";
    for (std::size_t col = 0; col < w; ++col) {
      const std::size_t i = row * w + col;
      out += fmt::format("{:>3}{}", i + 1, map.walls[i][1] ? "|" : " ");
    }
    out += "\n";
  }
  out += "o";
  for (std::size_t col = 0; col < w; ++col) out += map.walls[(h - 1) * w + col][2] ? "---o" : "   o";
  return out + "\n";
}

std::string belief_grid(const loc::WallMap &map, const std::vector<double> &belief) {
  const auto w = static_cast<std::size_t>(map.width);
  std::string out;
  for (std::size_t i = 0; i < map.cells(); ++i) {
    out += fmt::format("{}{:.3f}{}", i % w == 0 ? "  " : " ", belief[i], i % w == w - 1 ? "\n" : "");
  }
  return out;
}

std::string count_grid(const loc::WallMap &map, const std::vector<int> &counts) {
  const auto w = static_cast<std::size_t>(map.width);
  std::string out;
  for (std::size_t i = 0; i < map.cells(); ++i) {
    out += fmt::format(" {:>4}{}", counts[i], i % w == w - 1 ? "\n" : "");
  }
  return out;
}

std::string reading_words(const loc::Reading &z) {
  return fmt::format("N {}, E {}, S {}, W {}", z[0] ? "wall" : "no wall", z[1] ? "wall" : "no wall",
                     z[2] ? "wall" : "no wall", z[3] ? "wall" : "no wall");
}

std::string model_lines(const loc::WallSensor &s, double p_move) {
  return fmt::format("sensor model, each side: P(z=wall|wall) {:g}, P(z=no wall|wall) {:g}, "
                     "P(z=wall|no wall) {:g}, P(z=no wall|no wall) {:g}\n"
                     "motion model: a move succeeds with {:g} and the robot stays with {:g}; "
                     "towards a wall it stays\n",
                     s.wall_given_wall, s.open_given_wall, s.wall_given_open, s.open_given_open, p_move, 1.0 - p_move);
}

std::string correction_by_hand(const loc::WallMap &map, const loc::WallSensor &s, const std::vector<double> &prior,
                               const loc::Reading &z) {
  std::string out = "correction by hand: reading " + reading_words(z) + "\n";
  out += "P(z|cell) = the product over N, E, S, W of P(z_side | the map's side); "
         "posterior = prior x P(z|cell) / sum\n";
  out += fmt::format("cell  walls  {:<31}  {:<6}  {:<17}  posterior\n", "P(z|cell)", "prior", "prior x P(z|cell)");
  std::vector<double> products(prior.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < map.cells(); ++i) sum += products[i] = prior[i] * loc::likelihood(map, s, i, z);
  for (std::size_t i = 0; i < map.cells(); ++i) {
    std::string walls, factors;
    for (std::size_t side = 0; side < 4; ++side) {
      const bool wall = map.walls[i][side];
      walls += wall ? "NESW"[side] : '-';
      const double p = wall ? (z[side] ? s.wall_given_wall : s.open_given_wall) : (z[side] ? s.wall_given_open : s.open_given_open);
      factors += fmt::format("{}{:g}", side == 0 ? "" : " x ", p);
    }
    out += fmt::format("{:>4}  {}   {:<20} = {:.6f}  {:.4f}  {:<17}  {:.3f}\n", i + 1, walls, factors,
                       loc::likelihood(map, s, i, z), prior[i], fmt::format("{:.8f}", products[i]),
                       sum > 0.0 ? products[i] / sum : 0.0);
  }
  out += fmt::format("sum of prior x P(z|cell) = {:.8f}\n", sum);
  return out;
}

}  // namespace app::course
