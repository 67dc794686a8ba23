// compare's table, --quiet and --out; plan --out's plan.png and plan.csv.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_runner.hpp"
#include "common/error.hpp"
#include "png_reader.hpp"
#include "app/picture/map_picture.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const std::string &text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> fields_of(const std::string &line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  return fields;
}

const std::string kWorld = std::string(WORLDS_DIR) + "/lab4x4.txt";

}  // namespace

TEST_CASE("compare: a heading per K over the maps, the summaries as one table, its keys lined up") {
  const test_cli::Ran ran = test_cli::run({"compare", kWorld, "--subcells", "3,5", "--noise", "0"});
  CHECK(ran.status == 0);
  const auto lines = lines_of(ran.out);
  REQUIRE(lines.size() > 30);
  CHECK(lines[0].starts_with("K 3"));
  CHECK(lines[0].find("K 5") == std::string("WWWWWWWWWWWW   ").size());
  // The table: the key column, then a column per K, each value under its heading.
  std::size_t heading = 0;
  while (heading < lines.size() && !(lines[heading].starts_with(" ") && lines[heading].find("K 3") != std::string::npos)) ++heading;
  REQUIRE(heading < lines.size());
  const std::size_t k3 = lines[heading].find("K 3"), k5 = lines[heading].find("K 5");
  bool saw_subcells = false;
  for (std::size_t n = heading + 1; n + 1 < lines.size(); ++n) {
    const std::string &row = lines[n];
    CHECK(row[k3 - 1] == ' ');
    CHECK(row[k5 - 1] == ' ');
    if (row.starts_with("subcells ")) {
      saw_subcells = true;
      CHECK(row.substr(k3, 1) == "3");
      CHECK(row.substr(k5) == "5");
    }
    if (row.starts_with("coverage ")) CHECK(row.substr(k5) == "100.00%");
  }
  CHECK(saw_subcells);
  CHECK(lines.back().starts_with("wall_time_ms: "));
}

TEST_CASE("compare --quiet --out DIR: the table alone, without the time; compare.csv a row per K, run --out's files in DIR/kK/") {
  const test_cli::TempDir dir("compare_out");
  const test_cli::Ran ran =
      test_cli::run({"compare", kWorld, "--subcells", "3,5", "--noise", "0", "--quiet", "--out", dir.path.string()});
  CHECK(ran.status == 0);
  CHECK(ran.out.find("WWW") == std::string::npos);
  CHECK(ran.out.find("wall_accuracy ") != std::string::npos);
  CHECK(ran.out.find("wall_time_ms") == std::string::npos);
  const auto csv = lines_of(test_png::read_all(dir.path / "compare.csv"));
  REQUIRE(csv.size() == 3);
  const auto header = fields_of(csv[0]);
  REQUIRE(header.size() > 4);
  CHECK(header[0] == "k");
  std::size_t subcells = 0;
  while (subcells < header.size() && header[subcells] != "subcells") ++subcells;
  REQUIRE(subcells < header.size());
  for (const std::string k : {"3", "5"}) {
    const auto row = fields_of(csv[k == "3" ? 1 : 2]);
    CHECK(row.size() == header.size());
    CHECK(row[0] == k);
    CHECK(row[subcells] == k);
    CHECK(fs::exists(dir.path / ("k" + k) / "map.png"));
    CHECK(fs::exists(dir.path / ("k" + k) / "summary.json"));
    CHECK_FALSE(fs::exists(dir.path / ("k" + k) / "trace.csv"));
  }
}

TEST_CASE("plan --out DIR: plan.csv from the start's centre to the goal's, plan.png draws it in magenta") {
  const test_cli::TempDir dir("plan_out");
  const test_cli::Ran ran = test_cli::run({"plan", kWorld, "--noise", "0", "--out", dir.path.string()});
  CHECK(ran.status == 0);
  const auto csv = lines_of(test_png::read_all(dir.path / "plan.csv"));
  REQUIRE(csv.size() > 3);
  CHECK(csv[0] == "index,subcell_x,subcell_y,x_m,y_m");
  const test_png::Png png = test_png::read_png(test_png::read_all(dir.path / "plan.png"));
  const int scale = 34;  // ceil(100 / K) px a sub-cell at K 3
  const int height_subcells = 12;
  mapping::GridGeometry lab;  // the map's corner in the picture, right of the y axis's labels
  lab.width_cells = lab.height_cells = 4;
  const int left = static_cast<int>(app::map_origin_px(lab).x), top = static_cast<int>(app::map_origin_px(lab).y);
  int previous_x = -1, previous_y = -1;
  for (std::size_t n = 1; n < csv.size(); ++n) {
    const auto f = fields_of(csv[n]);
    REQUIRE(f.size() == 5);
    const int x = std::stoi(f[1]), y = std::stoi(f[2]);
    CHECK(std::stoi(f[0]) == static_cast<int>(n - 1));
    CHECK(std::stod(f[3]) == doctest::Approx((x + 0.5) / 3.0).epsilon(1e-4));  // 4 decimals
    CHECK(std::stod(f[4]) == doctest::Approx((y + 0.5) / 3.0).epsilon(1e-4));
    if (previous_x >= 0) CHECK(std::abs(x - previous_x) + std::abs(y - previous_y) >= 1);
    if (previous_x >= 0) CHECK(std::max(std::abs(x - previous_x), std::abs(y - previous_y)) == 1);
    // The path's sub-cells in magenta; the last one the plan's end, a white disc ringed in it.
    const std::vector<int> want = n + 1 < csv.size() ? std::vector<int>{200, 0, 200} : std::vector<int>{255, 255, 255};
    CHECK(png.at(left + x * scale + scale / 2, top + (height_subcells - 1 - y) * scale + scale / 2) == want);
    previous_x = x, previous_y = y;
  }
  const auto first = fields_of(csv[1]);
  CHECK(first[1] == "1");  // the start (0,0)'s centre sub-cell at K 3
  CHECK(first[2] == "1");
  CHECK(fs::exists(dir.path / "map.png"));
}

// Regression (the trust sweep): `compare --subcells ""` compared nothing and exited 0,
// `run --out ""` wrote no file and `run ""` ran the default world, silently. A value typed
// empty is refused for every option and positional (app/cli/cli_errors.hpp).
TEST_CASE("an option's value typed empty is an error, not the option left out") {
  CHECK_THROWS_WITH_AS(test_cli::run({"compare", kWorld, "--subcells", ""}), "--subcells must not be empty",
                       common::InputError);
  CHECK_THROWS_WITH_AS(test_cli::run({"run", kWorld, "--out", ""}), "--out must not be empty", common::InputError);
  CHECK_THROWS_WITH_AS(test_cli::run({"run", ""}), "WORLD must not be empty", common::InputError);
  CHECK_THROWS_WITH_AS(test_cli::run({"batch", kWorld, "--csv", ""}), "--csv must not be empty", common::InputError);
  CHECK_THROWS_WITH_AS(test_cli::run({"demo", "1d", "--measurements", ""}), "--measurements must not be empty",
                       common::InputError);
}
