// The course's exercises as functions (app/course/): each returns exactly the text its command
// prints, so the command line only declares options and prints; the golden files are the
// commands' outputs.

#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "app/course/demo_1d_exercise.hpp"
#include "app/course/demo_cone.hpp"
#include "app/course/demo_pie.hpp"
#include "app/course/explain.hpp"
#include "app/course/map_log.hpp"
#include "common/error.hpp"

namespace {

std::string golden(const std::string &name) {
  std::ifstream in(std::string(GOLDEN_DIR) + "/" + name);
  REQUIRE(in);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("each course exercise returns the text its command prints with the default options") {
  const mapping::SensorModelOptions model;
  CHECK(app::course::explain_text(model) == golden("explain_default.out"));
  const app::course::Demo1dInput one_d_input;
  const app::course::Demo1dOutput one_d = app::course::run_demo_1d(one_d_input);
  CHECK(one_d.text == golden("demo_1d_default.out"));
  CHECK(one_d.status == 0);
  const app::course::DemoPieInput pie;
  CHECK(app::course::run_demo_pie(pie) == golden("demo_pie_default.out"));
  const app::course::DemoConeInput cone;
  CHECK(app::course::run_demo_cone(cone) == golden("demo_cone_default.out"));
}

TEST_CASE("map-log as a function returns the golden case's text, its log named as given") {
  app::course::MapLogInput input;
  input.log_path = std::string(TEST_DATA_DIR) + "/logs/room_bump.csv";
  input.cells = "12,12";
  input.boundary = "0,6,0,6";
  input.options.bump_radius_m = 0.5;
  std::string text = golden("map_log_room_bump.out");
  const std::string golden_path = "tests/data/logs/room_bump.csv";  // as the golden case names it
  text.replace(text.find(golden_path), golden_path.size(), input.log_path);
  CHECK(app::course::run_map_log(input) == text);
}

TEST_CASE("demo cone prints the lecture's Khepera III numbers: IR 0.03 rad +-3 %, sonar 0.4 rad +-6.6 %") {
  CHECK(app::course::kKheperaIr.aperture_rad == 0.03);
  CHECK(app::course::kKheperaIr.distance_error == 0.03);
  CHECK(app::course::kKheperaSonar.aperture_rad == 0.4);
  CHECK(app::course::kKheperaSonar.distance_error == 0.066);
}

TEST_CASE("demo 1d as a function: a shuffled order that agrees with the given one is status 0") {
  app::course::Demo1dInput input;
  input.order = "shuffle";
  input.seed = 7;
  const app::course::Demo1dOutput output = app::course::run_demo_1d(input);
  CHECK(output.status == 0);
  CHECK(output.text.find("order independence: same as the given order's result") != std::string::npos);
}

TEST_CASE("a course exercise's bad option is an InputError naming it, before any text") {
  app::course::DemoConeInput cone;
  cone.sensor = "laser";
  CHECK_THROWS_WITH_AS(app::course::run_demo_cone(cone), "--sensor must be ir or sonar (got laser)", common::InputError);
  app::course::MapLogInput log;
  log.log_path = std::string(TEST_DATA_DIR) + "/logs/room_bump.csv";
  CHECK_THROWS_WITH_AS(app::course::run_map_log(log), "map-log needs --boundary XS,XE,YS,YE (m)", common::InputError);
}
