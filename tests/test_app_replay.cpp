// replay.html's data: frames of changes, quantised log-odds, the path, "</" escaped, the size
// limit; and a real run's page read back by nlohmann's parser and replayed into the map that
// map.pgm holds. The page in a browser: tests/replay_chromium.sh.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "png_reader.hpp"
#include "app/report/files_recorder.hpp"
#include "app/report/outputs.hpp"
#include "app/report/replay.hpp"
#include "app/run/run.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

mapping::GridGeometry two_cells() {
  mapping::GridGeometry g;
  g.width_cells = 2;
  g.height_cells = 1;
  g.subcells = 3;
  return g;
}

// Arrivals at steps 1 and 5; sub-cell 4 (cell 0's centre) freed at 1, 2 and 6, sub-cell 10
// (cell 1's north middle) occupied at 3.
app::GridHistory small_history() {
  app::GridHistory history(two_cells(), 0.0f);
  mapping::OccupancyGrid grid(two_cells(), 0.0f);
  history.arrived(1, {0, 0}, mapping::Heading::north);
  grid.at_index(4) = -0.847f;
  history.record(1, grid);
  grid.at_index(4) = -1.694f;
  history.record(2, grid);
  grid.at_index(10) = 0.405f;
  history.record(3, grid);
  history.arrived(5, {1, 0}, mapping::Heading::east);
  grid.at_index(4) = -2.541f;
  history.record(6, grid);
  return history;
}

app::ReplayInput input_of(const app::GridHistory &history) {
  app::ReplayInput input;
  app::add_history(input, history, 7);
  input.title = "worlds/a</script>b.txt";
  input.caption = "model cell, K 3";
  input.steps = 7;
  input.summary = {{"coverage", "100.00%"}, {"wall_accuracy", "97.50%"}};
  return input;
}

// The JSON block of a page, "<\/" read back as "</".
Json data_of(const std::string &html) {
  const std::string open = "<script type=\"application/json\" id=\"replay-data\">";
  const std::size_t from = html.find(open);
  REQUIRE(from != std::string::npos);
  const std::size_t to = html.find("</script>", from);
  REQUIRE(to != std::string::npos);
  return Json::parse(html.substr(from + open.size(), to - from - open.size()));
}

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("maze_mapper_replay_" + std::to_string(::getpid()));
  TempDir() { fs::remove_all(path); }
  ~TempDir() { fs::remove_all(path); }
};

// A quiet run of a world from worlds/ with --out dir (no trace.csv).
app::RunSummary run_into(const TempDir &dir, const std::string &world, bool replay) {
  app::RunOptions o;
  o.world = std::string(WORLDS_DIR) + "/" + world;
  o.output.quiet = true;
  o.output.trace = false;
  o.output.replay = replay;
  o.output.out_dir = dir.path.string();
  std::ostringstream out;
  return app::run_and_write(o, out);
}

}  // namespace

TEST_CASE("replay data: one frame a move, changes as (gap, 2 * centi-log-odds + occupied), the last value wins") {
  const app::GridHistory history = small_history();
  const Json d = Json::parse(app::replay_data_json(input_of(history), 1));
  CHECK(d["units"] == "cells");
  CHECK(d["width"] == 2);
  CHECK(d["k"] == 3);
  CHECK(d["initial"] == 0);
  CHECK(d["frame_note"] == "");
  CHECK(d["path"]["steps"] == Json::array({1, 5}));
  // Cell centres in mm from the grid's corner (1 m cells), headings north and east in mrad.
  CHECK(d["path"]["xy_mm"] == Json::array({500, 500, 1500, 500}));
  CHECK(d["path"]["yaw_mrad"] == Json::array({1571, 0}));
  CHECK(d["frames"]["pose"] == Json::array({0, 1}));
  CHECK(d["frames"]["step"] == Json::array({4, 7}));
  CHECK(d["frames"]["t_ms"] == Json::array({-1, -1}));
  // Frame 0, steps 1 to 4: index 4 at -1.69 (free: 2 * -169 + 0), index 10 (gap 6) at 0.41, occupied.
  CHECK(d["frames"]["changes"][0] == Json::array({4, -338, 6, 83}));
  CHECK(d["frames"]["changes"][1] == Json::array({4, -508}));
  CHECK(d["summary"][1] == Json::array({"wall_accuracy", "97.50%"}));
  // Two moves a frame: one frame, everything in it.
  const Json one = Json::parse(app::replay_data_json(input_of(history), 2));
  CHECK(one["frames"]["pose"] == Json::array({1}));
  CHECK(one["frames"]["changes"][0] == Json::array({4, -508, 6, 83}));
  CHECK(one["frame_note"] == "2 moves a frame");
}

TEST_CASE("replay data in metres: poses, goals and landmarks in mm from the grid's corner, a room's frames every N steps") {
  app::ReplayInput input;
  input.units = app::ReplayUnits::metres;
  input.grid = mapping::GridGeometry{4, 2, 1, 0.25, {-1.0, 2.0}};
  input.path = {{0, {-0.5, 2.25}, 0.0}, {15, {-0.25, 2.3}, 1.5708}};
  input.changes = {{5, 0.405f}};
  input.frames = {{0, 0, 0.0, 0}, {1, 15, 0.48, 1}};
  input.steps_per_frame = 15;
  input.goals = {{-0.125, 2.375}};
  input.body_radius_m = 0.05;
  input.landmarks = {{{0.0, 2.5}, app::Rgb{255, 0, 0}, 0.1}, {{-0.5, 3.0}, std::nullopt, 0.25}};
  const Json d = Json::parse(app::replay_data_json(input, 1));
  CHECK(d["units"] == "metres");
  CHECK(d["k"] == 1);
  CHECK(d["origin"] == Json::array({-1.0, 2.0}));
  CHECK(d["path"]["xy_mm"] == Json::array({500, 250, 750, 300}));
  CHECK(d["path"]["yaw_mrad"] == Json::array({0, 1571}));
  CHECK(d["frames"]["t_ms"] == Json::array({0, 480}));
  CHECK(d["frames"]["changes"][1] == Json::array({5, 83}));
  CHECK(d["goals"] == Json::array({875, 375}));
  // The second's colour not given: -1, -1, -1 (the page draws it neutral grey).
  CHECK(d["landmarks"] == Json::array({1000, 500, 100, 255, 0, 0, 500, 1000, 250, -1, -1, -1}));
  CHECK(d["body_mm"] == 50);
  CHECK(d["frame_note"] == "a frame every 15 steps");
  CHECK(Json::parse(app::replay_data_json(input, 2))["frame_note"] == "a frame every 30 steps");
  CHECK(d["boundary_mm"] == Json::array());  // no solid boundary given: no wall band
  input.solid_boundary = app::PlainGridBounds{-1.0, 0.0, 2.0, 2.5};  // x from -1 to 0, y from 2 to 2.5
  CHECK(Json::parse(app::replay_data_json(input, 1))["boundary_mm"] == Json::array({0, 0, 1000, 500}));
}

TEST_CASE("replay data: the poses a supervisor set the robot down on are listed, and the start mark's pose") {
  app::ReplayInput input;
  input.units = app::ReplayUnits::metres;
  input.grid = mapping::GridGeometry{4, 2, 1, 0.25, {-1.0, 2.0}};
  input.path = {{1, {0.0, 0.0}, 0.0}, {2, {-0.5, 2.25}, 0.0, true}, {3, {-0.25, 2.3}, 0.0}};
  input.frames = {{0, 1, 0.032, 0}};
  const Json plain = Json::parse(app::replay_data_json(input, 1));
  CHECK(plain["path"]["placed"] == Json::array({1}));
  CHECK(plain["path"]["start"] == 0);
  input.start_pose = 1;
  CHECK(Json::parse(app::replay_data_json(input, 1))["path"]["start"] == 1);
  input.path[1].placed = false;
  CHECK(Json::parse(app::replay_data_json(input, 1))["path"]["placed"] == Json::array());
}

TEST_CASE("replay page: self-contained, the data's \"</\" escaped; over the size limit more moves a frame, then none") {
  const app::GridHistory history = small_history();
  app::ReplayInput input = input_of(history);
  const std::optional<app::Replay> page = app::replay_html(input);
  REQUIRE(page);
  CHECK(page->frames_merged == 1);
  CHECK(page->html.find("worlds/a<\\/script>b.txt") != std::string::npos);
  CHECK(page->html.find("a</script>") == std::string::npos);
  CHECK(page->html.find("<input type=\"range\" id=\"step\"") != std::string::npos);
  CHECK(page->html.find("src=") == std::string::npos);
  CHECK(page->html.find("http") == std::string::npos);
  CHECK(data_of(page->html)["title"] == "worlds/a</script>b.txt");

  input.max_bytes = page->html.size() - 1;  // one frame fewer is smaller
  const std::optional<app::Replay> halved = app::replay_html(input);
  REQUIRE(halved);
  CHECK(halved->frames_merged == 2);
  input.max_bytes = 100;
  CHECK_FALSE(app::replay_html(input));
}

TEST_CASE("run --out: replay.html has a frame a move, and its changes replayed give map.pgm's map") {
  const TempDir dir;
  const app::RunSummary summary = run_into(dir, "maze8x8.txt", true);
  const Json d = data_of(test_png::read_all(dir.path / "replay.html"));
  CHECK(d["frames"]["pose"].size() == static_cast<std::size_t>(summary.moves) + 1);
  CHECK(d["frame_note"] == "");
  CHECK(d["steps"] == summary.steps);
  const int k = d["k"], w = d["width"], h = d["height"];
  std::vector<int> value(static_cast<std::size_t>(w * h * k * k), -1);  // -1: never observed
  for (const Json &frame : d["frames"]["changes"]) {
    long index = 0;
    for (std::size_t i = 0; i + 1 < frame.size(); i += 2) {
      index += frame[i].get<long>();
      value[static_cast<std::size_t>(index)] = frame[i + 1].get<int>() & 1;
    }
  }
  // map.pgm: 0 occupied, 254 free, 205 never observed; north row first.
  const std::string pgm = test_png::read_all(dir.path / "map.pgm");
  const std::string pixels = pgm.substr(pgm.size() - value.size());
  const mapping::OccupancyGrid layout(mapping::GridGeometry{w, h, k, 1.0, {}}, 0.0f);
  int checked = 0;
  for (int row = 0; row < h * k; ++row) {
    for (int col = 0; col < w * k; ++col) {
      const int v = value[layout.index(mapping::SubCell{col, h * k - 1 - row})];
      const auto pixel = static_cast<unsigned char>(pixels[static_cast<std::size_t>(row * w * k + col)]);
      CHECK(pixel == (v < 0 ? 205 : v == 1 ? 0 : 254));
      ++checked;
    }
  }
  CHECK(checked == 24 * 24);
}

TEST_CASE("--no-replay writes no replay.html") {
  const TempDir dir;
  run_into(dir, "lab4x4.txt", false);
  CHECK(fs::exists(dir.path / "map.png"));
  CHECK_FALSE(fs::exists(dir.path / "replay.html"));
}

TEST_CASE("the history is kept for --snapshots, and for the replay up to kReplayMaxSubcells sub-cells") {
  app::RunOptions o;
  mapping::GridGeometry g;
  g.width_cells = 341;  // 1023 x 1023 sub-cells: fits
  g.height_cells = 341;
  CHECK(app::keeps_history(o, g));
  o.output.replay = false;
  CHECK_FALSE(app::keeps_history(o, g));
  o.output.snapshots = 3;
  CHECK(app::keeps_history(o, g));
  o.output.replay = true;
  o.output.snapshots = 0;
  g.width_cells = 342;  // 1026 x 1023: too large, a warning on stderr
  CHECK_FALSE(app::keeps_history(o, g));
}
