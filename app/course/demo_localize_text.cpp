#include "app/course/demo_localize_text.hpp"

#include <fmt/format.h>

namespace app::course {

std::string model_lines(const loc::WallSensor &s, double p_move) {
  return fmt::format("sensor model, each side: P(z=wall|wall) {:g}, P(z=no wall|wall) {:g}, "
                     "P(z=wall|no wall) {:g}, P(z=no wall|no wall) {:g}\n"
                     "motion model: a move succeeds with {:g} and the robot stays with {:g}; "
                     "towards a wall it stays\n",
                     s.wall_given_wall, s.open_given_wall, s.wall_given_open, s.open_given_open, p_move, 1.0 - p_move);
}

std::string correction_by_hand(const loc::WallMap &map, const loc::WallSensor &s, const std::vector<double> &prior,
                               const loc::Reading &z) {
  std::string out = "correction by hand: reading " + loc::reading_words(z) + "\n";
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
