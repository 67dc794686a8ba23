#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "common/random.hpp"
#include "app/course/demo_1d.hpp"
#include "validation_error.hpp"

using app::course::CellUpdate;
using app::course::Demo1dCell;
using app::course::Demo1dOptions;

namespace {

const Demo1dCell &cell_at(const std::vector<Demo1dCell> &cells, double position_cm) {
  const auto it = std::find_if(cells.begin(), cells.end(),
                               [&](const Demo1dCell &c) { return c.position_cm == position_cm; });
  REQUIRE(it != cells.end());
  return *it;
}

}  // namespace

TEST_CASE("demo 1d: classify follows x < z free, z <= x <= z + behind occupied") {
  CHECK(app::course::classify(100, 101, 20) == CellUpdate::free);
  CHECK(app::course::classify(101, 101, 20) == CellUpdate::occupied);  // at the hit: occupied
  CHECK(app::course::classify(121, 101, 20) == CellUpdate::occupied);  // 20 cm behind: still occupied
  CHECK(app::course::classify(121.5, 101, 20) == CellUpdate::none);
  CHECK(app::course::classify(0, 0, 0) == CellUpdate::occupied);
  CHECK(app::course::classify(10, 0, 0) == CellUpdate::none);
}

TEST_CASE("demo 1d: cell positions 0, r, 2r, ... up to the length") {
  Demo1dOptions o;
  std::vector<double> x = app::course::cell_positions_cm(o);
  REQUIRE(x.size() == 21);
  CHECK(x.front() == 0.0);
  CHECK(x[11] == 110.0);
  CHECK(x.back() == 200.0);
  o.length_cm = 205;
  CHECK(app::course::cell_positions_cm(o).size() == 21);
  o.length_cm = 0;
  CHECK(app::course::cell_positions_cm(o).size() == 1);
  o.length_cm = 0.3;
  o.resolution_cm = 0.1;  // 0.3 / 0.1 = 2.9999999999999996 in doubles; still 4 cells
  CHECK(app::course::cell_positions_cm(o).size() == 4);
}

// The textbook exercise by hand. l(0.3) = ln(3/7) = -0.847298, l(0.6) = ln(3/2) = 0.405465,
// l(0.5) = 0. Measurements 101, 82, 91, 112, 99, 151, 96, 85, 99, 105.
//   cell 110: occupied by 101, 91, 99, 96, 99, 105 (z <= 110 <= z + 20), free by 112, 151
//             l = 6 * 0.405465 - 2 * 0.847298 = 0.738194, p = 1 / (1 + e^-0.738194) = 0.6766
//   cell 100: occupied by 82, 91, 99, 96, 85, 99, free by 101, 112, 151, 105
//             l = 6 * 0.405465 - 4 * 0.847298 = -0.956402
//   cell 120: occupied by 101, 112, 105, free by 151:  l = 3 * 0.405465 - 0.847298 = 0.369097
//   cell 130: occupied by 112, free by 151:            l = 0.405465 - 0.847298 = -0.441833
//   cell   0: free by all ten:                         l = -8.472979
//   cell 160: occupied by 151 only:                    l = 0.405465
//   cell 180: nearer than no measurement and more than 20 cm behind all: l = 0, p = 0.5
TEST_CASE("demo 1d: the default exercise, checked by hand") {
  const Demo1dOptions o;
  const std::vector<Demo1dCell> cells = app::course::integrate(o, o.measurements_cm);
  REQUIRE(cells.size() == 21);

  const Demo1dCell &c110 = cell_at(cells, 110);
  CHECK(c110.free_updates == 2);
  CHECK(c110.occupied_updates == 6);
  CHECK(c110.log_odds == doctest::Approx(0.738194).epsilon(1e-6));
  CHECK(c110.belief == doctest::Approx(0.6766).epsilon(1e-4));
  CHECK(c110.belief == doctest::Approx(0.68).epsilon(0.01));  // the exercise's "about 0.68"

  CHECK(cell_at(cells, 100).log_odds == doctest::Approx(-0.956402).epsilon(1e-6));
  CHECK(cell_at(cells, 120).log_odds == doctest::Approx(0.369097).epsilon(1e-6));
  CHECK(cell_at(cells, 130).log_odds == doctest::Approx(-0.441833).epsilon(1e-6));
  CHECK(cell_at(cells, 0).log_odds == doctest::Approx(-8.472979).epsilon(1e-6));
  CHECK(cell_at(cells, 160).log_odds == doctest::Approx(0.405465).epsilon(1e-6));
  CHECK(cell_at(cells, 180).log_odds == 0.0);
  CHECK(cell_at(cells, 180).belief == 0.5);
}

TEST_CASE("demo 1d: free and occupied counts of every cell (the exercise as a table)") {
  //                          0  10  20  30  40  50  60  70  80  90 100 110 120 130 140 150 160 170 180 190 200
  const std::vector<int> free{10, 10, 10, 10, 10, 10, 10, 10, 10, 8, 4, 2, 1, 1, 1, 1, 0, 0, 0, 0, 0};
  const std::vector<int> occ{0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 6, 6, 3, 1, 0, 0, 1, 1, 0, 0, 0};
  const Demo1dOptions o;
  const std::vector<Demo1dCell> cells = app::course::integrate(o, o.measurements_cm);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    CAPTURE(cells[i].position_cm);
    CHECK(cells[i].free_updates == free[i]);
    CHECK(cells[i].occupied_updates == occ[i]);
    CHECK(cells[i].log_odds == doctest::Approx(free[i] * std::log(3.0 / 7.0) + occ[i] * std::log(1.5)));
  }
}

TEST_CASE("demo 1d: base 10 gives the same beliefs and log-odds divided by ln 10") {
  Demo1dOptions o;
  o.model.base = mapping::LogBase::ten;
  const std::vector<Demo1dCell> ten = app::course::integrate(o, o.measurements_cm);
  const std::vector<Demo1dCell> e = app::course::integrate(Demo1dOptions{}, o.measurements_cm);
  // cell 110: 6 * log10(1.5) - 2 * log10(7/3) = 6 * 0.176091 - 2 * 0.367977 = 0.320593
  CHECK(cell_at(ten, 110).log_odds == doctest::Approx(0.320593).epsilon(1e-6));
  for (std::size_t i = 0; i < ten.size(); ++i) {
    CHECK(ten[i].belief == doctest::Approx(e[i].belief).epsilon(1e-12));
    CHECK(ten[i].log_odds == doctest::Approx(e[i].log_odds / std::log(10.0)).epsilon(1e-12));
  }
}

TEST_CASE("demo 1d: a measurement beyond the length frees every cell") {
  Demo1dOptions o;
  o.measurements_cm = {250};
  for (const Demo1dCell &c : app::course::integrate(o, o.measurements_cm)) {
    CHECK(c.free_updates == 1);
    CHECK(c.occupied_updates == 0);
  }
}

TEST_CASE("demo 1d: order independence over 1,000 random permutations") {
  const Demo1dOptions o;
  const std::vector<Demo1dCell> original = app::course::integrate(o, o.measurements_cm);
  common::Rng rng(2024);
  std::vector<double> order = o.measurements_cm;
  for (int trial = 0; trial < 1000; ++trial) {
    rng.shuffle(std::span<double>(order));
    const std::vector<Demo1dCell> permuted = app::course::integrate(o, order);
    REQUIRE(permuted.size() == original.size());
    for (std::size_t i = 0; i < original.size(); ++i) {
      CHECK(permuted[i].free_updates == original[i].free_updates);
      CHECK(permuted[i].occupied_updates == original[i].occupied_updates);
    }
    CHECK(app::course::max_log_odds_difference(original, permuted) <= app::course::kOrderTolerance);
  }
}

TEST_CASE("demo 1d: shuffled is a seeded permutation") {
  const std::vector<double> &given = app::course::kDemo1dMeasurementsCm;
  const std::vector<double> a = app::course::shuffled(given, 7);
  CHECK(a == app::course::shuffled(given, 7));
  CHECK(a != app::course::shuffled(given, 8));
  std::vector<double> sorted_a = a;
  std::vector<double> sorted_given = given;
  std::sort(sorted_a.begin(), sorted_a.end());
  std::sort(sorted_given.begin(), sorted_given.end());
  CHECK(sorted_a == sorted_given);
}

TEST_CASE("demo 1d: validation errors name the option and its value") {
  Demo1dOptions o;
  CHECK(validation_error(o) == "");
  o = {};
  o.resolution_cm = 0;
  CHECK(validation_error(o) == "error: --resolution must be a positive number of cm (got 0)");
  o = {};
  o.resolution_cm = NAN;
  CHECK(validation_error(o) == "error: --resolution must be a positive number of cm (got nan)");
  o = {};
  o.length_cm = -5;
  CHECK(validation_error(o) == "error: --length must be a finite number of cm >= 0 (got -5)");
  o = {};
  o.length_cm = INFINITY;
  CHECK(validation_error(o) == "error: --length must be a finite number of cm >= 0 (got inf)");
  o = {};
  o.behind_cm = -1;
  CHECK(validation_error(o) == "error: --behind must be a finite number of cm >= 0 (got -1)");
  o = {};
  o.length_cm = 1e6;
  o.resolution_cm = 1;
  CHECK(validation_error(o) ==
        "error: --length 1000000 with --resolution 1 gives 1000001 cells (at most 10001)");
  o = {};
  o.measurements_cm = {};
  CHECK(validation_error(o) == "error: --measurements must list at least one distance in cm");
  o = {};
  o.measurements_cm = {101, NAN};
  CHECK(validation_error(o) == "error: --measurements item 2 must be a finite number of cm >= 0 (got nan)");
  o = {};
  o.measurements_cm = {-3};
  CHECK(validation_error(o) == "error: --measurements item 1 must be a finite number of cm >= 0 (got -3)");
  o = {};
  o.measurements_cm = {0, 1000};  // at the robot, and beyond the length: both usable
  CHECK(validation_error(o) == "");
  o = {};
  o.model.p_occ = 0.4;
  CHECK(validation_error(o) == "error: --p-occ must be greater than --prior (got 0.4 <= 0.5)");
}
