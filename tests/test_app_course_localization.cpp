// The localization lab's arithmetic (app/run/localization.hpp) and its two demos: the
// closed-form trilateration, the cell scores, the grid filter's predict and correct, the
// particle filter's draws, and the runs over every start of the shipped 5 x 5 world.

#include <doctest/doctest.h>

#include <cmath>
#include <numeric>
#include <string>

#include "app/course/demo_localize.hpp"
#include "app/course/demo_trilaterate.hpp"
#include "app/run/localization.hpp"
#include "common/error.hpp"
#include "maze/world/world.hpp"

namespace course_loc = app::loc;

namespace {

const std::string kLoc5x5 = std::string(WORLDS_DIR) + "/loc5x5.txt";

std::array<double, 3> exact_distances(double x, double y, const std::array<course_loc::Landmark, 3> &m) {
  std::array<double, 3> r{};
  for (std::size_t k = 0; k < 3; ++k) r[k] = std::hypot(x - m[k].x_m, y - m[k].y_m);
  return r;
}

double total_of(const std::vector<double> &v) { return std::accumulate(v.begin(), v.end(), 0.0); }

}  // namespace

TEST_CASE("trilateration from exact distances to three corner landmarks gives the pose back to 1e-9") {
  const auto &l = course_loc::kArenaLandmarks;
  for (const auto &marks : {std::array<course_loc::Landmark, 3>{l[0], l[1], l[2]}, std::array<course_loc::Landmark, 3>{l[1], l[3], l[2]},
                            std::array<course_loc::Landmark, 3>{l[0], l[2], l[3]}}) {
    for (const auto &[x, y] : {std::pair{0.0, 0.0}, std::pair{-2.1, 1.9}, std::pair{1.37, -0.42}, std::pair{2.5, -2.5}}) {
      const course_loc::Trilateration t = course_loc::trilaterate(marks, exact_distances(x, y, marks));
      CHECK(std::abs(t.x_m - x) < 1e-9);
      CHECK(std::abs(t.y_m - y) < 1e-9);
    }
  }
}

TEST_CASE("trilateration with yellow, red and green has A 10, B 0, D -10, E -10 and the course's x and y") {
  const auto &l = course_loc::kArenaLandmarks;
  const course_loc::Trilateration t = course_loc::trilaterate({l[0], l[1], l[2]}, {3.2, 4.1, 2.9});
  CHECK(t.a == 10.0);
  CHECK(t.b == 0.0);
  CHECK(t.d == -10.0);
  CHECK(t.e == -10.0);
  CHECK(t.c == doctest::Approx(3.2 * 3.2 - 4.1 * 4.1));
  CHECK(t.f == doctest::Approx(4.1 * 4.1 - 2.9 * 2.9));
  CHECK(t.x_m == doctest::Approx((t.c * t.e - t.f * t.b) / (t.e * t.a - t.b * t.d)));
  CHECK(t.y_m == doctest::Approx((t.c * t.d - t.a * t.f) / (t.b * t.d - t.a * t.e)));
}

TEST_CASE("three landmarks on one line are refused: the closed form divides by zero") {
  const course_loc::Landmark a{"a", 0, 0}, b{"b", 1, 0}, c{"c", 2, 0};
  CHECK_THROWS_AS(course_loc::trilaterate({a, b, c}, {1, 1, 1}), common::InputError);
}

TEST_CASE("arena cells are numbered row by row from the north-west, 1 to 25") {
  CHECK(course_loc::arena_cell(-2.0, 2.0) == 1);
  CHECK(course_loc::arena_cell(2.0, 2.0) == 5);
  CHECK(course_loc::arena_cell(0.0, 0.0) == 13);
  CHECK(course_loc::arena_cell(-2.0, -2.0) == 21);
  CHECK(course_loc::arena_cell(2.5, -2.5) == 25);
  CHECK_FALSE(course_loc::arena_cell(2.6, 0.0).has_value());
  CHECK(course_loc::arena_cell_centre(1) == std::array<double, 2>{-2.0, 2.0});
  CHECK(course_loc::arena_cell_centre(25) == std::array<double, 2>{2.0, -2.0});
}

TEST_CASE("cell scores are normal densities multiplied over the measured landmarks, normalised, highest at the cell measured from") {
  CHECK(course_loc::normal_density(0.0, 0.0, 1.0) == doctest::Approx(0.3989422804));
  CHECK(course_loc::normal_density(1.0, 0.0, 1.0) == doctest::Approx(0.2419707245));
  std::array<std::optional<double>, 4> d{};
  const auto centre = course_loc::arena_cell_centre(8);
  for (std::size_t k = 0; k < 4; ++k) d[k] = std::hypot(centre[0] - course_loc::kArenaLandmarks[k].x_m, centre[1] - course_loc::kArenaLandmarks[k].y_m);
  const std::vector<double> s = course_loc::cell_scores(d, 1.0);
  CHECK(total_of(s) == doctest::Approx(1.0));
  CHECK(std::max_element(s.begin(), s.end()) - s.begin() == 7);
}

TEST_CASE("a correction multiplies by the four sides' sensor probabilities and normalises") {
  const maze::Maze m = maze::load_world(kLoc5x5).maze();
  const course_loc::WallMap map = course_loc::wall_map(m);
  REQUIRE(map.cells() == 25);
  // Cell 1: walls N, S, W; reading its walls exactly: 0.8 x 0.6 x 0.8 x 0.8.
  CHECK(map.walls[0] == course_loc::Reading{true, false, true, true});
  const course_loc::WallSensor sensor;
  CHECK(course_loc::likelihood(map, sensor, 0, map.walls[0]) == doctest::Approx(0.8 * 0.6 * 0.8 * 0.8));
  const course_loc::Reading none{false, false, false, false};
  CHECK(course_loc::likelihood(map, sensor, 0, none) == doctest::Approx(0.2 * 0.6 * 0.2 * 0.2));
  const std::vector<double> uniform(25, 1.0 / 25);
  const std::vector<double> b = course_loc::correct(map, sensor, uniform, map.walls[0]);
  CHECK(total_of(b) == doctest::Approx(1.0));
  double total = 0.0;
  for (std::size_t i = 0; i < 25; ++i) total += course_loc::likelihood(map, sensor, i, map.walls[0]);
  CHECK(b[0] == doctest::Approx(course_loc::likelihood(map, sensor, 0, map.walls[0]) / total));
}

TEST_CASE("a prediction moves p of an open cell's belief on, keeps 1 - p, and keeps all of a walled cell's") {
  const course_loc::WallMap map = course_loc::wall_map(maze::load_world(kLoc5x5).maze());
  std::vector<double> b(25, 0.0);
  b[0] = 0.6, b[1] = 0.4;  // cell 1 is open east, cell 2 is open east, cell 3 is walled east
  const std::vector<double> east = course_loc::predict(map, b, 1, 0.8);
  CHECK(east[0] == doctest::Approx(0.12));
  CHECK(east[1] == doctest::Approx(0.48 + 0.08));
  CHECK(east[2] == doctest::Approx(0.32));
  const std::vector<double> north = course_loc::predict(map, b, 0, 0.8);  // both walled north
  CHECK(north == b);
  CHECK(total_of(course_loc::predict(map, std::vector<double>(25, 0.04), 2, 0.7)) == doctest::Approx(1.0));
}

TEST_CASE("a sensor model whose pairs do not add up to 1 is refused") {
  CHECK_THROWS_AS(course_loc::validate(course_loc::WallSensor{0.8, 0.3, 0.4, 0.6}), common::InputError);
  CHECK_THROWS_AS(course_loc::validate(course_loc::WallSensor{1.2, -0.2, 0.4, 0.6}), common::InputError);
  CHECK_NOTHROW(course_loc::validate(course_loc::WallSensor{0.9, 0.1, 0.3, 0.7}));
}

TEST_CASE("the grid filter localizes from every start of loc5x5 within 4 moves, in the true cell") {
  for (int start = 1; start <= 25; ++start) {
    CAPTURE(start);
    app::course::DemoLocalizeInput in;
    in.world = kLoc5x5;
    in.start = start;
    const app::course::LocalizeResult r = app::course::run_demo_localize(in).result;
    CHECK(r.localized);
    CHECK(r.moves <= 4);
    CHECK(r.believed_cell == r.true_cell);
    CHECK(r.believed_share >= 0.8);
  }
}

TEST_CASE("an exact run whose moves cannot tell places apart names the alike starts and no cell") {
  app::course::DemoLocalizeInput in;
  in.world = std::string(WORLDS_DIR) + "/open_room6x6.txt";
  in.start = 15;  // an inner cell: no walls round it, nor round its east neighbour
  in.moves.push_back('E');
  const app::course::DemoLocalizeOutput o = app::course::run_demo_localize(in);
  CHECK_FALSE(o.result.localized);
  CHECK(o.result.alike_starts.size() == 12);  // the inner 4 x 4 but its east column
  CHECK(o.text.find("do not tell these starts apart") != std::string::npos);
}

TEST_CASE("the particle filter with one seed gives the same run twice, and another seed another") {
  app::course::DemoLocalizeInput in;
  in.world = kLoc5x5;
  in.particles = 250;
  in.seed = 5;
  const std::string once = app::course::run_demo_localize(in).text;
  CHECK(app::course::run_demo_localize(in).text == once);
  in.seed = 6;
  CHECK(app::course::run_demo_localize(in).text != once);
}

TEST_CASE("options that do not apply are refused, one line naming the option") {
  app::course::DemoLocalizeInput in;
  in.world = kLoc5x5;
  in.particles = 10;
  in.explain = true;
  CHECK_THROWS_WITH_AS(app::course::run_demo_localize(in), doctest::Contains("--explain"), common::InputError);
  app::course::DemoTrilaterateInput tri;
  tri.noise_m = 0.1;
  CHECK_THROWS_WITH_AS(app::course::run_demo_trilaterate(tri), doctest::Contains("--noise applies with --pose"), common::InputError);
  tri = {};
  tri.distances = std::string("3,-,2");
  CHECK_THROWS_WITH_AS(app::course::run_demo_trilaterate(tri), doctest::Contains("--distances"), common::InputError);
}
