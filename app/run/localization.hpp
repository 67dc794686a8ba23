#pragma once
// The localization lab's arithmetic (the map is known, the pose is not), for `demo
// trilaterate` and `demo localize` (demo_trilaterate.hpp, demo_localize.hpp; the exercise is
// docs/lab-localization.md). python/maze_mapper/localization.py computes the same on NumPy
// arrays.
//
// Task 1's arena: 5 x 5 cells of 1 m, origin at its centre, x east, y north; cells numbered
// row by row from the north-west corner, 1 to 25; a landmark at each corner.
//
// Task 2's maze: a known wall map; its cells numbered the same way (1 at the north-west, row
// by row), a cell's sides N, E, S, W in that order; the robot knows which way is north.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "common/random.hpp"
#include "maze/world/maze.hpp"

namespace app::loc {

struct Landmark {
  const char *name;
  double x_m;
  double y_m;
};
// In the order the distances are given: yellow, red, green, blue.
inline constexpr std::array<Landmark, 4> kArenaLandmarks{
    {{"yellow", -2.5, 2.5}, {"red", 2.5, 2.5}, {"green", -2.5, -2.5}, {"blue", 2.5, -2.5}}};
inline constexpr int kArenaSide = 5;        // cells a side
inline constexpr double kArenaHalf_m = 2.5;  // the arena is [-2.5, 2.5] m both ways

// Subtracting circle 2 from circle 1 and circle 3 from circle 2:
//   A x + B y = C, A = 2(x2 - x1), B = 2(y2 - y1), C = r1^2 - r2^2 - x1^2 + x2^2 - y1^2 + y2^2
//   D x + E y = F, D = 2(x3 - x2), E = 2(y3 - y2), F = r2^2 - r3^2 - x2^2 + x3^2 - y2^2 + y3^2
//   x = (C E - F B) / (E A - B D),  y = (C D - A F) / (B D - A E)
struct Trilateration {
  double a, b, c, d, e, f;
  double x_m, y_m;
};
// Throws common::InputError when the three landmarks lie on one line (E A - B D = 0).
Trilateration trilaterate(const std::array<Landmark, 3> &marks, const std::array<double, 3> &r_m);

// The arena cell (1 to 25) that holds (x, y), a point on a shared edge in the cell to its
// south-east; nothing outside the arena.
std::optional<int> arena_cell(double x_m, double y_m);
// The centre of arena cell n (1 to 25).
std::array<double, 2> arena_cell_centre(int n);

// The normal density N(z; mean, sigma).
double normal_density(double z, double mean, double sigma);
// Each arena cell's score, cell 1 first: the product over the measured landmarks (a distance
// given) of N(distance; the cell centre's distance to the landmark, sigma), normalised.
std::vector<double> cell_scores(const std::array<std::optional<double>, 4> &distances_m, double sigma_m);

// A maze's walls cell by cell, cell 1 (north-west) first, each N, E, S, W.
struct WallMap {
  int width = 0;
  int height = 0;
  std::vector<std::array<bool, 4>> walls;
  std::size_t cells() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
  // The cell beside `index` (0-based) across side s (0 N, 1 E, 2 S, 3 W), which must be open.
  std::size_t neighbour(std::size_t index, std::size_t side) const;
};
WallMap wall_map(const maze::Maze &maze);
// The 0-based index of a maze cell, and back.
std::size_t cell_index(const WallMap &map, maze::Cell c);
maze::Cell maze_cell(const WallMap &map, std::size_t index);

// P(z = wall | wall), P(z = no wall | wall), P(z = wall | no wall), P(z = no wall | no wall).
struct WallSensor {
  double wall_given_wall = 0.8;
  double open_given_wall = 0.2;
  double wall_given_open = 0.4;
  double open_given_open = 0.6;
};
// Throws common::InputError naming --sensor when a value is outside [0, 1] or a pair does
// not add up to 1.
void validate(const WallSensor &sensor);

// The lab's defaults: a move succeeds with kLabMotion, and the robot is localized when one cell
// holds kLabLocalized of the belief.
inline constexpr double kLabMotion = 0.8;
inline constexpr double kLabLocalized = 0.8;

// "P1,P2,P3,P4" (--sensor) as a sensor model, checked (validate()); empty text: the lab's.
WallSensor parse_sensor(const std::string &text);
// Throws common::InputError naming --motion unless p_move is in [0, 1], naming --localized
// unless share is in (0.5, 1].
void validate_motion(double p_move);
void validate_localized(double share);

using Reading = std::array<bool, 4>;  // wall seen N, E, S, W

// P(reading | cell): the product of the four sides' probabilities.
double likelihood(const WallMap &map, const WallSensor &sensor, std::size_t index, const Reading &z);
// Belief times likelihood, normalised (the sum stays 0 when every cell's product is 0).
std::vector<double> correct(const WallMap &map, const WallSensor &sensor, const std::vector<double> &belief,
                            const Reading &z);
// A move towards `side`: from a cell open that way the robot arrives with p_move and stays
// with 1 - p_move; from a cell walled that way it stays.
std::vector<double> predict(const WallMap &map, const std::vector<double> &belief, std::size_t side, double p_move);

// The walls as the sensor reads them: exact without an rng, else each side drawn from the
// sensor model.
Reading read_walls(const WallMap &map, const WallSensor &sensor, std::size_t index, common::Rng *rng);

// A particle filter's particles, each a cell index.
struct Particles {
  std::vector<std::size_t> cells;
  std::vector<int> counts(std::size_t cell_count) const;
};
// n particles in cells drawn uniformly.
Particles scatter(int n, std::size_t cell_count, common::Rng &rng);
// Each particle moves towards `side` with p_move (not through a wall).
void move(Particles &particles, const WallMap &map, std::size_t side, double p_move, common::Rng &rng);
// Low-variance (systematic) resampling by each particle's likelihood of z.
void resample(Particles &particles, const WallMap &map, const WallSensor &sensor, const Reading &z,
              common::Rng &rng);

}  // namespace app::loc
