// map.png read back by libpng: the tones at every sub-cell agree with map.pgm's independent
// occupied / free / unknown rule for each model, one update already reads as a wall, the
// markers sit where the run went, the legend has its scale bar and its colour bar; text is
// drawn; the formats.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app/report/files_recorder.hpp"
#include "app/picture/map_picture.hpp"
#include "app/report/outputs.hpp"
#include "app/picture/drawing.hpp"
#include "app/picture/figure.hpp"
#include "app/picture/plain_grid_picture.hpp"
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

using test_png::rgb;

// Whether two colours are within `tolerance` in every channel (anti-aliased edges, blocks).
bool near(const std::vector<int> &a, app::Rgb b, int tolerance = 8) {
  return std::abs(a[0] - b.r) <= tolerance && std::abs(a[1] - b.g) <= tolerance && std::abs(a[2] - b.b) <= tolerance;
}
bool near(app::Rgb a, app::Rgb b, int tolerance = 8) { return near(std::vector<int>{a.r, a.g, a.b}, b, tolerance); }

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
    mapping::GridGeometry g;
    g.width_cells = g.height_cells = 4;
    const app::PointPx origin = app::map_origin_px(g);
    const int left = static_cast<int>(origin.x);
    const int top = static_cast<int>(origin.y);
    REQUIRE(png.width > left + 408);  // the map is 12 * 34 = 408 px wide, the axes at its left
    REQUIRE(png.height > top + 408);
    int walls = 0;
    for (int row = 0; row < 12; ++row) {
      for (int x = 0; x < 12; ++x) {
        if (row == 10 && x == 1) continue;  // the start cell's centre, under the start mark
        // Two pixels in from the sub-cell's top-left corner: clear of the path and marks.
        const std::vector<int> p = png.at(left + x * 34 + 2, top + row * 34 + 2);
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
    CHECK(png.at(left + 51, top + 10 * 34 + 17) == rgb(app::kStartColour));  // cell (0,0)
    CHECK(near(png.at(left + 3 * 102 + 15, top + 30), app::kGoalColour));    // the left of the frame in goal (3,3)
    // The scale bar: 1 m = one cell = 102 px, as many metres as a third of the page holds,
    // from the legend's left padding (the font size).
    const int x0 = static_cast<int>(app::layout_figure(app::map_figure(g, app::MapTones{}, {}, "")).font_px);
    const int length = static_cast<int>(std::lround(app::scale_bar_length_m(102.0, png.width / 3.0) * 102.0));
    bool bar = false;
    for (int y = top + 408; y < png.height && !bar; ++y) {
      bar = png.at(x0 + 1, y)[0] < 50 && png.at(x0 + length - 2, y)[0] < 50 && png.at(x0 + length + 2, y)[0] > 200 &&
            png.at(x0 + 50, y)[0] < 50;
    }
    CHECK(bar);
    // The colour bar: somewhere under the map, a row going from white (4 free updates) to
    // black (4 occupied) through the two tones one update gives.
    bool colour_bar = false;
    for (int y = top + 408; y < png.height && !colour_bar; ++y) {
      bool white = false, light = false, dark = false, black = false;
      for (int x = 0; x < png.width; ++x) {
        const std::vector<int> p = png.at(x, y);
        if (p == std::vector<int>{255, 255, 255}) continue;
        white = white || near(p, app::Rgb{250, 250, 250}, 5);
        light = light || (white && p == std::vector<int>{215, 215, 215});
        dark = dark || (light && p == std::vector<int>{70, 70, 70});
        black = black || (dark && p[0] < 5);
      }
      colour_bar = black;
    }
    CHECK(colour_bar);
  }
}

TEST_CASE("map.png marks the robot with a blue disc at the path's last cell, the axes and legend around the map") {
  mapping::GridGeometry g;
  g.width_cells = 3;
  g.height_cells = 2;
  const mapping::OccupancyGrid grid(g, 0.0f);
  const std::vector<mapping::Cell> path{{0, 0}, {1, 0}, {1, 1}};
  const app::MapMarks marks{path, {{2, 1}}, {}, {}};
  app::Drawing page = app::map_picture(grid, app::MapTones{}, marks, "model cell, K 3");
  const app::PointPx origin = app::map_origin_px(g);
  const app::PointPx end = app::cell_centre_px(g, {1, 1});
  CHECK(end.x == origin.x + 153);
  CHECK(end.y == origin.y + 51);
  const int x = static_cast<int>(end.x), y = static_cast<int>(end.y);
  CHECK(page.at(x, y) == app::kEndColour);
  CHECK(page.at(x + 6, y + 6) == app::kEndColour);
  CHECK(near(page.at(x, y + 29), app::kPathColour));  // from (1,0) up to (1,1)
  const int left = static_cast<int>(origin.x), top = static_cast<int>(origin.y);
  CHECK(page.at(left + 2, top + 2) == app::kUnknownTone);  // nothing observed
  CHECK(near(page.at(left + 2 * 102 + 15, top + 30), app::kGoalColour));
  // The axes' labels left of and under the map: ink there, white elsewhere in the margin.
  int ink_left = 0, ink_under = 0;
  for (int yy = top; yy < top + 204; ++yy) {
    for (int xx = 0; xx < left - 2; ++xx) ink_left += page.at(xx, yy).r < 128 ? 1 : 0;
  }
  for (int yy = top + 206; yy < top + 204 + 24; ++yy) {
    for (int xx = left; xx < left + 306; ++xx) ink_under += page.at(xx, yy).r < 128 ? 1 : 0;
  }
  CHECK(ink_left > 20);
  CHECK(ink_under > 20);
}

TEST_CASE("text is drawn in a real font: letters with descenders reach below the baseline") {
  app::Drawing page(120, 40);
  page.text({4, 24}, "gy", 20, app::Rgb{0, 0, 0});
  int below = 0, above = 0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 120; ++x) {
      if (page.at(x, y).r < 128) (y > 24 ? below : above) += 1;
    }
  }
  CHECK(above > 20);
  CHECK(below > 10);  // g and y go down; the old 5 x 7 font had no descenders
  CHECK(app::text_width("goal", 20) > app::text_width("go", 20));
  CHECK(app::text_descent(20) > 2.0);
}

TEST_CASE("pictures: PNG bytes are the same on every drawing; SVG and PDF by name or extension") {
  mapping::GridGeometry g;
  g.width_cells = 2;
  g.height_cells = 2;
  const mapping::OccupancyGrid grid(g, 0.0f);
  const std::vector<mapping::Cell> path{{0, 0}, {1, 0}};
  const app::MapMarks marks{path, {{1, 1}}, {}, {}};
  const std::string a = app::map_picture(grid, app::MapTones{}, marks, "caption").encode();
  const std::string b = app::map_picture(grid, app::MapTones{}, marks, "caption").encode();
  CHECK(a == b);
  CHECK(a.rfind("\x89PNG", 0) == 0);
  const std::string svg = app::map_picture(grid, app::MapTones{}, marks, "caption", app::PictureFormat::svg).encode();
  CHECK(svg.find("<svg") != std::string::npos);
  const std::string pdf = app::map_picture(grid, app::MapTones{}, marks, "caption", app::PictureFormat::pdf).encode();
  CHECK(pdf.rfind("%PDF", 0) == 0);
  CHECK(app::picture_format_of_file("out/map.SVG") == app::PictureFormat::svg);
  CHECK(app::picture_format_of_file("a.pdf") == app::PictureFormat::pdf);
  CHECK(app::picture_format_of_file("a.png") == app::PictureFormat::png);
  CHECK(!app::picture_format_of_file("a.svg/x").has_value());
  CHECK(!app::picture_format_of_file("a.jpg").has_value());
  CHECK(app::picture_format_named("svg") == app::PictureFormat::svg);
}

TEST_CASE("the colour bar of map.png's tones: a tick at each knot, white to black") {
  const app::ColourBar bar = app::map_tone_bar(app::MapTones{}, "never observed");
  REQUIRE(bar.ticks.size() == 5);
  CHECK(bar.ticks.front().label == "-3.39");
  CHECK(bar.ticks[2].label == "0");
  CHECK(bar.ticks[2].note == "prior, p 0.5");  // where the tones jump from free to occupied
  CHECK(bar.ticks[1].note.empty());
  CHECK(bar.ticks.back().label == "+1.62");
  CHECK(bar.tones.front().r > 245);
  CHECK(bar.tones.back().r < 10);
  CHECK(bar.extra->colour == app::kUnknownTone);
}

TEST_CASE("axis labels: every 1, 2, 5, 10, ... cells, as far apart as a label needs") {
  CHECK(app::axis_step(102.0, 20.0) == 1);
  CHECK(app::axis_step(15.0, 20.0) == 2);
  CHECK(app::axis_step(5.0, 24.0) == 5);
  CHECK(app::axis_step(1.0, 30.0) == 50);
}

TEST_CASE("scale bars are 1, 2 or 5 times a power of ten metres") {
  CHECK(app::scale_bar_length_m(102.0, 160) == 1.0);
  CHECK(app::scale_bar_length_m(102.0, 250) == 2.0);
  CHECK(app::scale_bar_length_m(10.0, 1365) == 100.0);
  CHECK(app::scale_bar_length_m(555.0, 160) == doctest::Approx(0.2));
}

TEST_CASE("text on a page is at least a 40th of its height, on one page or on a shared one") {
  const app::MapTones tones;
  for (const std::pair<int, int> &size : std::vector<std::pair<int, int>>{{1, 1}, {4, 4}, {8, 8}, {64, 64}, {3, 40}, {200, 10}}) {
    const int w = size.first;  // named, not bound: CAPTURE's lambda cannot take a structured binding (C++17)
    const int h = size.second;
    const mapping::GridGeometry g{w, h, 3, 0.18, {}};
    const app::Figure map = app::map_figure(g, tones, {}, "maze8x8.txt, model cell, K 3");
    const app::FigureLayout alone = app::layout_figure(map);
    CAPTURE(w);
    CAPTURE(h);
    CHECK(alone.font_px * 40 >= alone.height);
    app::Figure taller = map;
    taller.lines = {"one", "two", "three", "four", "five"};
    const app::PageFrame page = app::shared_page({map, taller});
    CHECK(page.font_px * 40 >= page.height);
    CHECK(app::layout_figure(map, page).height == app::layout_figure(taller, page).height);
    CHECK(app::layout_figure(map, page).width == app::layout_figure(taller, page).width);
  }
}

TEST_CASE("a plain grid in metres: the axes' ticks at round metres") {
  app::PlainGrid g;
  g.cells_x = 50;
  g.cells_y = 30;
  g.cell_w_m = g.cell_h_m = 0.1;
  g.axes_in_metres = true;
  g.tones.assign(1500, app::kWhite);
  const app::Figure fig = app::plain_grid_figure(g, app::Figure{});
  REQUIRE(fig.axes);
  CHECK(fig.axes->px_per_m == doctest::Approx(120.0));  // 600 px over the longer side, 5 m
  CHECK(fig.axes->x0_m == 0.0);
  g.axes_in_metres = false;
  CHECK(app::plain_grid_figure(g, app::Figure{}).axes->px_per_m == 0.0);
}
