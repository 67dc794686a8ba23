#include "app/run/localization.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "app/run/option_values.hpp"
#include "common/error.hpp"

namespace app::loc {

Trilateration trilaterate(const std::array<Landmark, 3> &m, const std::array<double, 3> &r) {
  const double x1 = m[0].x_m, y1 = m[0].y_m, x2 = m[1].x_m, y2 = m[1].y_m, x3 = m[2].x_m, y3 = m[2].y_m;
  Trilateration t{};
  t.a = -2 * x1 + 2 * x2;
  t.b = -2 * y1 + 2 * y2;
  t.c = r[0] * r[0] - r[1] * r[1] - x1 * x1 + x2 * x2 - y1 * y1 + y2 * y2;
  t.d = -2 * x2 + 2 * x3;
  t.e = -2 * y2 + 2 * y3;
  t.f = r[1] * r[1] - r[2] * r[2] - x2 * x2 + x3 * x3 - y2 * y2 + y3 * y3;
  const double den = t.e * t.a - t.b * t.d;
  if (den == 0.0) {
    throw common::InputError(fmt::format("the landmarks {}, {} and {} lie on one line: E A - B D = 0", m[0].name,
                                         m[1].name, m[2].name));
  }
  t.x_m = (t.c * t.e - t.f * t.b) / den;
  t.y_m = (t.c * t.d - t.a * t.f) / (t.b * t.d - t.a * t.e);
  return t;
}

std::optional<int> arena_cell(double x_m, double y_m) {
  if (!(std::abs(x_m) <= kArenaHalf_m && std::abs(y_m) <= kArenaHalf_m)) return std::nullopt;
  const int col = std::min(kArenaSide - 1, static_cast<int>(std::floor(x_m + kArenaHalf_m)));
  const int row = std::min(kArenaSide - 1, static_cast<int>(std::floor(kArenaHalf_m - y_m)));
  return row * kArenaSide + col + 1;
}

std::array<double, 2> arena_cell_centre(int n) {
  const int row = (n - 1) / kArenaSide, col = (n - 1) % kArenaSide;
  return {-kArenaHalf_m + col + 0.5, kArenaHalf_m - row - 0.5};
}

double normal_density(double z, double mean, double sigma) {
  const double u = (z - mean) / sigma;
  return std::exp(-0.5 * u * u) / (sigma * std::sqrt(2 * std::numbers::pi));
}

std::vector<double> cell_scores(const std::array<std::optional<double>, 4> &distances_m, double sigma_m) {
  std::vector<double> scores(kArenaSide * kArenaSide, 1.0);
  double sum = 0.0;
  for (std::size_t n = 1; n <= scores.size(); ++n) {
    const auto [cx, cy] = arena_cell_centre(static_cast<int>(n));
    for (std::size_t k = 0; k < 4; ++k) {
      if (!distances_m[k]) continue;
      const double expected = std::hypot(cx - kArenaLandmarks[k].x_m, cy - kArenaLandmarks[k].y_m);
      scores[n - 1] *= normal_density(*distances_m[k], expected, sigma_m);
    }
    sum += scores[n - 1];
  }
  if (sum > 0.0) {
    for (double &s : scores) s /= sum;
  }
  return scores;
}

std::size_t WallMap::neighbour(std::size_t index, std::size_t side) const {
  const auto w = static_cast<std::size_t>(width);
  switch (side) {
    case 0: return index - w;
    case 1: return index + 1;
    case 2: return index + w;
    default: return index - 1;
  }
}

std::size_t cell_index(const WallMap &map, maze::Cell c) {
  return static_cast<std::size_t>((map.height - 1 - c.y) * map.width + c.x);
}

maze::Cell maze_cell(const WallMap &map, std::size_t index) {
  const int i = static_cast<int>(index);
  return {i % map.width, map.height - 1 - i / map.width};
}

WallMap wall_map(const maze::Maze &maze) {
  WallMap map{maze.width(), maze.height(), {}};
  map.walls.resize(map.cells());
  for (std::size_t i = 0; i < map.cells(); ++i) {
    for (std::size_t s = 0; s < 4; ++s) map.walls[i][s] = maze.has_wall(maze_cell(map, i), static_cast<maze::Side>(s));
  }
  return map;
}

void validate(const WallSensor &s) {
  for (const double p : {s.wall_given_wall, s.open_given_wall, s.wall_given_open, s.open_given_open}) {
    common::require_input(p >= 0.0 && p <= 1.0, fmt::format("--sensor probabilities must be in [0, 1] (got {:g})", p));
  }
  common::require_input(std::abs(s.wall_given_wall + s.open_given_wall - 1.0) < 1e-9,
                  fmt::format("--sensor P1 + P2 must be 1: P(wall|wall) + P(no wall|wall) (got {:g})",
                              s.wall_given_wall + s.open_given_wall));
  common::require_input(std::abs(s.wall_given_open + s.open_given_open - 1.0) < 1e-9,
                  fmt::format("--sensor P3 + P4 must be 1: P(wall|no wall) + P(no wall|no wall) (got {:g})",
                              s.wall_given_open + s.open_given_open));
}

double likelihood(const WallMap &map, const WallSensor &s, std::size_t index, const Reading &z) {
  double p = 1.0;
  for (std::size_t side = 0; side < 4; ++side) {
    const bool wall = map.walls[index][side];
    p *= wall ? (z[side] ? s.wall_given_wall : s.open_given_wall) : (z[side] ? s.wall_given_open : s.open_given_open);
  }
  return p;
}

std::vector<double> correct(const WallMap &map, const WallSensor &sensor, const std::vector<double> &belief,
                            const Reading &z) {
  std::vector<double> out(belief.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < map.cells(); ++i) sum += out[i] = belief[i] * likelihood(map, sensor, i, z);
  if (sum > 0.0) {
    for (double &b : out) b /= sum;
  }
  return out;
}

std::vector<double> predict(const WallMap &map, const std::vector<double> &belief, std::size_t side, double p_move) {
  std::vector<double> out(belief.size(), 0.0);
  for (std::size_t i = 0; i < map.cells(); ++i) {
    if (map.walls[i][side]) {
      out[i] += belief[i];
    } else {
      out[i] += (1.0 - p_move) * belief[i];
      out[map.neighbour(i, side)] += p_move * belief[i];
    }
  }
  return out;
}

Reading read_walls(const WallMap &map, const WallSensor &s, std::size_t index, common::Rng *rng) {
  Reading z = map.walls[index];
  if (rng == nullptr) return z;
  for (std::size_t side = 0; side < 4; ++side) {
    const double p_wall = map.walls[index][side] ? s.wall_given_wall : s.wall_given_open;
    z[side] = rng->uniform01() < p_wall;
  }
  return z;
}

std::vector<int> Particles::counts(std::size_t cell_count) const {
  std::vector<int> out(cell_count, 0);
  for (const std::size_t c : cells) ++out[c];
  return out;
}

Particles scatter(int n, std::size_t cell_count, common::Rng &rng) {
  Particles p;
  for (int k = 0; k < n; ++k) p.cells.push_back(static_cast<std::size_t>(rng.below(cell_count)));
  return p;
}

void move(Particles &particles, const WallMap &map, std::size_t side, double p_move, common::Rng &rng) {
  for (std::size_t &c : particles.cells) {
    const bool moves = rng.uniform01() < p_move;
    if (moves && !map.walls[c][side]) c = map.neighbour(c, side);
  }
}

void resample(Particles &particles, const WallMap &map, const WallSensor &sensor, const Reading &z,
              common::Rng &rng) {
  const std::size_t n = particles.cells.size();
  std::vector<double> cumulative(n);
  double sum = 0.0;
  for (std::size_t k = 0; k < n; ++k) cumulative[k] = sum += likelihood(map, sensor, particles.cells[k], z);
  if (n == 0 || sum <= 0.0) return;
  const double step = sum / static_cast<double>(n);
  double u = rng.uniform01() * step;
  std::vector<std::size_t> kept;
  kept.reserve(n);
  std::size_t k = 0;
  for (std::size_t m = 0; m < n; ++m, u += step) {
    while (k + 1 < n && cumulative[k] <= u) ++k;
    kept.push_back(particles.cells[k]);
  }
  particles.cells = std::move(kept);
}

WallSensor parse_sensor(const std::string &text) {
  WallSensor s;
  if (text.empty()) return s;
  const std::vector<double> p = parse_number_list(text, "--sensor", 4);
  s = {p[0], p[1], p[2], p[3]};
  validate(s);
  return s;
}

void validate_motion(double p_move) {
  common::require_input(p_move >= 0.0 && p_move <= 1.0, fmt::format("--motion must be in [0, 1] (got {:g})", p_move));
}

void validate_localized(double share) {
  common::require_input(share > 0.5 && share <= 1.0, fmt::format("--localized must be > 0.5 and <= 1 (got {:g})", share));
}

}  // namespace app::loc
