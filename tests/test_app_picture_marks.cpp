// The size rule of every picture's marks (app/picture/size_rules.hpp) and the goal points a
// room's world names, drawn: a room picture's start and goal scale with its page, not a few
// pixels; `room --out` draws the world's goal in map.png and truth.png and hands it to
// replay.html with the rule's numbers. About 2 s.

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/picture/figure.hpp"
#include "app/picture/map_picture.hpp"
#include "app/picture/metric/map_pictures.hpp"
#include "app/picture/plain_grid_picture.hpp"
#include "app/picture/size_rules.hpp"
#include "cli_runner.hpp"
#include "mapping/sensor_model.hpp"
#include "png_reader.hpp"
#include "sensing/metric/map.hpp"

namespace {

using test_png::rgb;

// The run of pixels in colour c along row y through x (0 when (x, y) is not in c).
int run_across(const test_png::Png &png, int x, int y, app::Rgb c) {
  if (!png.is(x, y, c)) return 0;
  int left = x;
  int right = x;
  while (left > 0 && png.at(left - 1, y) == rgb(c)) --left;
  while (right + 1 < png.width && png.at(right + 1, y) == rgb(c)) ++right;
  return right - left + 1;
}

// Pixels in colour c within `half` px of (x, y).
int pixels_near(const test_png::Png &png, app::PointPx at, int half, app::Rgb c) {
  int n = 0;
  for (int y = static_cast<int>(at.y) - half; y <= static_cast<int>(at.y) + half; ++y) {
    for (int x = static_cast<int>(at.x) - half; x <= static_cast<int>(at.x) + half; ++x) {
      if (x >= 0 && y >= 0 && x < png.width && y < png.height && png.is(x, y, c)) ++n;
    }
  }
  return n;
}

// The frame a room picture of a side_m square walled at its edge draws its map in.
app::PlainGridFrame square_room_frame(double side_m, double cell_m) {
  app::PlainGrid grid;
  grid.cells_x = grid.cells_y = static_cast<int>(std::lround(side_m / cell_m));
  grid.cell_w_m = grid.cell_h_m = cell_m;
  grid.axes_in_metres = true;
  grid.solid_boundary = app::PlainGridBounds{0.0, side_m, 0.0, side_m};
  return app::plain_grid_frame(grid, app::Figure{});
}

struct MarkSizes {
  int start_px = 0;
  int page_height_px = 0;
  double least_mark_px = 0.0;
};

// map.png of a never-observed side_m square room of cell_m cells, the start at its middle.
MarkSizes start_mark_of_room(double side_m, double cell_m) {
  const mapping::SensorModel model{mapping::SensorModelOptions{}};
  const sensing::MetricMap map(sensing::metric_grid_from_resolution({0.0, side_m, 0.0, side_m}, cell_m), model);
  app::MetricPictureMarks marks;
  marks.start = {side_m / 2, side_m / 2};
  marks.goals = {{side_m / 4, side_m / 4}};
  marks.boundary = app::PlainGridBounds{0.0, side_m, 0.0, side_m};
  marks.caption = "a square room";
  const app::MetricRobotMarks robot{{}, {}, {side_m * 0.75, side_m * 0.75}, 0.0};
  const test_png::Png png = test_png::read_png(app::metric_map_picture(map, robot, app::MapTones{}, marks));
  const app::PlainGridFrame frame = square_room_frame(side_m, cell_m);
  const app::PointPx start = frame.at(side_m / 2, side_m / 2);
  return {run_across(png, static_cast<int>(start.x), static_cast<int>(start.y), app::kStartColour), png.height,
          frame.least_mark_px};
}

nlohmann::json replay_data(const std::filesystem::path &page_path) {
  const std::string page = test_png::read_all(page_path);
  const std::string open = "<script type=\"application/json\" id=\"replay-data\">";
  const std::size_t begin = page.find(open) + open.size();
  REQUIRE(begin > open.size());
  return nlohmann::json::parse(page.substr(begin, page.find("</script>", begin) - begin));
}

}  // namespace

TEST_CASE("size rule: a mark is at least 0.6 of the page's font, and the font at least a 40th of the page") {
  CHECK(app::min_mark_px(14.0) == doctest::Approx(8.4));
  CHECK(app::min_mark_px(50.0) == doctest::Approx(30.0));
  CHECK(app::crop_margin_m(2.0) == doctest::Approx(0.5));   // half a metre at least
  CHECK(app::crop_margin_m(12.0) == doctest::Approx(1.2));  // a tenth of the box
}

TEST_CASE("room pictures: the start mark scales with the page, not a few pixels of a map cell") {
  // 5 m at 0.1 m: 12 px cells on a map of some 600 px; 40 m at 0.02 m: 1 px cells on 2000 px.
  const MarkSizes small = start_mark_of_room(5.0, 0.1);
  const MarkSizes large = start_mark_of_room(40.0, 0.02);
  INFO("small page ", small.page_height_px, " px: start ", small.start_px, " px; large page ", large.page_height_px,
       " px: start ", large.start_px, " px");
  // Whole pixels of the mark's colour: its anti-aliased edges (a pixel each side) left out.
  CHECK(small.start_px >= small.least_mark_px - 2);
  CHECK(large.start_px >= large.least_mark_px - 2);
  CHECK(large.page_height_px > 2 * small.page_height_px);
  CHECK(large.start_px > 2 * small.start_px);
  // The same share of the page on both: between a 70th and a 30th of its height.
  for (const MarkSizes &m : {small, large}) {
    CHECK(m.start_px * 70 >= m.page_height_px);
    CHECK(m.start_px * 30 <= m.page_height_px);
  }
}

TEST_CASE("room --out: the world's goal point drawn in map.png and truth.png and handed to replay.html") {
  // The IR room's frontier run: its file names the goal (4.7, 2.7), which frontier does not plan to.
  const test_cli::TempDir dir("room_goal_marks");
  const std::string world = std::string(WORLDS_DIR) + "/ir_room.room";
  REQUIRE(test_cli::run({"room", world, "--quiet", "--out", dir.path.string()}).status == 0);
  app::PlainGrid grid;
  grid.cells_x = 50;
  grid.cells_y = 30;
  grid.cell_w_m = grid.cell_h_m = 0.1;
  grid.axes_in_metres = true;
  grid.solid_boundary = app::PlainGridBounds{0.0, 5.0, 0.0, 3.0};
  const app::PlainGridFrame frame = app::plain_grid_frame(grid, app::Figure{});
  const app::PointPx goal = frame.at(4.7, 2.7);
  const int half = static_cast<int>(frame.least_mark_px * 1.5);
  for (const char *name : {"map.png", "truth.png"}) {
    INFO(name);
    const test_png::Png png = test_png::read_png(test_png::read_all(dir.path / name));
    CHECK(pixels_near(png, goal, half, app::kGoalColour) > 0);
    // Not at the other corner of the room: the frame is the goal's.
    CHECK(pixels_near(png, frame.at(0.3, 0.3), half, app::kGoalColour) == 0);
  }
  const nlohmann::json data = replay_data(dir.path / "replay.html");
  CHECK(data["goals"] == nlohmann::json::array({4700, 2700}));
  CHECK(data["mark_rule"] == nlohmann::json::array({app::kMarkOfFont, app::kLeastFontPx, app::kFontShareOfHeight}));
}
