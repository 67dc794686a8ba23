#include <doctest/doctest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "common/random.hpp"
#include "sensing/cone_cells.hpp"

using sensing::ConeReading;

namespace {

using Cells = std::vector<std::pair<int, int>>;

// The lecture's loops as written, with accumulated steps (r += INC, a += omega).
Cells reference(const ConeReading &in) {
  std::set<std::pair<int, int>> cells;
  for (double r = in.d_cells * (1 - in.eps); r <= in.d_cells * (1 + in.eps) + 1e-9; r += 0.25) {
    const double xa = in.x_cells + r * std::cos(in.phi_rad + in.sigma_rad / 2);
    const double ya = in.y_cells + r * std::sin(in.phi_rad + in.sigma_rad / 2);
    const double xb = in.x_cells + r * std::cos(in.phi_rad - in.sigma_rad / 2);
    const double yb = in.y_cells + r * std::sin(in.phi_rad - in.sigma_rad / 2);
    const double omega = in.sigma_rad / std::sqrt((xa - xb) * (xa - xb) + (ya - yb) * (ya - yb)) / 2;
    for (double a = -in.sigma_rad / 2; a <= in.sigma_rad / 2 + 1e-9; a += omega) {
      cells.insert({static_cast<int>(std::floor(in.x_cells + r * std::cos(in.phi_rad + a))),
                    static_cast<int>(std::floor(in.y_cells + r * std::sin(in.phi_rad + a)))});
    }
  }
  return Cells(cells.begin(), cells.end());
}

}  // namespace

TEST_CASE("cone cells: the radius steps by the lecture's INC, a quarter of a cell") {
  CHECK(sensing::kConeRadiusInc == 0.25);
}

TEST_CASE("cone cells: one distance step by hand (eps 0, d 4 cells, sigma 0.4 rad, east)") {
  // chord 2 * 4 sin(0.2) = 1.5894 cells, omega = 0.4 / 1.5894 / 2 = 0.12583 rad: a_k = -0.2,
  // -0.0742, 0.0517, 0.1775 (the next, 0.3033, is past 0.2); points (3.92, -0.79), (3.99,
  // -0.30), (3.99, 0.21), (3.94, 0.71).
  const auto sweep = sensing::cone_cells(ConeReading{0.0, 0.0, 0.0, 4.0, 0.4, 0.0});
  REQUIRE(sweep.steps.size() == 1);
  CHECK(sweep.steps[0].r_cells == 4.0);
  CHECK(sweep.steps[0].omega_rad == doctest::Approx(0.125834).epsilon(1e-5));
  CHECK(sweep.steps[0].angles == 4);
  CHECK(sweep.cells == Cells{{3, -1}, {3, 0}});
}

TEST_CASE("cone cells: the distance steps run from d(1 - eps) to d(1 + eps) by 0.25 cells") {
  // Sonar, d 20: 18.68 ... 21.32, so j = 0 ... 10 (r = 21.18; 21.43 is past the end).
  const auto sweep = sensing::cone_cells(ConeReading{0.0, 0.0, 0.0, 20.0, 0.4, 0.066});
  REQUIRE(sweep.steps.size() == 11);
  CHECK(sweep.steps.front().r_cells == doctest::Approx(18.68));
  CHECK(sweep.steps.back().r_cells == doctest::Approx(21.18));
  // An end that lands on the bound is swept: d 10, eps 0.05: 9.5 ... 10.5 is 5 steps.
  CHECK(sensing::cone_cells(ConeReading{0.0, 0.0, 0.0, 10.0, 0.03, 0.05}).steps.size() == 5);
}

TEST_CASE("cone cells: the same cells as the loops written out, on random ranges and poses") {
  common::Rng rng(4);
  for (int trial = 0; trial < 200; ++trial) {
    const bool sonar = trial % 2 == 1;
    const ConeReading in{rng.uniform(-20.0, 20.0), rng.uniform(-20.0, 20.0), rng.uniform(-3.2, 3.2),
                            rng.uniform(1.0, 60.0), sonar ? 0.4 : 0.03, sonar ? 0.066 : 0.03};
    CAPTURE(trial);
    CHECK(sensing::cone_cells(in).cells == reference(in));
  }
}
