#include <doctest/doctest.h>

#include "app/course/demo_pie.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "mapping/sensor_model.hpp"
#include "plan/metric/wavefront.hpp"
#include "sensing/metric/map.hpp"
#include "sensing/pie_slice.hpp"

using sensing::MetricCell;
using sensing::MetricMap;
using sensing::MetricMarks;

namespace {

// '#' occupied (l > 0), '.' free (l < 0), ' ' untouched; north row first.
std::string picture(const MetricMap &map) {
  std::string out;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) {
      const double l = map.log_odds({i, j});
      out += l > 0 ? '#' : (l < 0 ? '.' : ' ');
    }
    out += '\n';
  }
  return out;
}

}  // namespace

TEST_CASE("room grid: --cells must make square cells, --resolution covers the boundary") {
  const sensing::MetricBoundary room{0.0, 5.0, 0.0, 3.0};
  const auto spec = sensing::metric_grid_from_resolution(room, 0.1);
  CHECK(spec.cells_x == 50);
  CHECK(spec.cells_y == 30);
  const auto coarse = sensing::metric_grid_from_resolution(room, 0.4);  // 12.5 x 7.5: rounded up
  CHECK(coarse.cells_x == 13);
  CHECK(coarse.cells_y == 8);
  CHECK(coarse.boundary.x_end_m == doctest::Approx(5.2));
  CHECK(sensing::metric_grid_from_cells(room, 50, 30).cell_m == doctest::Approx(0.1));
  CHECK_THROWS_WITH_AS(sensing::metric_grid_from_cells(room, 25, 25),
                       doctest::Contains("cells are square (try --cells 25,15 or --resolution 0.2)"),
                       common::InputError);
  auto huge = sensing::metric_grid_from_resolution(room, 0.001);
  CHECK_THROWS_WITH_AS(sensing::validate(huge, 1u << 20), doctest::Contains("would take"), common::InputError);
  CHECK_THROWS_AS(sensing::metric_grid_from_resolution({0, 0, 0, 1}, 0.1), common::InputError);
}

TEST_CASE("room marks: one update a cell a scan, occupied wins, the classroom numbers") {
  mapping::SensorModelOptions o;
  o.base = mapping::LogBase::ten;
  const mapping::SensorModel model(o);
  MetricMap map(sensing::metric_grid_from_cells({0, 3, 0, 3}, 3, 3), model);
  MetricMarks marks(0.99999, 0.3);
  marks.mark(map, MetricCell{1, 1}, sensing::kMetricFree);
  marks.mark(map, MetricCell{1, 1}, sensing::kMetricFree);
  marks.mark(map, MetricCell{2, 2}, sensing::kMetricFree);
  marks.mark(map, MetricCell{2, 2}, sensing::kMetricOccupied);
  marks.mark(map, MetricCell{7, 7}, sensing::kMetricOccupied);  // outside: ignored
  CHECK(marks.apply(map) == 2);
  CHECK(map.log_odds({1, 1}) == doctest::Approx(-0.368).epsilon(0.001));
  CHECK(map.log_odds({2, 2}) == doctest::Approx(5.0).epsilon(0.001));
  CHECK(map.unobserved_at(map.index({0, 0})));
}

TEST_CASE("room lidar: cells before the hit free, the hit occupied, no return frees to max range") {
  const mapping::SensorModel model;
  MetricMap map(sensing::metric_grid_from_resolution({0, 1, 0, 0.5}, 0.1), model);
  // Two beams from (0.05, 0.25): ahead (east) hits at 0.6 m, the other (north) sees nothing
  // and frees to the grid's edge.
  const std::vector<float> ranges{INFINITY, 0.6f};
  sensing::LidarScan scan;
  scan.origin = {0.05, 0.25};
  scan.yaw_rad = 0.0;
  scan.fov_rad = 3.14159265358979323846;  // beam i at pi/2 - i pi/2: north, then east
  scan.min_range_m = 0.0;
  scan.max_range_m = 1.0;
  scan.ranges = ranges;
  MetricMarks marks(model.options().p_occ, model.options().p_free);
  sensing::mark_metric_lidar(map, scan, marks);
  marks.apply(map);
  CHECK(picture(map) ==
        ".         \n"
        ".         \n"
        "......#   \n"
        "          \n"
        "          \n");
}

TEST_CASE("room pie: the same verdicts as the pie-slice update on the same cells") {
  // The IR assignment's Figure 1 (demo pie's set-up), on a room grid whose corners are on
  // multiples of 0.1 m.
  const sensing::PieSliceOptions figure = app::course::figure_1_options();
  mapping::SensorModelOptions so;
  so.prior = 0.5;
  const mapping::SensorModel model(so);
  MetricMap map(sensing::metric_grid_from_resolution({0, 4, 0, 4}, 0.1), model);
  std::vector<sensing::RangeReading> readings;
  for (std::size_t n = 0; n < figure.readings_m.size(); ++n) {
    sensing::RangeReading r;
    r.origin = {figure.x_m, figure.y_m};
    r.angle_rad = (figure.heading_deg + figure.mounts_deg[n]) * 3.14159265358979323846 / 180.0;
    r.range_m = figure.readings_m[n];
    r.max_range_m = figure.max_range_m;
    readings.push_back(r);
  }
  sensing::RangeModelOptions ro;
  ro.pie_half_angle_rad = figure.half_angle_deg * 3.14159265358979323846 / 180.0;
  ro.pie_contact_m = figure.contact_m;
  MetricMarks marks(sensing::kPieOccupiedP, sensing::kPieFreeP);
  sensing::mark_metric_pie(map, ro, readings, marks);
  marks.apply(map);
  int compared = 0;
  for (const sensing::PieSliceCell &c : sensing::pie_slice_update(figure)) {
    // Occupied where some sensor said contact; free where all said clear (one update a scan).
    const double l = map.log_odds({c.i, c.j});
    if (c.occupied > 0) {
      CHECK(l == doctest::Approx(std::log(0.7 / 0.3)));
    } else {
      CHECK(l == doctest::Approx(std::log(0.4 / 0.6)));
    }
    ++compared;
  }
  CHECK(compared > 100);
}

// The IR's arc, 9.7 ... 10.3 cells from the sensor at 0.5 cells, lies in cell 10; the free
// sweep ends at 9.7 - 0.25 cells, in cell 9.
TEST_CASE("room cone: the arc occupied, the cone inside free; a sonar's nothing-seen marks nothing") {
  const mapping::SensorModel model;
  MetricMap map(sensing::metric_grid_from_resolution({0, 2, 0, 0.3}, 0.1), model);
  sensing::RangeReading ir;
  ir.origin = {0.05, 0.15};
  ir.angle_rad = 0.0;
  ir.range_m = 1.0;
  ir.max_range_m = 1.5;
  ir.aperture_rad = 0.03;
  ir.range_error = 0.03;
  MetricMarks marks(model.options().p_occ, model.options().p_free);
  sensing::mark_metric_cone(map, {}, std::span(&ir, 1), marks);
  marks.apply(map);
  CHECK(picture(map) ==
        "                    \n"
        "..........#         \n"
        "                    \n");
  MetricMap other(map.spec(), model);
  sensing::RangeReading sonar = ir;
  sonar.range_m = 1.5;
  sonar.echo_can_be_lost = true;
  sensing::mark_metric_cone(other, {}, std::span(&sonar, 1), marks);
  CHECK(marks.empty());
}

TEST_CASE("room wavefront: obstacles 1, goal 2, the wave 4-neighbour, dilation, the path down it") {
  const plan::FlatGrid g{5, 3};
  std::vector<bool> obstacles(g.size(), false);
  obstacles[1 * 5 + 2] = true;  // the middle cell
  const auto grown = plan::dilated(g, obstacles, 1);
  int blocked = 0;
  for (const bool b : grown) blocked += b ? 1 : 0;
  CHECK(blocked == 9);  // the 3 x 3 square around it
  const auto wave = plan::wave_from(g, obstacles, 4);  // goal at (4, 0)
  std::string rows;
  for (int j = 2; j >= 0; --j) {
    for (int i = 0; i < 5; ++i) rows += fmt::format("{:>3}", wave[static_cast<std::size_t>(j * 5 + i)]);
    rows += "\n";
  }
  CHECK(rows ==
        "  8  7  6  5  4\n"
        "  7  6  1  4  3\n"
        "  6  5  4  3  2\n");
  const auto path = plan::descend(g, wave, 10);  // from (0, 2)
  REQUIRE(path);
  CHECK(path->size() == 7);
  CHECK(path->back() == 4);
  CHECK_FALSE(plan::descend(g, plan::wave_from(g, grown, 4), 10));  // walled off by the dilation
}
