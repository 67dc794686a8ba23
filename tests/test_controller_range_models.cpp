// One-scan matrices of the bump, depth, pie and cone models, as literal K x K
// tables of the centre cell of a 3 x 3 grid of 1 m cells, and the course's base-10 numbers.

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "common/error.hpp"
#include "mapping/sensor_model.hpp"
#include "render/ascii_map.hpp"
#include "sensing/range_models.hpp"
#include "sensing/setups.hpp"
#include "test_values.hpp"

using sensing::BumpReading;
using mapping::Cell;
using mapping::OccupancyGrid;
using mapping::Point;
using sensing::RangeReading;

namespace {

constexpr double kNorth = kPi / 2.0;

mapping::GridGeometry geometry(int k) {
  mapping::GridGeometry g;
  g.width_cells = 3;
  g.height_cells = 3;
  g.subcells = k;
  g.cell_size_m = 1.0;
  return g;
}

mapping::SensorModel base10() {
  mapping::SensorModelOptions o;
  o.base = mapping::LogBase::ten;
  return mapping::SensorModel(o);
}

// The hambot's rim sensor looking north from the centre of cell (1, 1); a wall face 0.006 m
// south of y = 2 is 0.404 m ahead.
const Point kRim{1.5, 1.59};
constexpr double kToNorthWall = 0.404;

RangeReading reading(double angle_rad, double range_m, double max_m, double aperture = 0.0,
                     double error = 0.0) {
  return RangeReading{kRim, angle_rad, range_m, max_m, aperture, error};
}

}  // namespace

TEST_CASE("range models: the course's base-10 numbers") {
  const mapping::SensorModel model = base10();
  CHECK(model.increment_for(sensing::kBumpOccupiedP) == doctest::Approx(5.000).epsilon(1e-4));
  CHECK(model.increment_for(sensing::kBumpFreeP) == doctest::Approx(-0.368).epsilon(1e-3));
  CHECK(model.increment_for(sensing::kDepthRayP) == doctest::Approx(-0.176).epsilon(1e-3));
  CHECK(model.increment_for(sensing::kDepthHitP) == doctest::Approx(5.000).epsilon(1e-4));
}

TEST_CASE("bump model: pressed front bumper against the north wall, K = 3, base 10") {
  const mapping::SensorModel model = base10();
  OccupancyGrid grid(geometry(3), 0.0f);
  const Point robot{1.5, 1.904};  // body radius 0.09 from the wall face
  const double d = 0.09 / std::numbers::sqrt2;
  const std::vector<BumpReading> bumpers{{{1.5, 1.994}, true},
                                         {{1.5 - d, 1.904 + d}, false},
                                         {{1.5 + d, 1.904 + d}, false}};
  sensing::LeveledUpdate update = sensing::make_bump_update();
  sensing::mark_bumps(grid, robot, bumpers, update);
  CHECK(update.apply(grid, model) == 1);  // everything in the band middle: occupied wins
  CHECK(render::format_cell_matrix(grid, Cell{1, 1}) ==
        "+0.00 +5.00 +0.00\n"
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00\n");
  // Back at the centre, nothing pressed: the centre is freed once.
  sensing::mark_bumps(grid, Point{1.5, 1.5},
                      std::vector<BumpReading>{{{1.5, 1.59}, false}, {{1.5 - d, 1.5 + d}, false}},
                      update);
  CHECK(update.apply(grid, model) == 1);
  CHECK(grid.at(Cell{1, 1}, {1, 1}) == doctest::Approx(-0.368).epsilon(1e-3));
  CHECK(grid.at(Cell{1, 1}, {0, 1}) == doctest::Approx(5.000).epsilon(1e-4));
}

TEST_CASE("depth model: a hit north, a ray west, ignored readings, K = 3, base 10") {
  const mapping::SensorModel model = base10();
  OccupancyGrid grid(geometry(3), 0.0f);
  const std::vector<RangeReading> rays{
      reading(kNorth, kToNorthWall, 4.0),
      RangeReading{Point{1.41, 1.5}, kPi, 0.9, 4.0, 0.0, 0.0},  // hits x = 0.51, cell (0, 1)
      reading(0.0, 4.0, 4.0),   // max: ignored
      reading(-kNorth, 0.0, 4.0)};  // 0: ignored
  sensing::LeveledUpdate update = sensing::make_depth_update();
  sensing::mark_depth(grid, Point{1.5, 1.5}, rays, update);
  update.apply(grid, model);
  CHECK(render::format_cell_matrix(grid, Cell{1, 1}) ==
        "+0.00 +5.00 +0.00\n"
        "-0.18 -0.37 +0.00\n"
        "+0.00 +0.00 +0.00\n");
  CHECK(render::format_cell_matrix(grid, Cell{0, 1}) ==
        "+0.00 +0.00 +0.00\n"
        "+0.00 +5.00 -0.18\n"
        "+0.00 +0.00 +0.00\n");
  CHECK(grid.at(Cell{1, 1}, {1, 0}) == doctest::Approx(-0.176).epsilon(1e-3));
}

TEST_CASE("pie model: contacting north reading, K = 3, beta 25 deg, base e") {
  const mapping::SensorModel model;  // prior 0.5: increments are logit(0.7), logit(0.4)
  OccupancyGrid grid(geometry(3), 0.0f);
  sensing::RangeModelOptions options;
  options.pie_half_angle_rad = 25.0 * kPi / 180.0;
  sensing::LeveledUpdate update = sensing::make_pie_update();
  const std::vector<RangeReading> one{reading(kNorth, kToNorthWall, 1.5)};
  sensing::mark_pie(grid, options, one, update);
  update.apply(grid, model);
  // The band's three sub-cells share the corners (x 1.333, 1.667; y 2) in the contact part.
  CHECK(render::format_cell_matrix(grid, Cell{1, 1}) ==
        "+0.85 +0.85 +0.85\n"
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00\n");
  CHECK(grid.at(Cell{1, 1}, {0, 1}) == doctest::Approx(std::log(0.7 / 0.3)));
}

TEST_CASE("pie model: a clear reading frees the slice, K = 3, beta 10 deg") {
  const mapping::SensorModel model;
  OccupancyGrid grid(geometry(3), 0.0f);
  sensing::LeveledUpdate update = sensing::make_pie_update();
  const std::vector<RangeReading> one{reading(kNorth, 1.5, 1.5)};
  sensing::RangeModelOptions whole_slice;  // the course's slice, to max range
  whole_slice.pie_usable_fraction = 1.0;
  sensing::mark_pie(grid, whole_slice, one, update);
  update.apply(grid, model);
  CHECK(render::format_cell_matrix(grid, Cell{1, 1}) ==
        "+0.00 -0.41 +0.00\n"
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00\n");
  // The slice widens: at y = 2.667 its half-width (0.19 m) takes in the corners x = 1.333, 1.667.
  CHECK(render::format_cell_matrix(grid, Cell{1, 2}) ==
        "-0.41 -0.41 -0.41\n"
        "-0.41 -0.41 -0.41\n"
        "+0.00 -0.41 +0.00\n");
}

TEST_CASE("pie model: the clear slice stops at the usable range, 2/3 of max") {
  const mapping::SensorModel model;
  OccupancyGrid grid(geometry(3), 0.0f);
  sensing::LeveledUpdate update = sensing::make_pie_update();
  const std::vector<RangeReading> one{reading(kNorth, 1.5, 1.5)};
  sensing::mark_pie(grid, sensing::RangeModelOptions{}, one, update);
  update.apply(grid, model);
  // 1.0 m from y = 1.59: the next cell's far band (y 2.667 ...) and the inner corners of its
  // side bands stay unobserved.
  CHECK(render::format_cell_matrix(grid, Cell{1, 2}) ==
        "+0.00 +0.00 +0.00\n"
        "+0.00 -0.41 +0.00\n"
        "+0.00 -0.41 +0.00\n");
}

// The ir-ring's four axis sensors in cell (1, 1), robot facing north: walls north and east
// (readings 0.404 m, contacting), openings west and south (nothing seen: max 1.5 m).
std::vector<RangeReading> ir_cross_scan() {
  const double eps = 0.03;
  return {RangeReading{{1.5, 1.59}, kNorth, kToNorthWall, 1.5, 0.03, eps},
          RangeReading{{1.59, 1.5}, 0.0, kToNorthWall, 1.5, 0.03, eps},
          RangeReading{{1.41, 1.5}, kPi, 1.5, 1.5, 0.03, eps},
          RangeReading{{1.5, 1.41}, -kNorth, 1.5, 1.5, 0.03, eps}};
}

TEST_CASE("pie model: walls north and east in one scan, K = 3, beta 10 deg") {
  const mapping::SensorModel model;
  OccupancyGrid grid(geometry(3), 0.0f);
  sensing::LeveledUpdate update = sensing::make_pie_update();
  sensing::mark_pie(grid, sensing::RangeModelOptions{}, ir_cross_scan(), update);
  update.apply(grid, model);
  // No corner or centre of the north band's middle sub-cell lies in the contact part (its
  // centre is 0.24 m ahead, its far corners 22 deg off the axis); the reading's arc, 0.404 m
  // ahead and 0.14 m across (x 1.43 ... 1.57, y 1.99), lies inside it. Likewise east.
  CHECK(render::format_cell_matrix(grid, Cell{1, 1}) ==
        "+0.00 +0.85 +0.00\n"
        "-0.41 +0.00 +0.85\n"
        "+0.00 -0.41 +0.00\n");
  // The arcs span two errors either side of the reading, 0.380 ... 0.428 m (y 1.970 ...
  // 2.018): past the cell side, into the neighbour's band - the wall's other half.
  CHECK(render::format_cell_matrix(grid, Cell{1, 2}) ==
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.85 +0.00\n");
  CHECK(grid.at(Cell{1, 1}, {0, 1}) == doctest::Approx(std::log(0.7 / 0.3)));
  CHECK(grid.at(Cell{1, 1}, {1, 0}) == doctest::Approx(std::log(0.4 / 0.6)));
}

TEST_CASE("pie model: walls north and east in one scan, K = 5, beta 10 deg") {
  const mapping::SensorModel model;
  OccupancyGrid grid(geometry(5), 0.0f);
  sensing::LeveledUpdate update = sensing::make_pie_update();
  sensing::mark_pie(grid, sensing::RangeModelOptions{}, ir_cross_scan(), update);
  update.apply(grid, model);
  // Each slice frees the sub-cells whose centre is on its axis; the sub-cell next to the
  // robot's own has its near corners 0.01 m ahead, 84 deg off the axis. The wall bands'
  // middles hold the arcs.
  CHECK(render::format_cell_matrix(grid, Cell{1, 1}) ==
        "+0.00 +0.00 +0.85 +0.00 +0.00\n"
        "+0.00 +0.00 -0.41 +0.00 +0.00\n"
        "-0.41 -0.41 +0.00 -0.41 +0.85\n"
        "+0.00 +0.00 -0.41 +0.00 +0.00\n"
        "+0.00 +0.00 -0.41 +0.00 +0.00\n");
}

TEST_CASE("pie model: a contact lies two of its errors and two of max's below max") {
  const mapping::SensorModel model;
  sensing::LeveledUpdate update = sensing::make_pie_update();
  // From the rim of cell (1, 0) looking north; max 1.5 m, eps 3 %: a contact needs
  // d (1 + 2 eps) < 1.5 (1 - 2 eps), d < 1.330 m. A no-return read 2.3 sigma short (1.40 m)
  // would put its arc (y 1.99) on cell (1, 1)'s north band: under the old 1.41 m limit one
  // such reading closed an opening.
  const auto scan = [&](double range_m) {
    OccupancyGrid grid(geometry(3), 0.0f);
    const std::vector<RangeReading> one{RangeReading{{1.5, 0.59}, kNorth, range_m, 1.5, 0.03, 0.03}};
    sensing::mark_pie(grid, sensing::RangeModelOptions{}, one, update);
    update.apply(grid, model);
    return grid;
  };
  const OccupancyGrid clear = scan(1.40);
  // Clear up to the usable range, 1.0 m (y 1.59): cell (1, 1)'s north band is not touched.
  CHECK(clear.at(Cell{1, 1}, {0, 1}) == 0.0f);
  CHECK(clear.at(Cell{1, 1}, {2, 1}) == doctest::Approx(std::log(0.4 / 0.6)));
  const OccupancyGrid contact = scan(1.30);
  // The arc at y = 1.89 lies in cell (1, 1)'s north band.
  CHECK(contact.at(Cell{1, 1}, {0, 1}) == doctest::Approx(std::log(0.7 / 0.3)));
}

TEST_CASE("pie model: a reading averaged across a post's edge is no information") {
  const mapping::SensorModel model;
  sensing::LeveledUpdate update = sensing::make_pie_update();
  // The ir-ring's diagonal sensor looking south-west from the centre of cell (1, 1): a post
  // at the corner (1, 1) reads 0.6 m; one ray on the post and two past it average 0.948 m,
  // whose arc (x, y 0.77) lies 0.23 m from any cell side.
  const auto scan = [&](double range_m) {
    OccupancyGrid grid(geometry(3), 0.0f);
    const double a = -3.0 * kPi / 4.0;
    const std::vector<RangeReading> one{
        RangeReading{{1.5 + 0.09 * std::cos(a), 1.5 + 0.09 * std::sin(a)}, a, range_m, 1.5, 0.03, 0.03}};
    sensing::mark_pie(grid, sensing::RangeModelOptions{}, one, update);
    update.apply(grid, model);
    return grid;
  };
  const OccupancyGrid post = scan(0.6);
  CHECK(post.at(Cell{1, 1}, {2, 0}) == doctest::Approx(std::log(0.7 / 0.3)));
  const OccupancyGrid mixed = scan(0.948);
  for (const Cell c : {Cell{0, 0}, Cell{1, 0}, Cell{0, 1}, Cell{1, 1}}) {
    CHECK(render::format_cell_matrix(mixed, c) ==
          "+0.00 +0.00 +0.00\n"
          "+0.00 +0.00 +0.00\n"
          "+0.00 +0.00 +0.00\n");
  }
}

TEST_CASE("cone model: IR reading north, K = 3, defaults") {
  const mapping::SensorModel model;  // p_occ 0.6 -> +0.41, p_free 0.3 -> -0.85
  OccupancyGrid grid(geometry(3), 0.0f);
  sensing::LeveledUpdate update = sensing::make_cone_update(model.options());
  const std::vector<RangeReading> one{reading(kNorth, kToNorthWall, 1.5, 0.03, 0.03)};
  sensing::mark_cone(grid, one, update);
  update.apply(grid, model);
  CHECK(render::format_cell_matrix(grid, Cell{1, 1}) ==
        "+0.00 +0.41 +0.00\n"
        "+0.00 -0.85 +0.00\n"
        "+0.00 +0.00 +0.00\n");
  // The arc reaches d (1 + eps) = 0.416 m: past the boundary into the neighbour's band.
  CHECK(render::format_cell_matrix(grid, Cell{1, 2}) ==
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00\n"
        "+0.00 +0.41 +0.00\n");
}

TEST_CASE("cone model: a sonar's arc at 0.4 m stays within one 0.2 m column, K = 5") {
  const mapping::SensorModel model;
  OccupancyGrid grid(geometry(5), 0.0f);
  sensing::LeveledUpdate update = sensing::make_cone_update(model.options());
  const std::vector<RangeReading> one{reading(kNorth, kToNorthWall, 5.0, 0.4, 0.066)};
  sensing::mark_cone(grid, one, update);
  update.apply(grid, model);
  // Half the aperture (0.2 rad) at 0.43 m is 0.086 m across: x 1.414 ... 1.586, column 2.
  // The free cone ends at 0.377 m, in radial steps of 0.094 m: row 1 is first reached at
  // 0.094 m, range weight 1 - 0.25^2 = 0.94, p = 0.5 - 0.94 x 0.2 = 0.3125: -0.79.
  CHECK(render::format_cell_matrix(grid, Cell{1, 1}) ==
        "+0.00 +0.00 +0.41 +0.00 +0.00\n"
        "+0.00 +0.00 -0.79 +0.00 +0.00\n"
        "+0.00 +0.00 -0.85 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00 +0.00 +0.00\n"
        "+0.00 +0.00 +0.00 +0.00 +0.00\n");
}

TEST_CASE("range model options are validated") {
  sensing::RangeModelOptions o;
  o.pie_half_angle_rad = 0.0;
  CHECK_THROWS_AS(sensing::validate(o), common::InputError);
  o = {};
  o.pie_contact_m = -0.1;
  CHECK_THROWS_AS(sensing::validate(o), common::InputError);
  CHECK(sensing::parse_model("bump") == sensing::ModelKind::bump);
  CHECK(sensing::to_string(sensing::ModelKind::cone) == "cone");
}

TEST_CASE("cone model: a sonar looking along a corridor leaves the side bands alone and fades with range") {
  const mapping::SensorModel model;
  OccupancyGrid grid(geometry(3), 0.0f);
  sensing::LeveledUpdate update = sensing::make_cone_update(model.options());
  // Openings north of cells (1, 1) and (1, 2), a wall north of (1, 2): 1.404 m ahead.
  const std::vector<RangeReading> one{reading(kNorth, 1.404, 5.0, 0.4, 0.066)};
  sensing::mark_cone(grid, one, update);
  update.apply(grid, model);
  // Arc 1.219 ... 1.589 m (two errors of 6.6 % either side; past y = 3 it leaves the grid);
  // from 1.25 m on it has five bins at 0, +-0.08, +-0.16 rad. The axis bin gets p_occ
  // (+0.41); the outer bins, 0.21 m off the axis, fall in the band's corners with weight
  // 1 - 0.8^2 = 0.36: p = 0.5 + 0.36 x 0.1 = 0.536, +0.14. In the free cone at y 2.33 ... 2.67
  // the outermost bin centre is 0.133 rad off the axis (0.13 m): the west and east bands,
  // 0.167 m away, are not freed (without the weighting the cone's edges, 0.2 m off the axis,
  // freed them at -0.85: the walls beside every corridor the sonar looked along).
  // The free cone ends at 1.219 m, in 8 radial steps of 0.152 m; each sub-cell takes its
  // nearest step's range weight 1 - (r / 1.219)^2: row 2 of cell (1, 2) from r 0.457 m
  // (w 0.86, p 0.328, -0.72), row 1 from 0.762 m (w 0.61, p 0.378, -0.50).
  CHECK(render::format_cell_matrix(grid, Cell{1, 2}) ==
        "+0.14 +0.41 +0.14\n"
        "+0.00 -0.50 +0.00\n"
        "+0.00 -0.72 +0.00\n");
  CHECK(render::format_cell_matrix(grid, Cell{1, 1}) ==
        "+0.00 -0.83 +0.00\n"
        "+0.00 -0.85 +0.00\n"
        "+0.00 +0.00 +0.00\n");
  CHECK(grid.at(Cell{1, 2}, {0, 0}) == doctest::Approx(std::log(0.536 / 0.464)));
}

TEST_CASE("leveled update: a weighted mark moves p from the prior towards its level's p") {
  mapping::SensorModelOptions o;
  o.base = mapping::LogBase::ten;
  o.prior = 0.4;
  const mapping::SensorModel model(o);
  OccupancyGrid grid(geometry(3), static_cast<float>(model.prior_log_odds()));
  sensing::LeveledUpdate update({0.7, 0.2});
  update.mark(grid, mapping::SubCell{0, 0}, 1, 1.0);   // p 0.2
  update.mark(grid, mapping::SubCell{1, 0}, 1, 0.5);   // p 0.4 + 0.5 (0.2 - 0.4) = 0.3
  update.mark(grid, mapping::SubCell{1, 0}, 1, 0.25);  // weaker, same level: ignored
  update.mark(grid, mapping::SubCell{2, 0}, 1, 1.0);
  update.mark(grid, mapping::SubCell{2, 0}, 0, 0.5);   // occupied wins: p 0.4 + 0.5 (0.3) = 0.55
  update.mark(grid, mapping::SubCell{3, 0}, 0, 0.0);   // no information: no update
  CHECK(update.apply(grid, model) == 3);
  const double l0 = model.prior_log_odds();
  CHECK(grid.at(mapping::SubCell{0, 0}) == doctest::Approx(std::log10(0.2 / 0.8)));
  CHECK(grid.at(mapping::SubCell{1, 0}) == doctest::Approx(std::log10(0.3 / 0.7)));
  CHECK(grid.at(mapping::SubCell{2, 0}) == doctest::Approx(std::log10(0.55 / 0.45)));
  CHECK(grid.at(mapping::SubCell{3, 0}) == doctest::Approx(l0));
}

TEST_CASE("no-return readings: a sonar's tells of its cone only when it looks square to the grid") {
  // Sonar, aperture 0.4 rad: square when the axis is within pi/8 - 0.2 = 0.193 rad of a grid axis.
  RangeReading sonar = reading(kNorth, 5.0, 5.0, 0.4, 0.066);
  sonar.echo_can_be_lost = true;
  CHECK(sensing::no_return_tells(sonar));
  sonar.angle_rad = kPi + 0.19;
  CHECK(sensing::no_return_tells(sonar));
  sonar.angle_rad = kPi + 0.2;
  CHECK_FALSE(sensing::no_return_tells(sonar));
  sonar.angle_rad = kPi / 4;  // the ring's diagonals hear nothing, wall or no wall
  CHECK_FALSE(sensing::no_return_tells(sonar));
  RangeReading ir = reading(kPi / 4, 1.5, 1.5, 0.03, 0.03);
  CHECK(sensing::no_return_tells(ir));
  // Nothing seen: within two errors of max, d (1 + 2 eps) >= max (1 - 2 eps): from 3.83 m.
  CHECK(sensing::is_no_return(reading(kNorth, 3.9, 5.0, 0.4, 0.066)));
  CHECK_FALSE(sensing::is_no_return(reading(kNorth, 3.8, 5.0, 0.4, 0.066)));
}

TEST_CASE("cone model: a sonar's lost echo at a slant marks nothing; square to the grid it frees the cone") {
  const mapping::SensorModel model;
  const auto scan = [&](double angle_rad) {
    OccupancyGrid grid(geometry(3), 0.0f);
    sensing::LeveledUpdate update = sensing::make_cone_update(model.options());
    RangeReading r{Point{1.5, 1.5}, angle_rad, 5.1, 5.0, 0.4, 0.066, true};
    sensing::mark_cone(grid, std::vector<RangeReading>{r}, update);
    return update.apply(grid, model);
  };
  CHECK(scan(kPi / 4) == 0);
  CHECK(scan(kNorth) > 0);
}

TEST_CASE("read_range_side: the reading facing a side reads it wall, open or unknown") {
  const OccupancyGrid grid(geometry(3), 0.0f);
  // Cell (1, 1); the north side's line y = 2 is 0.41 m from the rim at y 1.59.
  const auto side = [&](std::vector<RangeReading> readings, mapping::Heading h) {
    return sensing::read_range_side(grid, readings, Cell{1, 1}, h);
  };
  using mapping::Heading;
  using mapping::SideState;
  CHECK(side({reading(kNorth, 0.404, 1.5, 0.03, 0.03)}, Heading::north) == SideState::wall);
  // Up to the line plus a quarter cell (0.66 m) is a wall; beyond it, or nothing seen, open.
  CHECK(side({reading(kNorth, 0.65, 1.5, 0.03, 0.03)}, Heading::north) == SideState::wall);
  CHECK(side({reading(kNorth, 0.67, 1.5, 0.03, 0.03)}, Heading::north) == SideState::open);
  CHECK(side({reading(kNorth, 1.5, 1.5, 0.03, 0.03)}, Heading::north) == SideState::open);
  // No reading faces east (0.1 rad at most off the side's normal).
  CHECK(side({reading(kNorth, 0.404, 1.5, 0.03, 0.03)}, Heading::east) == SideState::unknown);
  CHECK(side({reading(0.11, 0.404, 1.5, 0.03, 0.03)}, Heading::east) == SideState::unknown);
  // A sonar square to the side that heard nothing: open (a wall there would have echoed).
  RangeReading sonar = reading(kNorth, 5.0, 5.0, 0.4, 0.066);
  sonar.echo_can_be_lost = true;
  CHECK(side({sonar}, Heading::north) == SideState::open);
}
