// Robot profiles as JSON (app/run/profile_json.hpp): print -> load round-trips exactly, and every
// bad file says where.

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "app/run/profile_json.hpp"
#include "app/run/run_options.hpp"
#include "cli_runner.hpp"
#include "common/error.hpp"
#include "common/input_file.hpp"
#include "maze/sim/profile.hpp"

namespace {

std::string load_error(const std::string &text) {
  try {
    app::profile_from_json(text, "r.json");
  } catch (const common::InputError &e) {
    return e.diagnostic();
  }
  return "no error";
}

// hambot's JSON with `from` replaced by `to` (once).
std::string edited(const std::string &from, const std::string &to) {
  std::string text = app::profile_to_json(maze::sim::default_profile());
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("profile JSON: every built-in reads back to an equal profile, bit for bit") {
  for (const maze::sim::RobotProfile &p : maze::sim::profiles()) {
    CAPTURE(p.name);
    const std::string text = app::profile_to_json(p);
    const maze::sim::RobotProfile back = app::profile_from_json(text, "p.json");
    CHECK(back == p);
    CHECK(app::profile_to_json(back) == text);
  }
}

TEST_CASE("profile JSON: units in the key names, doubles in their shortest exact form") {
  const std::string text = app::profile_to_json(maze::sim::default_profile());
  CHECK(text.find("\"wheel_radius_m\": 0.045,") != std::string::npos);
  CHECK(text.find("\"max_range_m\": 12.0,") != std::string::npos);
  CHECK(text.find("\"fov_rad\": 6.283185307179586,") != std::string::npos);
  CHECK(text.find("\"frequency_hz\": 0.0,") != std::string::npos);
  CHECK(text.find("\"resolution_m\": 0.01") != std::string::npos);
  CHECK(text.find("\"bumpers\": []") != std::string::npos);
  const std::string ir = app::profile_to_json(maze::sim::find_profile("ir-ring"));
  CHECK(ir.find("\"angle_rad\": 0.7853981633974483,") != std::string::npos);
}

TEST_CASE("profile JSON: an edited value loads") {
  const maze::sim::RobotProfile p =
      app::profile_from_json(edited("\"max_range_m\": 12.0", "\"max_range_m\": 5.5"), "r.json");
  CHECK(p.lidars.at(0).max_range_m == 5.5);
}

TEST_CASE("profile JSON: malformed JSON is FILE:LINE:COL") {
  CHECK(load_error("{\n  \"name\": \"x\",\n  oops\n}\n") ==
        "r.json:3:3: error: invalid JSON: syntax error while parsing object key - invalid literal; "
        "last read: '\"x\",<U+000A>  o'; expected string literal");
  CHECK(load_error("") == "r.json:1:1: error: invalid JSON: syntax error while parsing value - "
                          "unexpected end of input; expected '[', '{', or a literal");
  CHECK(load_error(edited("\"axle_m\": 0.184,", "\"axle_m\": 0.184")) ==
        "r.json:6:17: error: invalid JSON: syntax error while parsing object - unexpected string "
        "literal; expected '}'");
}

TEST_CASE("profile JSON: a bad value, an unknown key, a missing one or a wrong type names its key path") {
  CHECK(load_error(edited("\"max_range_m\": 12.0", "\"max_range_m\": 0.01")) ==
        "r.json: error: lidars[0].max_range_m must be greater than min_range_m (got 0.01 <= 0.05)");
  CHECK(load_error(edited("\"max_range_m\"", "\"max_rang_m\"")) ==
        "r.json: error: lidars[0].max_rang_m is not a known key (known: name, horizontal_resolution, "
        "fov_rad, min_range_m, max_range_m, noise, frequency_hz, resolution_m, height_m)");
  CHECK(load_error(edited("\"resolution_m\": 0.01", "\"resolution_m\": -1")) ==
        "r.json: error: lidars[0].resolution_m must be a finite number >= 0 (got -1)");
  CHECK(load_error(edited("\"resolution_m\": 0.01", "\"resolution_m\": \"1 cm\"")) ==
        "r.json: error: lidars[0].resolution_m must be a number");
  CHECK(load_error(edited("\"gps\": \"gps\",", "")) == "r.json: error: gps is missing");
  CHECK(load_error(edited("\"horizontal_resolution\": 360", "\"horizontal_resolution\": 360.5")) ==
        "r.json: error: lidars[0].horizontal_resolution must be a whole number");
  CHECK(load_error(edited("\"axle_m\": 0.184", "\"axle_m\": \"wide\"")) == "r.json: error: axle_m must be a number");
  CHECK(load_error(edited("\"lidars\": [", "\"lidars\": [3, ")) == "r.json: error: lidars[0] must be an object");
  CHECK(load_error("[]") == "r.json: error: the profile must be an object");
}

TEST_CASE("profile JSON: --robot names a file when it has a '/' or ends in .json") {
  CHECK(app::names_a_profile_file("robots/x"));
  CHECK(app::names_a_profile_file("x.json"));
  CHECK_FALSE(app::names_a_profile_file("hambot"));
  CHECK(app::resolve_robot("hambot-12m") == maze::sim::find_profile("hambot-12m"));
  CHECK_THROWS_WITH_AS(app::resolve_robot("no/such.json"),
                       "cannot read no/such.json: No such file or directory", common::InputError);
}

TEST_CASE("profile JSON: a run reads its profile file once, and its copies share what was read") {
  const test_cli::TempDir dir("profile_once");
  std::filesystem::create_directories(dir.path);
  const std::string file = (dir.path / "r.json").string();
  const auto write = [&file](const std::string &text) {
    std::ofstream(file) << text;
  };
  write(edited("\"max_range_m\": 12.0", "\"max_range_m\": 5.5"));
  app::RunOptions options;
  options.robot = file;
  CHECK(app::robot_profile(options).lidars.at(0).max_range_m == 5.5);
  write(edited("\"max_range_m\": 12.0", "\"max_range_m\": 7.5"));  // edited while the run goes on
  CHECK(app::robot_profile(options).lidars.at(0).max_range_m == 5.5);
  const app::RunOptions copy = options;
  CHECK(&app::robot_profile(copy) == &app::robot_profile(options));
  // Another robot named: read anew; fresh options read the file as it is now.
  options.robot = "hambot-12m";
  CHECK(app::robot_profile(options) == maze::sim::find_profile("hambot-12m"));
  app::RunOptions fresh;
  fresh.robot = file;
  CHECK(app::robot_profile(fresh).lidars.at(0).max_range_m == 7.5);
}

TEST_CASE("robot profile file: one larger than 1 MiB or holding a NUL byte is refused before it is read whole") {
  const test_cli::TempDir dir("profile_limits");
  std::filesystem::create_directories(dir.path);
  const std::string file = (dir.path / "big.json").string();
  std::ofstream(file) << std::string(common::kMiB + 1, ' ');
  CHECK_THROWS_WITH_AS(app::resolve_robot(file), "not a robot profile (JSON) file: more than 1 MiB", common::InputError);
  std::ofstream(file) << std::string(70'000, '\0');
  CHECK_THROWS_WITH_AS(app::resolve_robot(file), "not a robot profile (JSON) file: a NUL byte", common::InputError);
}
