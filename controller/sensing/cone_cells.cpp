// The cells of a range sensor's cone (sensing/cone_cells.hpp).

#include "sensing/cone_cells.hpp"

#include <algorithm>
#include <cmath>

namespace sensing {
namespace {

constexpr double kRounding = 1e-9;

ConeArc arc_at(const ConeReading &in, double r) {
  ConeArc s;
  s.r_cells = r;
  s.xa = in.x_cells + r * std::cos(in.phi_rad + in.sigma_rad / 2);
  s.ya = in.y_cells + r * std::sin(in.phi_rad + in.sigma_rad / 2);
  s.xb = in.x_cells + r * std::cos(in.phi_rad - in.sigma_rad / 2);
  s.yb = in.y_cells + r * std::sin(in.phi_rad - in.sigma_rad / 2);
  s.omega_rad = (in.sigma_rad / std::hypot(s.xa - s.xb, s.ya - s.yb)) / 2;
  return s;
}

}  // namespace

ConeCells cone_cells(const ConeReading &in) {
  return cone_cells_between(in, in.d_cells * (1 - in.eps), in.d_cells * (1 + in.eps));
}

ConeCells cone_cells_between(const ConeReading &in, double start, double end) {
  ConeCells sweep;
  for (int j = 0; start + j * kConeRadiusInc <= end + kRounding; ++j) {
    ConeArc s = arc_at(in, start + j * kConeRadiusInc);
    for (int k = 0; -in.sigma_rad / 2 + k * s.omega_rad <= in.sigma_rad / 2 + kRounding; ++k) {
      const double a = -in.sigma_rad / 2 + k * s.omega_rad;
      const double obj_x = in.x_cells + s.r_cells * std::cos(in.phi_rad + a);
      const double obj_y = in.y_cells + s.r_cells * std::sin(in.phi_rad + a);
      sweep.cells.emplace_back(static_cast<int>(std::floor(obj_x)), static_cast<int>(std::floor(obj_y)));
      ++s.angles;
    }
    sweep.steps.push_back(s);
  }
  std::sort(sweep.cells.begin(), sweep.cells.end());
  sweep.cells.erase(std::unique(sweep.cells.begin(), sweep.cells.end()), sweep.cells.end());
  return sweep;
}

}  // namespace sensing
