// map.png read back by libpng: the tones at every sub-cell agree with map.pgm's independent
// occupied / free / unknown rule for each model, one update already reads as a wall, the
// markers sit where the run went, the legend has its scale bar; the 5 x 7 font.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "app/report/files_recorder.hpp"
#include "app/picture/map_picture.hpp"
#include "app/report/outputs.hpp"
#include "app/picture/picture.hpp"
#include "app/run/run.hpp"
#include "png_reader.hpp"

namespace {

namespace fs = std::filesystem;
using test_png::Png;

struct OutDir {
  fs::path path = fs::temp_directory_path() / ("maze_mapper_map_picture_" + std::to_string(::getpid()));
  OutDir() { fs::remove_all(path); }
  ~OutDir() { fs::remove_all(path); }
};

std::vector<int> rgb(app::Rgb c) { return {c.r, c.g, c.b}; }

// The rows of a canvas as '#' (ink) and '.' (background).
std::vector<std::string> ink_rows(const app::Canvas &canvas) {
  std::vector<std::string> rows;
  for (int y = 0; y < canvas.height(); ++y) {
    std::string row;
    for (int x = 0; x < canvas.width(); ++x) row += canvas.at(x, y) == app::Rgb{255, 255, 255} ? '.' : '#';
    rows.push_back(row);
  }
  return rows;
}

struct Setup {
  const char *name;
  sensing::ModelKind model;
  const char *robot;
};

}  // namespace

TEST_CASE("map.png tones: one update reads as a wall or as free; never observed is its own tone") {
  app::MapTones t;  // the classroom increments: +0.4055 occupied, -0.8473 free
  CHECK(rgb(app::tone(0.0f, t)) == rgb(app::kUnknownTone));
  CHECK(rgb(app::tone(0.4055f, t)) == std::vector<int>{70, 70, 70});
  CHECK(rgb(app::tone(2 * 0.4055f, t)) == std::vector<int>{47, 47, 47});
  CHECK(rgb(app::tone(4 * 0.4055f, t)) == std::vector<int>{0, 0, 0});
  CHECK(rgb(app::tone(9.0f, t)) == std::vector<int>{0, 0, 0});
  CHECK(rgb(app::tone(-0.8473f, t)) == std::vector<int>{215, 215, 215});
  CHECK(rgb(app::tone(-4 * 0.8473f, t)) == std::vector<int>{255, 255, 255});
  CHECK(rgb(app::tone(0.4055f - 0.8473f, t)) == std::vector<int>{215, 215, 215});  // seen both ways: free
  // A prior above 0.5: a sub-cell still at it is never observed, not a wall.
  t.initial_log_odds = 0.4055f;
  CHECK(rgb(app::tone(0.4055f, t)) == rgb(app::kUnknownTone));
  // --threshold -0.5 (bump): -0.3 is occupied.
  t.threshold = -0.5f;
  CHECK(rgb(app::tone(-0.3f, t)) == std::vector<int>{70, 70, 70});
}

TEST_CASE("map.png, every model: each sub-cell's tone is map.pgm's class; start, end, goal and the scale bar") {
  const Setup setups[] = {{"cell", sensing::ModelKind::cell, "hambot"},
                          {"ray", sensing::ModelKind::ray, "hambot"},
                          {"bump", sensing::ModelKind::bump, "bumper-depth"},
                          {"depth", sensing::ModelKind::depth, "bumper-depth"},
                          {"pie", sensing::ModelKind::pie, "ir-ring"},
                          {"cone", sensing::ModelKind::cone, "ir-ring"}};
  for (const Setup &s : setups) {
    CAPTURE(s.name);
    const OutDir dir;
    app::RunOptions o;
    o.world = std::string(WORLDS_DIR) + "/lab4x4.txt";
    o.output.quiet = true;
    o.model.kind = s.model;
    o.robot = s.robot;
    o.output.out_dir = dir.path.string();
    std::ostringstream out;
    app::run_and_write(o, out);
    const std::string pgm = test_png::read_all(dir.path / "map.pgm");
    const std::string pixels = pgm.substr(pgm.size() - 144);  // 12 x 12 sub-cells, north row first
    const Png png = test_png::read_png(test_png::read_all(dir.path / "map.png"));
    REQUIRE(png.width == app::kMinPictureWidth);  // the map is 12 * 34 = 408 px wide
    REQUIRE(png.height > 408);
    int walls = 0;
    for (int row = 0; row < 12; ++row) {
      for (int x = 0; x < 12; ++x) {
        if (row == 10 && x == 1) continue;  // the start cell's centre, under the start mark
        // Two pixels in from the sub-cell's top-left corner: clear of the path and marks.
        const std::vector<int> p = png.at(x * 34 + 2, row * 34 + 2);
        const auto pgm_class = static_cast<unsigned char>(pixels[static_cast<std::size_t>(row * 12 + x)]);
        CAPTURE(x);
        CAPTURE(row);
        if (pgm_class == 0) {
          ++walls;
          CHECK((p[0] == p[1] && p[1] == p[2] && p[0] <= 70));
        } else if (pgm_class == 254) {
          CHECK((p[0] == p[1] && p[1] == p[2] && p[0] >= 215));
        } else {
          CHECK(p == rgb(app::kUnknownTone));
        }
      }
    }
    CHECK(walls > 20);
    CHECK(png.at(51, 10 * 34 + 17) == rgb(app::kStartColour));  // cell (0,0)
    CHECK(png.at(3 * 102 + 14, 30) == rgb(app::kGoalColour));   // the left of the frame in goal (3,3)
    // The scale bar: 1 m = one cell = 102 px, from x = 6 in the legend strip.
    bool bar = false;
    for (int y = 408; y < png.height && !bar; ++y) {
      bar = png.at(6, y)[0] < 50 && png.at(6 + 101, y)[0] < 50 && png.at(6 + 102, y)[0] > 200 &&
            png.at(6 + 50, y)[0] < 50;
    }
    CHECK(bar);
  }
}

TEST_CASE("map.png marks the end of the path with a blue disc") {
  mapping::GridGeometry g;
  g.width_cells = 3;
  g.height_cells = 2;
  const mapping::OccupancyGrid grid(g, 0.0f);
  const app::MapMarks marks{{{0, 0}, {1, 0}, {1, 1}}, {{2, 1}}, {}, {}};
  const app::Canvas canvas = app::map_picture(grid, app::MapTones{}, marks, "model cell, K 3");
  const app::PixelPoint end = app::cell_centre_px(g, {1, 1});
  CHECK(end.x == 153);
  CHECK(end.y == 51);
  CHECK(canvas.at(end.x, end.y) == app::kEndColour);
  CHECK(canvas.at(end.x + 7, end.y + 7) == app::kEndColour);
  CHECK(canvas.at(153, 80) == app::kPathColour);             // from (1,0) up to (1,1)
  CHECK(canvas.at(2, 2) == app::kUnknownTone);               // nothing observed
  CHECK(canvas.at(2 * 102 + 14, 30) == app::kGoalColour);
}

TEST_CASE("the 5 x 7 font draws its glyphs; a character it lacks is '?'") {
  app::Canvas canvas(12, 7, app::Rgb{255, 255, 255});
  canvas.text(0, 0, "K3", 1, app::Rgb{0, 0, 0});
  CHECK(ink_rows(canvas) == std::vector<std::string>{
                                "#...#.#####.",
                                "#..#.....#..",
                                "#.#.....#...",
                                "##.......#..",
                                "#.#.......#.",
                                "#..#..#...#.",
                                "#...#..###..",
                            });
  app::Canvas unknown(6, 7, app::Rgb{255, 255, 255});
  app::Canvas question(6, 7, app::Rgb{255, 255, 255});
  unknown.text(0, 0, "~", 1, app::Rgb{0, 0, 0});
  question.text(0, 0, "?", 1, app::Rgb{0, 0, 0});
  CHECK(ink_rows(unknown) == ink_rows(question));
  CHECK(app::text_width("1 m", 2) == 36);
}

TEST_CASE("scale bars are 1, 2 or 5 times a power of ten metres") {
  CHECK(app::scale_bar_length_m(102.0, 160) == 1.0);
  CHECK(app::scale_bar_length_m(102.0, 250) == 2.0);
  CHECK(app::scale_bar_length_m(10.0, 1365) == 100.0);
  CHECK(app::scale_bar_length_m(555.0, 160) == doctest::Approx(0.2));
}
