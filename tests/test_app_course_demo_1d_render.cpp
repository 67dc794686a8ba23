#include <doctest/doctest.h>

#include <unistd.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "app/course/demo_1d.hpp"
#include "app/course/demo_1d_render.hpp"

namespace {

std::vector<app::course::Demo1dCell> default_cells() {
  const app::course::Demo1dOptions o;
  return app::course::integrate(o, o.measurements_cm);
}

std::size_t count_of(const std::string &text, const std::string &what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::vector<std::string> lines_of(const std::string &text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A small well-formedness check: every tag closes in order, one root element. Returns the
// root's name, or "" when the text is not well formed.
std::string xml_root(const std::string &text) {
  std::vector<std::string> open;
  std::string root;
  for (std::size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at + 1)) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos) return "";
    const std::string tag = text.substr(at + 1, end - at - 1);
    if (tag.front() == '?') continue;
    if (tag.front() == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return "";
      open.pop_back();
      continue;
    }
    const std::string name = tag.substr(0, tag.find_first_of(" />"));
    if (open.empty()) {
      if (!root.empty()) return "";
      root = name;
    }
    if (tag.back() != '/') open.push_back(name);
  }
  return open.empty() ? root : "";
}

std::string read_file(const std::filesystem::path &path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::filesystem::path fresh_directory(const std::string &name) {
  // The process id in the name: the unit tests of other files run beside these (ctest -j).
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::size_t entries_in(const std::filesystem::path &dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto &entry : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST_CASE("demo 1d table: one line a cell, 4 decimals") {
  const std::vector<std::string> lines = lines_of(app::course::demo_1d_table(default_cells()));
  REQUIRE(lines.size() == 22);
  CHECK(lines[0] == "cell (cm)   log-odds  belief p  free  occupied");
  CHECK(lines[1] == "        0    -8.4730    0.0002    10         0");
  CHECK(lines[12] == "      110     0.7382    0.6766     2         6");
  CHECK(lines[21] == "      200     0.0000    0.5000     0         0");
}

TEST_CASE("tick_step: 1-2-5 steps with at most 10 intervals") {
  CHECK(app::course::tick_step(200) == 20);
  CHECK(app::course::tick_step(50) == 5);
  CHECK(app::course::tick_step(30) == 5);
  CHECK(app::course::tick_step(100) == 10);
  CHECK(app::course::tick_step(10000) == 1000);
  CHECK(app::course::tick_step(1) == doctest::Approx(0.1));
}

TEST_CASE("ASCII plot: one point a cell, in the row of its belief") {
  const std::string plot = app::course::ascii_belief_plot(default_cells());
  const std::vector<std::string> lines = lines_of(plot);
  REQUIRE(lines.size() == 1 + app::course::kPlotRows + 3);
  CHECK(count_of(plot, "*") == 21);
  CHECK(lines[0] == "belief p");
  CHECK(lines[1] == " 1.0 +");
  // 110 cm is cell 11, column 33 of the plot area (which starts at column 7); its belief
  // 0.6766 rounds to the 0.70 row, the 7th from the top.
  CHECK(lines[7].substr(0, 6) == " 0.7 +");
  CHECK(lines[7].find('*') == 7 + 33);
  CHECK(lines[21] == " 0.0 + *  *  *  *  *  *  *  *  *  *");
  CHECK(lines[23] == "       0     20    40    60    80   100   120   140   160   180   200");
}

TEST_CASE("ASCII plot: a single cell still draws") {
  app::course::Demo1dOptions o;
  o.length_cm = 0;
  const std::string plot = app::course::ascii_belief_plot(app::course::integrate(o, o.measurements_cm));
  CHECK(count_of(plot, "*") == 1);
}

TEST_CASE("SVG plot: a well-formed <svg> document with one circle a cell") {
  const std::vector<app::course::Demo1dCell> cells = default_cells();
  const std::string svg = app::course::svg_belief_plot(cells, "belief <after> 10 & more");
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(xml_root(svg) == "svg");
  CHECK(count_of(svg, "<circle ") == cells.size());
  CHECK(count_of(svg, "<polyline ") == 1);
  CHECK(svg.find("belief &lt;after&gt; 10 &amp; more") != std::string::npos);
  CHECK(svg.find(R"(xmlns="http://www.w3.org/2000/svg")") != std::string::npos);
}

TEST_CASE("write_file_atomically: the SVG file is written whole, nothing else is left") {
  const std::filesystem::path dir = fresh_directory("maze_mapper_test_svg");
  const std::filesystem::path file = dir / "plot.svg";
  const std::string svg = app::course::svg_belief_plot(default_cells(), "exercise");
  common::write_file_atomically(file.string(), "old content");
  common::write_file_atomically(file.string(), svg);  // replaces an existing file
  const std::string written = read_file(file);
  CHECK(written == svg);
  CHECK(xml_root(written) == "svg");
  CHECK(count_of(written, "<circle ") == 21);
  CHECK(entries_in(dir) == 1);
  std::filesystem::remove_all(dir);
}

TEST_CASE("write_file_atomically: an unwritable path is an InputError, nothing is left") {
  const std::filesystem::path dir = fresh_directory("maze_mapper_test_unwritable");
  const std::string missing = (dir / "no-such-dir" / "plot.svg").string();
  try {
    common::write_file_atomically(missing, "x");
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == "error: cannot write " + missing + ": No such file or directory");
  }
  std::filesystem::create_directory(dir / "a-directory");
  const std::string directory = (dir / "a-directory").string();
  try {
    common::write_file_atomically(directory, "x");
    FAIL("no error");
  } catch (const common::InputError &e) {
    CHECK(e.diagnostic() == "error: cannot write " + directory + ": Is a directory");
  }
  CHECK(entries_in(dir) == 1);
  CHECK(entries_in(dir / "a-directory") == 0);
  std::filesystem::remove_all(dir);
}
