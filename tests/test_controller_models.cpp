#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "common/random.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "mapping/traversal.hpp"
#include "render/ascii_map.hpp"
#include "sensing/cell_model.hpp"
#include "sensing/setups.hpp"
#include "synthetic_world.hpp"
#include "test_values.hpp"

using mapping::Cell;
using mapping::GridGeometry;
using sensing::ModelOptions;
using sensing::ModelKind;
using mapping::OccupancyGrid;
using mapping::SubCell;

namespace {

// 3 x 3 cells of 1 m; only the centre cell's north and west sides are walls.
const char *const kNorthWest =
    "o   o   o   o\n"
    "             \n"
    "o   o---o   o\n"
    "    |        \n"
    "o   o   o   o\n"
    "             \n"
    "o   o   o   o";

GridGeometry geometry(int k, int w = 3, int h = 3) {
  GridGeometry g;
  g.width_cells = w;
  g.height_cells = h;
  g.subcells = k;
  g.cell_size_m = 1.0;
  return g;
}

// One noiseless scan from the centre of cell (1, 1) of kNorthWest, then the cell's matrix.
std::string one_scan(ModelKind kind, int k, const mapping::SensorModelOptions &sensor = {},
                     double yaw = kPi / 2, int scans = 1, Cell shown = {1, 1}) {
  const testing_world::TextMaze maze(kNorthWest);
  const auto boxes = testing_world::wall_boxes(maze, 1.0, 0.012);
  const mapping::Point origin{1.5, 1.5};
  const auto ranges = testing_world::range_image(boxes, origin, yaw, 360, 2 * kPi, 0.05, 12.0);
  const mapping::SensorModel model(sensor);
  OccupancyGrid grid(geometry(k), static_cast<float>(model.prior_log_odds()));
  mapping::ScanUpdate update;
  ModelOptions options;
  options.kind = kind;
  for (int n = 0; n < scans; ++n) {
    sensing::integrate_scan(options, grid, testing_world::hambot_scan(origin, yaw, ranges),
                            Cell{1, 1}, model, update);
  }
  return render::format_cell_matrix(grid, shown);
}

}  // namespace

TEST_CASE("cell model, K = 3: walls N and W, open E and S, one scan with the defaults") {
  CHECK(one_scan(ModelKind::cell, 3) ==
        "+0.41 +0.41 +0.41\n"
        "+0.41 -0.85 -0.85\n"
        "+0.41 -0.85 +0.00\n");
}

TEST_CASE("cell model, K = 5: walled bands whole, the path to each band free") {
  CHECK(one_scan(ModelKind::cell, 5) ==
        "+0.41 +0.41 +0.41 +0.41 +0.41\n"
        "+0.41 +0.00 -0.85 +0.00 +0.00\n"
        "+0.41 -0.85 -0.85 -0.85 -0.85\n"
        "+0.41 +0.00 -0.85 +0.00 +0.00\n"
        "+0.41 +0.00 -0.85 +0.00 +0.00\n");
}

TEST_CASE("cell model, K = 7: a wall is the whole band at every K; openings only their path") {
  CHECK(one_scan(ModelKind::cell, 7) ==
        "+0.41 +0.41 +0.41 +0.41 +0.41 +0.41 +0.41\n"
        "+0.41 +0.00 +0.00 -0.85 +0.00 +0.00 +0.00\n"
        "+0.41 +0.00 +0.00 -0.85 +0.00 +0.00 +0.00\n"
        "+0.41 -0.85 -0.85 -0.85 -0.85 -0.85 -0.85\n"
        "+0.41 +0.00 +0.00 -0.85 +0.00 +0.00 +0.00\n"
        "+0.41 +0.00 +0.00 -0.85 +0.00 +0.00 +0.00\n"
        "+0.41 +0.00 +0.00 -0.85 +0.00 +0.00 +0.00\n");
}

TEST_CASE("cell model: the world-frame beams are picked whatever the robot's yaw") {
  for (const double yaw : {0.0, kPi / 2, kPi, -kPi / 2, 0.3, -2.0}) {
    CAPTURE(yaw);
    CHECK(one_scan(ModelKind::cell, 3, {}, yaw) ==
          "+0.41 +0.41 +0.41\n"
          "+0.41 -0.85 -0.85\n"
          "+0.41 -0.85 +0.00\n");
  }
}

TEST_CASE("cell model: nothing outside the robot's cell is updated") {
  CHECK(one_scan(ModelKind::cell, 3, {}, kPi / 2, 1, Cell{1, 2}) ==
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00\n");
}

TEST_CASE("ray model, K = 3 and 5: every sub-cell of the cell crossed; walls where beams end") {
  CHECK(one_scan(ModelKind::ray, 3) ==
        "+0.41 +0.41 +0.41\n"
        "+0.41 -0.85 -0.85\n"
        "+0.41 -0.85 -0.85\n");
  CHECK(one_scan(ModelKind::ray, 5) ==
        "+0.41 +0.41 +0.41 +0.41 +0.41\n"
        "+0.41 -0.85 -0.85 -0.85 -0.85\n"
        "+0.41 -0.85 -0.85 -0.85 -0.85\n"
        "+0.41 -0.85 -0.85 -0.85 -0.85\n"
        "+0.41 -0.85 -0.85 -0.85 -0.85\n");
  // Beyond the walls nothing; through the openings, free up to the grid's edge.
  CHECK(one_scan(ModelKind::ray, 3, {}, kPi / 2, 1, Cell{1, 2}) ==
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00\n");
  CHECK(one_scan(ModelKind::ray, 3, {}, kPi / 2, 1, Cell{2, 0}) ==
        "-0.85 -0.85 -0.85\n"
        "-0.85 -0.85 -0.85\n"
        "-0.85 -0.85 -0.85\n");
}

TEST_CASE("models honour the sensor options: base 10, other p's, a prior, clamping") {
  mapping::SensorModelOptions ten;
  ten.base = mapping::LogBase::ten;
  CHECK(one_scan(ModelKind::cell, 3, ten) ==
        "+0.18 +0.18 +0.18\n"
        "+0.18 -0.37 -0.37\n"
        "+0.18 -0.37 +0.00\n");

  mapping::SensorModelOptions sharp;
  sharp.p_free = 0.2;
  sharp.p_occ = 0.9;
  CHECK(one_scan(ModelKind::ray, 3, sharp) ==
        "+2.20 +2.20 +2.20\n"
        "+2.20 -1.39 -1.39\n"
        "+2.20 -1.39 -1.39\n");

  // Prior 0.4: a sub-cell starts at l(0.4) = -0.41; one update gives l(p) exactly, the
  // second adds l(p) - l(prior) again (the classroom rule).
  mapping::SensorModelOptions prior;
  prior.prior = 0.4;
  CHECK(one_scan(ModelKind::cell, 3, prior) ==
        "+0.41 +0.41 +0.41\n"
        "+0.41 -0.85 -0.85\n"
        "+0.41 -0.85 -0.41\n");
  CHECK(one_scan(ModelKind::cell, 3, prior, kPi / 2, 2) ==
        "+1.22 +1.22 +1.22\n"
        "+1.22 -1.29 -1.29\n"
        "+1.22 -1.29 -0.41\n");

  // Many scans: without a clamp the values keep growing; with -2 / 3.5 they stop there.
  CHECK(one_scan(ModelKind::cell, 3, {}, kPi / 2, 13) ==
        " +5.27  +5.27  +5.27\n"
        " +5.27 -11.01 -11.01\n"
        " +5.27 -11.01  +0.00\n");
  mapping::SensorModelOptions clamped;
  clamped.clamp = mapping::Clamp{-2.0, 3.5};
  CHECK(one_scan(ModelKind::ray, 3, clamped, kPi / 2, 10) ==
        "+3.50 +3.50 +3.50\n"
        "+3.50 -2.00 -2.00\n"
        "+3.50 -2.00 -2.00\n");
}

namespace {

// A scan of beams that all look east (a field of view of a nanoradian) from (0.5, 0.5).
sensing::LidarScan east_beams(const std::vector<float> &ranges) {
  sensing::LidarScan s;
  s.origin = {0.5, 0.5};
  s.yaw_rad = 0.0;
  s.fov_rad = 1e-9;
  s.min_range_m = 0.05;
  s.max_range_m = 12.0;
  s.ranges = ranges;
  return s;
}

// Row of sub-cells y = 1 (through the robot) of a 3 x 1 grid, K = 3: values as text.
std::string east_row(const std::vector<float> &ranges, const ModelOptions &options) {
  const mapping::SensorModel model;
  OccupancyGrid grid(geometry(3, 3, 1), 0.0f);
  mapping::ScanUpdate update;
  sensing::integrate_scan(options, grid, east_beams(ranges), Cell{0, 0}, model, update);
  std::string out;
  for (int x = 0; x < 9; ++x) {
    const float v = grid.at(SubCell{x, 1});
    out += v > 0.0f ? 'X' : (v < 0.0f ? '.' : '?');
  }
  return out;
}

}  // namespace

TEST_CASE("ray model: occupied wins within a scan; each sub-cell updated once") {
  ModelOptions ray;
  ray.kind = ModelKind::ray;
  // Beam 0 ends at x = 1.2 (sub-cell 3); beam 1 passes through it and ends at x = 1.9 (5).
  const std::vector<float> ranges{0.7f, 1.4f, 1.4f};
  CHECK(east_row(ranges, ray) == "?..X.X???");  // sub-cell 0 is behind the robot
  const mapping::SensorModel model;
  OccupancyGrid grid(geometry(3, 3, 1), 0.0f);
  mapping::ScanUpdate update;
  CHECK(sensing::integrate_scan(ray, grid, east_beams(ranges), Cell{0, 0}, model, update) == 5);
  CHECK(grid.at(SubCell{3, 1}) == doctest::Approx(0.405465));
  CHECK(grid.at(SubCell{4, 1}) == doctest::Approx(-0.847298));
  CHECK(grid.at(SubCell{1, 1}) == doctest::Approx(-0.847298));
  CHECK(grid.at(SubCell{0, 1}) == 0.0f);
}

TEST_CASE("ray model: hit depth, no-return beams, invalid readings") {
  ModelOptions ray;
  ray.kind = ModelKind::ray;
  CHECK(east_row({0.7f}, ray) == "?..X?????");
  ray.hit_depth = 2;
  CHECK(east_row({0.7f}, ray) == "?..XXX???");
  ray.hit_depth = 0;
  // No return: free to max range, or to the grid's edge.
  const float inf = std::numeric_limits<float>::infinity();
  CHECK(east_row({inf}, ray) == "?........");
  CHECK(east_row({13.0f}, ray) == "?........");  // beyond max range counts as no return
  ray.ignore_no_return = true;
  CHECK(east_row({inf}, ray) == "?????????");
  // NaN, negative and below-min readings are ignored, never stored.
  CHECK(east_row({std::numeric_limits<float>::quiet_NaN(), -1.0f, 0.01f}, ray) == "?????????");
}

TEST_CASE("model options: names and validation messages") {
  CHECK(sensing::parse_model("cell") == ModelKind::cell);
  CHECK(sensing::parse_model("ray") == ModelKind::ray);
  CHECK(sensing::to_string(ModelKind::ray) == "ray");
  try {
    sensing::parse_model("sonar");
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() ==
          "error: unknown --model 'sonar' (choose cell, ray, bump, depth, pie or cone)");
  }
  ModelOptions o;
  o.hit_depth = 9;
  try {
    sensing::validate(o);
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == "error: --hit-depth must be between 0 and 8 (got 9)");
  }
}

// ---- Amanatides-Woo traversal ----

namespace {

// 2 x 2 cells of 3 m with K = 3: 6 x 6 sub-cells of 1 m, so sub-cell indices are floor(x), floor(y).
GridGeometry unit_subcells() {
  GridGeometry g;
  g.width_cells = 2;
  g.height_cells = 2;
  g.subcells = 3;
  g.cell_size_m = 3.0;
  return g;
}

std::vector<SubCell> walk(mapping::Point a, mapping::Point b) {
  return mapping::subcells_on_segment(unit_subcells(), a, b);
}

using V = std::vector<SubCell>;

}  // namespace

TEST_CASE("traversal: axis-aligned, both ways") {
  CHECK(walk({0.5, 0.5}, {3.5, 0.5}) == V{{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  CHECK(walk({3.5, 0.5}, {0.5, 0.5}) == V{{3, 0}, {2, 0}, {1, 0}, {0, 0}});
  CHECK(walk({1.5, 3.5}, {1.5, 0.2}) == V{{1, 3}, {1, 2}, {1, 1}, {1, 0}});
  CHECK(walk({1.5, 0.5}, {1.5, 2.7}) == V{{1, 0}, {1, 1}, {1, 2}});
  CHECK(walk({1.5, 1.5}, {1.7, 1.2}) == V{{1, 1}});
}

TEST_CASE("traversal: diagonals through corners step diagonally") {
  CHECK(walk({0.5, 0.5}, {3.5, 3.5}) == V{{0, 0}, {1, 1}, {2, 2}, {3, 3}});
  CHECK(walk({3.5, 3.5}, {0.5, 0.5}) == V{{3, 3}, {2, 2}, {1, 1}, {0, 0}});
  CHECK(walk({0.5, 3.5}, {3.5, 0.5}) == V{{0, 3}, {1, 2}, {2, 1}, {3, 0}});
}

TEST_CASE("traversal: shallow and negative directions cross every sub-cell in order") {
  // (3.5, 2.2) -> (0.5, 1.4): x = 3 at y 2.067, y = 2 at x 2.75, x = 2 at y 1.8, x = 1 at y 1.533.
  CHECK(walk({3.5, 2.2}, {0.5, 1.4}) == V{{3, 2}, {2, 2}, {2, 1}, {1, 1}, {0, 1}});
  // (0.2, 0.5) -> (2.6, 1.7): y = 1 at x 1.2, x = 1 first at y 0.9.
  CHECK(walk({0.2, 0.5}, {2.6, 1.7}) == V{{0, 0}, {1, 0}, {1, 1}, {2, 1}});
}

TEST_CASE("traversal: stops at the grid's edge") {
  CHECK(walk({4.5, 2.5}, {10.0, 2.5}) == V{{4, 2}, {5, 2}});
  CHECK(walk({0.5, 0.5}, {-3.0, -3.0}) == V{{0, 0}});
  CHECK(walk({-1.0, 0.5}, {2.0, 0.5}).empty());  // starting outside: nothing
}

TEST_CASE("traversal: matches dense sampling on random segments") {
  common::Rng rng(7);
  const GridGeometry g = unit_subcells();
  for (int n = 0; n < 300; ++n) {
    const mapping::Point a{rng.uniform(0.0, 6.0), rng.uniform(0.0, 6.0)};
    const mapping::Point b{rng.uniform(0.0, 6.0), rng.uniform(0.0, 6.0)};
    const V cells = mapping::subcells_on_segment(g, a, b);
    REQUIRE(!cells.empty());
    // Consecutive sub-cells share a side (random segments never hit a corner exactly).
    for (std::size_t i = 1; i < cells.size(); ++i) {
      CHECK(std::abs(cells[i].x - cells[i - 1].x) + std::abs(cells[i].y - cells[i - 1].y) == 1);
    }
    // Every sample point lies in a listed sub-cell, and every listed sub-cell gets samples
    // in the order listed.
    std::size_t at = 0;
    constexpr int kSamples = 4000;
    for (int s = 0; s <= kSamples && at < cells.size(); ++s) {
      const double t = static_cast<double>(s) / kSamples;
      const SubCell p{static_cast<int>(std::floor(a.x_m + t * (b.x_m - a.x_m))),
                      static_cast<int>(std::floor(a.y_m + t * (b.y_m - a.y_m)))};
      while (at < cells.size() && !(cells[at] == p)) ++at;
    }
    CHECK(at < cells.size());
    CHECK(cells.back() == SubCell{static_cast<int>(b.x_m), static_cast<int>(b.y_m)});
  }
}

TEST_CASE("ray model: beams grazing a corridor wall keep its band; crossing an opening frees it") {
  // A 12 x 1 corridor, enclosed, scanned from its west end. Far down the corridor 1-degree
  // beams land more than a sub-cell apart on the walls, so some band sub-cells are crossed
  // by beams that end further on and hit by none: they must not be freed.
  const testing_world::TextMaze maze(
      "o---o---o---o---o---o---o---o---o---o---o---o---o\n"
      "|                                               |\n"
      "o---o---o---o---o---o---o---o---o---o---o---o---o");
  const auto boxes = testing_world::wall_boxes(maze, 1.0, 0.012);
  const mapping::SensorModel model;
  OccupancyGrid grid(geometry(3, 12, 1), 0.0f);
  mapping::ScanUpdate update;
  ModelOptions ray;
  ray.kind = ModelKind::ray;
  const mapping::Point origin{0.5, 0.5};
  const auto ranges = testing_world::range_image(boxes, origin, 0.0, 360, 2 * kPi, 0.05, 12.0);
  for (int scan = 0; scan < 3; ++scan) {
    sensing::integrate_scan(ray, grid, testing_world::hambot_scan(origin, 0.0, ranges), Cell{0, 0},
                            model, update);
  }
  int hit_bands = 0;
  for (int x = 0; x < 12; ++x) {
    CAPTURE(x);
    // North and south band middles: walls, or not seen; never freed.
    for (const int i : {0, 2}) {
      const float l = grid.at(Cell{x, 0}, mapping::LocalSubCell{i, 1});
      CHECK(l >= 0.0f);
      hit_bands += l > 0.0f ? 1 : 0;
    }
  }
  CHECK(hit_bands >= 8);  // the near walls are seen
  // Openings between cells: the beam along the corridor crosses them and frees both bands.
  for (int x = 0; x < 11; ++x) {
    CAPTURE(x);
    CHECK(grid.at(Cell{x, 0}, mapping::LocalSubCell{1, 2}) < 0.0f);
    CHECK(grid.at(Cell{x + 1, 0}, mapping::LocalSubCell{1, 0}) < 0.0f);
  }
}

TEST_CASE("cell model: readings split evenly between wall and opening leave the side unknown") {
  // The centre cell of kNorthWest facing north: its east side is open (beam 270 and its
  // neighbours read 1.494 m). Two adjacent spikes that agree with each other (0.6 and 0.47 m)
  // beside a dropped beam once made the lower median of four a wall that sealed a cell.
  const testing_world::TextMaze maze(kNorthWest);
  const auto boxes = testing_world::wall_boxes(maze, 1.0, 0.012);
  const mapping::Point origin{1.5, 1.5};
  std::vector<float> ranges = testing_world::range_image(boxes, origin, kPi / 2, 360, 2 * kPi, 0.05, 12.0);
  // kNorthWest has no outer walls: put one 1.5 m east (a wall a cell beyond the opening).
  for (int i = 260; i <= 280; ++i) ranges[static_cast<std::size_t>(i)] = 1.494f;
  const OccupancyGrid grid(geometry(3), 0.0f);
  const ModelOptions options;
  const auto east = [&] {
    return sensing::read_cell_side(options, grid, testing_world::hambot_scan(origin, kPi / 2, ranges), Cell{1, 1},
                                   mapping::Heading::east);
  };
  CHECK(east() == mapping::SideState::open);
  CHECK(sensing::read_cell_side(options, grid, testing_world::hambot_scan(origin, kPi / 2, ranges), Cell{1, 1},
                                mapping::Heading::north) == mapping::SideState::wall);
  ranges[268] = std::numeric_limits<float>::quiet_NaN();
  ranges[270] = 0.6f;
  ranges[271] = 0.47f;
  CHECK(east() == mapping::SideState::unknown);  // two near, two far
  ranges[269] = 0.55f;
  CHECK(east() == mapping::SideState::wall);     // three of four near: the majority
  ranges[269] = ranges[272];
  ranges[268] = ranges[272];
  CHECK(east() == mapping::SideState::open);     // two near of five: the median is far
}

TEST_CASE("cell model: the beams down a straight read the sides ahead, a wall where they stop, none past reach") {
  // A corridor one cell wide and six long, a wall across it on the north side of (0,3); the
  // robot at the centre of (0,0) facing north.
  const testing_world::TextMaze corridor(
      "o---o\n|   |\no   o\n|   |\no---o\n|   |\no   o\n|   |\no   o\n|   |\no   o\n|   |\no---o");
  const auto boxes = testing_world::wall_boxes(corridor, 1.0, 0.012);
  const mapping::Point origin{0.5, 0.5};
  const OccupancyGrid grid(geometry(3, 1, 6), 0.0f);
  const ModelOptions options;
  const auto north_of = [&](const sensing::LidarScan &scan, int y) {
    return sensing::read_side_ahead(options, grid, scan, Cell{0, y}, mapping::Heading::north);
  };
  const std::vector<float> far = testing_world::range_image(boxes, origin, kPi / 2, 360, 2 * kPi, 0.05, 12.0);
  const sensing::LidarScan far_scan = testing_world::hambot_scan(origin, kPi / 2, far);
  for (const int y : {0, 1, 2}) CHECK(north_of(far_scan, y) == mapping::SideState::open);
  CHECK(north_of(far_scan, 3) == mapping::SideState::wall);
  CHECK(north_of(far_scan, 4) == mapping::SideState::wall);  // behind the wall: the beams stop short of it

  // A lidar reaching 2 m sees the sides 0.5 and 1.5 m on (with the quarter-cell margin), not 2.5 m.
  const std::vector<float> near = testing_world::range_image(boxes, origin, kPi / 2, 360, 2 * kPi, 0.05, 2.0);
  sensing::LidarScan near_scan = testing_world::hambot_scan(origin, kPi / 2, near);
  near_scan.max_range_m = 2.0;
  CHECK(north_of(near_scan, 0) == mapping::SideState::open);
  CHECK(north_of(near_scan, 1) == mapping::SideState::open);
  CHECK(north_of(near_scan, 2) == mapping::SideState::unknown);
  // The robot's own side reads as before: no return there is an opening.
  CHECK(sensing::read_cell_side(options, grid, near_scan, Cell{0, 0}, mapping::Heading::north) ==
        mapping::SideState::open);
}
