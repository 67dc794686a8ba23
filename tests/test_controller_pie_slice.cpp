#include <doctest/doctest.h>

#include "app/course/demo_pie.hpp"

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/random.hpp"
#include "sensing/pie_slice.hpp"

using sensing::PieSliceCell;
using sensing::PieSliceOptions;

namespace {

// The cells as a matrix over their bounding box, north row first; `.` where not updated.
std::string matrix(const std::vector<PieSliceCell> &cells) {
  std::map<std::pair<int, int>, double> by_cell;
  int i0 = 1 << 20, i1 = -(1 << 20), j0 = 1 << 20, j1 = -(1 << 20);
  for (const auto &c : cells) {
    by_cell[{c.i, c.j}] = c.log_odds;
    i0 = std::min(i0, c.i), i1 = std::max(i1, c.i), j0 = std::min(j0, c.j), j1 = std::max(j1, c.j);
  }
  std::string out;
  for (int j = j1; j >= j0; --j) {
    for (int i = i0; i <= i1; ++i) {
      const auto it = by_cell.find({i, j});
      if (i != i0) out += ' ';
      out += it == by_cell.end() ? std::string("  .  ") : fmt::format("{:+.2f}", it->second);
    }
    out += "\n";
  }
  return out;
}

// One sensor at the origin facing east; binary-exact numbers so no point sits a rounding
// error from a slice's edge: cells of 0.125 m, reading 0.375 m, alpha 0.125 m; beta 10 deg.
PieSliceOptions one_sensor_east(double reading_m) {
  PieSliceOptions o;
  o.x_m = 0.0;
  o.y_m = 0.0;
  o.heading_deg = 0.0;
  o.mounts_deg = {0.0};
  o.readings_m = {reading_m};
  o.half_angle_deg = 10.0;
  o.resolution_m = 0.125;
  o.contact_m = 0.125;
  o.max_range_m = 1.5;
  return o;
}

// Six sensors 30 deg apart over the front of a robot facing south (the assignment's Figure 1).
PieSliceOptions six_sensors_south() { return app::course::figure_1_options(); }

// An independent reading of the course's rule: the angle test by a dot product, every cell
// of a fixed box visited, the verdict spelt out per point.
std::map<std::pair<int, int>, double> reference(const PieSliceOptions &o) {
  std::map<std::pair<int, int>, double> out;
  const double r = o.resolution_m;
  const double cos_beta = std::cos(o.half_angle_deg * std::acos(-1.0) / 180.0);
  for (std::size_t n = 0; n < o.readings_m.size(); ++n) {
    const double a = (o.heading_deg + o.mounts_deg[n]) * std::acos(-1.0) / 180.0;
    const bool contact = o.readings_m[n] < o.max_range_m;
    const double clear_end = contact ? o.readings_m[n] : o.max_range_m;
    const double contact_end = clear_end + (contact ? o.contact_m : 0.0);
    for (int j = -60; j <= 60; ++j) {
      for (int i = -60; i <= 60; ++i) {
        bool in_clear = false, in_contact_only = false;
        for (const auto &[px, py] : {std::pair{i * r, j * r}, {(i + 1) * r, j * r}, {i * r, (j + 1) * r},
                                    {(i + 1) * r, (j + 1) * r}, {(i + 0.5) * r, (j + 0.5) * r}}) {
          const double ex = px - o.x_m, ey = py - o.y_m;
          const double dist = std::sqrt(ex * ex + ey * ey);
          const bool in_angle = dist == 0.0 || ex * std::cos(a) + ey * std::sin(a) >= dist * cos_beta;
          if (in_angle && dist <= clear_end) in_clear = true;
          if (in_angle && dist > clear_end && dist <= contact_end && contact) in_contact_only = true;
        }
        if (in_contact_only) out[{i, j}] += std::log(0.7 / 0.3);
        else if (in_clear) out[{i, j}] += std::log(0.4 / 0.6);
      }
    }
  }
  return out;
}

}  // namespace

TEST_CASE("pie slice: a contact clears its slice to the reading, then alpha occupied beyond it") {
  // Columns x from -0.125 to 0.625 m, rows y from 0.125 down to -0.125 m; the sensor at the
  // corner shared by the four cells around the origin.
  CHECK(matrix(sensing::pie_slice_update(one_sensor_east(0.375))) ==
        "-0.41 -0.41 -0.41 -0.41 +0.85 +0.85\n"
        "-0.41 -0.41 -0.41 -0.41 +0.85 +0.85\n");
}

TEST_CASE("pie slice: a reading at max range is clear: its slice clears to max, nothing occupied") {
  PieSliceOptions o = one_sensor_east(1.5);
  o.max_range_m = 0.375;
  CHECK(matrix(sensing::pie_slice_update(o)) ==
        "-0.41 -0.41 -0.41 -0.41 -0.41\n"
        "-0.41 -0.41 -0.41 -0.41 -0.41\n");
  const auto slices = sensing::pie_slices(o);
  REQUIRE(slices.size() == 1);
  CHECK(!slices[0].contact);
  CHECK(slices[0].clear_m == 0.375);
}

TEST_CASE("pie slice: each sensor's slice points heading + mount, a contact ends alpha past its reading") {
  const auto slices = sensing::pie_slices(six_sensors_south());
  std::string table;
  for (const auto &s : slices) {
    table += fmt::format("{:.0f} {:.2f} {:.2f} {:.2f} {}\n", s.heading_deg, s.reading_m, s.clear_m,
                         s.contact ? s.contact_m : 0.0, s.contact ? "contact" : "clear");
  }
  CHECK(table ==
        "345 1.00 1.00 1.10 contact\n"
        "315 1.50 1.50 0.00 clear\n"
        "285 1.50 1.50 0.00 clear\n"
        "255 0.80 0.80 0.90 contact\n"
        "225 1.20 1.20 1.30 contact\n"
        "195 1.50 1.50 0.00 clear\n");
}

TEST_CASE("pie slice: the same cells and sums as an independent reference, on random readings") {
  common::Rng rng(17);
  for (int trial = 0; trial < 60; ++trial) {
    PieSliceOptions o;
    o.resolution_m = 0.1;
    o.x_m = rng.uniform(-1.0, 1.0);
    o.y_m = rng.uniform(-1.0, 1.0);
    o.heading_deg = rng.uniform(0.0, 360.0);
    o.half_angle_deg = rng.uniform(3.0, 40.0);
    o.contact_m = rng.uniform(0.05, 0.3);
    o.max_range_m = 1.5;
    o.mounts_deg.clear();
    o.readings_m.clear();
    const int sensors = 1 + static_cast<int>(rng.uniform(0.0, 6.0));
    for (int n = 0; n < sensors; ++n) {
      o.mounts_deg.push_back(rng.uniform(-180.0, 180.0));
      o.readings_m.push_back(rng.uniform(0.0, 2.0));
    }
    CAPTURE(trial);
    const auto expected = reference(o);
    const auto cells = sensing::pie_slice_update(o);
    REQUIRE(cells.size() == expected.size());
    for (const auto &c : cells) {
      const auto it = expected.find({c.i, c.j});
      REQUIRE(it != expected.end());
      CHECK(c.log_odds == doctest::Approx(it->second).epsilon(1e-12));
    }
  }
}

TEST_CASE("pie slice: bad set-ups are refused with what was wrong") {
  PieSliceOptions o = six_sensors_south();
  o.readings_m = {1.0, 1.0};
  CHECK_THROWS_WITH_AS(sensing::validate(o), "--readings has 2 values but --mounts has 6", common::InputError);
  o = six_sensors_south();
  o.half_angle_deg = 90.0;
  CHECK_THROWS_WITH_AS(sensing::validate(o), "--beta must be in (0, 90) deg (got 90)", common::InputError);
  o = six_sensors_south();
  o.readings_m[2] = -1.0;
  CHECK_THROWS_WITH_AS(sensing::validate(o), "--readings item 3 must be a finite number >= 0 m (got -1)", common::InputError);
  o = six_sensors_south();
  o.resolution_m = 0.0001;
  CHECK_THROWS_WITH_AS(sensing::validate(o), "the slices would span more than 2000 cells a side: raise --resolution",
                       common::InputError);
}
