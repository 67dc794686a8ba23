#include "lattice.hpp"

#include <cmath>
#include <utility>

#include "maze/world/maze.hpp"

namespace maze::lattice {

double common_divisor(double a, double b, double tol) {
  if (a < b) std::swap(a, b);
  while (b > tol) {
    double r = std::fmod(a, b);
    if (r > b - tol) r = 0.0;
    a = b;
    b = r;
  }
  return a;
}

bool on_lattice(double offset, double cell, double tol) {
  return std::abs(offset - cell * std::round(offset / cell)) <= tol;
}

std::optional<double> centres_lattice(const std::vector<double> &offsets, double finest, double span, double tol) {
  double cell = 0.0;
  for (const double offset : offsets) {
    if (offset <= tol) return std::nullopt;
    cell = common_divisor(cell, 2.0 * offset, tol);
  }
  if (cell <= finest || span / cell > kMaxMazeSide + 0.5) return std::nullopt;
  for (const double offset : offsets) {
    const double doubled = 2.0 * offset;
    if (!on_lattice(doubled, cell, 2.0 * tol) || std::llround(doubled / cell) % 2 == 0) return std::nullopt;
  }
  return cell;
}

std::optional<double> shared_lattice(double centres_cell, double walls_cell, double finest, double span,
                                     double tol) {
  for (int m = 1; m <= 2 * kMaxMazeSide + 1; m += 2) {
    const double cell = centres_cell / m;
    if (cell <= finest || span / cell > kMaxMazeSide + 0.5) return std::nullopt;
    if (on_lattice(walls_cell, cell, tol)) return cell;
  }
  return std::nullopt;
}

}  // namespace maze::lattice
