// truth.png read back by libpng: the colour at the middle of every scored side, counted,
// gives the summary's wall_accuracy, and the shading of the cells its coverage.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/report/files_recorder.hpp"
#include "app/run/evaluation.hpp"
#include "app/picture/map_picture.hpp"
#include "app/run/run.hpp"
#include "app/report/truth_picture.hpp"
#include "cli_runner.hpp"
#include "png_reader.hpp"

namespace {

namespace fs = std::filesystem;
using test_png::Png;

using test_png::rgb;

struct Tally {
  int right = 0;
  int missed = 0;
  int phantom = 0;
  int unseen = 0;
  int sides() const { return right + missed + phantom + unseen; }
};

// lab4x4's 16 cells are all reachable: the scored sides are every cell's north and east
// side and the south and west edge of the maze.
Tally tally_sides(const Png &png, int cell_px, int margin, app::PointPx origin) {
  Tally t;
  const auto count = [&](int x, int y) {
    const std::vector<int> p = png.at(static_cast<int>(origin.x) - margin + x, static_cast<int>(origin.y) - margin + y);
    if (p == rgb(app::kRightWallColour)) ++t.right;
    else if (p == rgb(app::kMissedColour)) ++t.missed;
    else if (p == rgb(app::kPhantomColour)) ++t.phantom;
    else if (p == rgb(app::kUnseenColour)) ++t.unseen;
    else ++t.right;  // no bar: an opening the map learned as open
  };
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const int left = margin + x * cell_px;
      const int top = margin + (3 - y) * cell_px;
      count(left + cell_px / 2, top);            // north
      count(left + cell_px, top + cell_px / 2);  // east
      if (y == 0) count(left + cell_px / 2, top + cell_px);
      if (x == 0) count(left, top + cell_px / 2);
    }
  }
  return t;
}

int visited_cells(const Png &png, int cell_px, app::PointPx origin) {
  int visited = 0;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      // 7 px in from the cell's corner: clear of the sides (5 px each way) and a goal's frame.
      const std::vector<int> p = png.at(static_cast<int>(origin.x) + x * cell_px + 7,
                                        static_cast<int>(origin.y) + (3 - y) * cell_px + 7);
      if (p == std::vector<int>{255, 255, 255}) ++visited;
      else CHECK(p == rgb(app::kUnvisitedTone));
    }
  }
  return visited;
}

struct Case {
  const char *name;
  explore::StrategyKind strategy;
  std::int64_t max_steps;
};

// The first pixel in colour c, row by row from the top: {x, y}, or {-1, -1}.
std::pair<int, int> first_pixel_of(const test_png::Png &png, app::Rgb c) {
  for (int y = 0; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      if (png.is(x, y, c)) return {x, y};
    }
  }
  return {-1, -1};
}

}  // namespace

TEST_CASE("a side's verdict: right, missed, phantom or an unseen opening") {
  using app::LearnedSide;
  using app::SideVerdict;
  CHECK(app::judge_side(true, LearnedSide::wall) == SideVerdict::right);
  CHECK(app::judge_side(false, LearnedSide::open) == SideVerdict::right);
  CHECK(app::judge_side(true, LearnedSide::open) == SideVerdict::missed);
  CHECK(app::judge_side(true, LearnedSide::unknown) == SideVerdict::missed);
  CHECK(app::judge_side(false, LearnedSide::wall) == SideVerdict::phantom);
  CHECK(app::judge_side(false, LearnedSide::unknown) == SideVerdict::unseen_opening);
}

TEST_CASE("truth.png: the sides' colours count to the summary's wall_accuracy, the cells to its coverage") {
  const Case cases[] = {{"floodfill", explore::StrategyKind::floodfill, 0},
                        {"500 steps", explore::StrategyKind::dfs, 500},
                        {"done", explore::StrategyKind::dfs, 0}};
  for (const Case &c : cases) {
    CAPTURE(c.name);
    const fs::path dir = fs::temp_directory_path() / fmt::format("maze_mapper_truth_{}_{}", ::getpid(), c.max_steps);
    fs::remove_all(dir);
    app::RunOptions o;
    o.world = std::string(WORLDS_DIR) + "/lab4x4.txt";
    o.output.quiet = true;
    o.strategy = c.strategy;
    if (c.max_steps > 0) o.max_steps = c.max_steps;
    o.output.out_dir = dir.string();
    std::ostringstream out;
    const app::RunSummary summary = app::run_and_write(o, out);
    const nlohmann::json json = nlohmann::json::parse(test_png::read_all(dir / "summary.json"));
    const Png png = test_png::read_png(test_png::read_all(dir / "truth.png"));
    fs::remove_all(dir);
    const int cell_px = 102;
    const int margin = app::truth_side_px(cell_px);
    CHECK(margin == 10);
    const maze::Maze lab = maze::load_world(o.world).maze();
    const app::PointPx origin = app::truth_origin_px(lab, 3);
    const Tally t = tally_sides(png, cell_px, margin, origin);
    CHECK(t.sides() == 40);
    CHECK(static_cast<std::size_t>(t.right) == summary.score.sides_correct);
    CHECK(json.at("wall_accuracy") == std::round(10000.0 * t.right / t.sides()) / 100.0);
    CHECK(json.at("coverage") == std::round(10000.0 * visited_cells(png, cell_px, origin) / 16.0) / 100.0);
    if (c.max_steps == 500) {
      CHECK(t.unseen > 0);
      CHECK(t.missed > 0);
    }
    if (c.strategy == explore::StrategyKind::floodfill) CHECK(json.at("coverage") == 93.75);
  }
}

TEST_CASE("run --out: map.png, truth.png and the snapshots are one size, their map areas at one place") {
  const test_cli::TempDir dir("truth_same_size");
  for (const char *world : {"maze8x8.txt", "lab4x4.txt"}) {
    REQUIRE(test_cli::run({"run", std::string(WORLDS_DIR) + "/" + world, "--quiet", "--no-trace", "--snapshots", "2",
                           "--out", dir.path.string()})
                .status == 0);
    const test_png::Png map = test_png::read_png(test_png::read_all(dir.path / "map.png"));
    const test_png::Png truth = test_png::read_png(test_png::read_all(dir.path / "truth.png"));
    const test_png::Png snapshot = test_png::read_png(test_png::read_all(dir.path / "snapshots" / "01.png"));
    CAPTURE(world);
    CHECK(map.width == truth.width);
    CHECK(map.height == truth.height);
    CHECK(snapshot.width == map.width);
    CHECK(snapshot.height == map.height);
    // The start's green square at the same place in both: its top-left pixel.
    CHECK(first_pixel_of(map, app::kStartColour) == first_pixel_of(truth, app::kStartColour));
  }
}
