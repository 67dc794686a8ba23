// The room run's pictures (app/picture/metric/map_pictures.hpp): the wave's tones, and what
// `room --out` draws: map.png, wave.png and a picture per snapshot, with their tones at known
// cells; replay.html's frames and their size; an output over the world refused. About 2 s.

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/picture/map_picture.hpp"
#include "app/picture/plain_grid_picture.hpp"
#include "app/picture/metric/map_pictures.hpp"
#include "app/report/files_recorder.hpp"
#include "app/run/metric/run.hpp"
#include "maze/world/world.hpp"
#include "cli_runner.hpp"
#include "common/error.hpp"
#include "png_reader.hpp"

#include <nlohmann/json.hpp>

namespace {

using test_png::rgb;

// Whether any pixel of the picture is in colour c.
bool has_colour(const test_png::Png &png, app::Rgb c) {
  for (std::size_t i = 0; i + 2 < png.rgb.size(); i += 3) {
    if (png.rgb[i] == c.r && png.rgb[i + 1] == c.g && png.rgb[i + 2] == c.b) return true;
  }
  return false;
}

// Where a room picture of a grid of cells_x x cells_y cells of cell_m from (x0, y0), walled
// at its edge, puts its map (the page's layout: metric_page's font follows the map's size).
app::PlainGridFrame room_frame(int cells_x, int cells_y, double cell_m, double x0_m, double y0_m, int &band_px) {
  app::PlainGrid grid;
  grid.cells_x = cells_x;
  grid.cells_y = cells_y;
  grid.x0_m = x0_m;
  grid.y0_m = y0_m;
  grid.cell_w_m = grid.cell_h_m = cell_m;
  grid.axes_in_metres = true;
  grid.solid_boundary =
      app::PlainGridBounds{x0_m, x0_m + cells_x * cell_m, y0_m, y0_m + cells_y * cell_m};
  band_px = app::boundary_band_px(grid);
  return app::plain_grid_frame(grid, app::Figure{});
}

// The pixel of a point in metres.
std::vector<int> pixel_of(const test_png::Png &png, const app::PlainGridFrame &frame, double x_m, double y_m) {
  const app::PointPx p = frame.at(x_m, y_m);
  return png.at(static_cast<int>(p.x), static_cast<int>(p.y));
}

// The pixels off the map's colour c on the ring band_px / 2 outside the grid, all round.
int ring_pixels_not(const test_png::Png &png, const app::PlainGridFrame &frame, int cells_x, int cells_y, int band_px,
                    app::Rgb c) {
  const int left = static_cast<int>(frame.origin.x) - band_px / 2 - 1;
  const int top = static_cast<int>(frame.origin.y) - band_px / 2 - 1;
  const int right = static_cast<int>(frame.origin.x + cells_x * frame.cell_w_px) + band_px / 2;
  const int bottom = static_cast<int>(frame.origin.y + cells_y * frame.cell_h_px) + band_px / 2;
  int off = 0;
  for (int x = left; x <= right; ++x) {
    off += (png.at(x, top) != rgb(c)) + (png.at(x, bottom) != rgb(c));
  }
  for (int y = top; y <= bottom; ++y) {
    off += (png.at(left, y) != rgb(c)) + (png.at(right, y) != rgb(c));
  }
  return off;
}

}  // namespace

TEST_CASE("wave tones: blocked, goal, unreached, and light near the goal to deep blue at the farthest") {
  CHECK(rgb(app::wave_tone(1, 40)) == std::vector<int>{90, 90, 90});
  CHECK(rgb(app::wave_tone(2, 40)) == rgb(app::kGoalColour));
  CHECK(rgb(app::wave_tone(0, 40)) == std::vector<int>{255, 255, 255});
  CHECK(rgb(app::wave_tone(3, 40)) == std::vector<int>{255, 236, 170});
  CHECK(rgb(app::wave_tone(40, 40)) == std::vector<int>{20, 60, 170});
  const app::Rgb middle = app::wave_tone(22, 41);  // half way from 3 to 41: between the two
  CHECK(middle.r == 138);  // (255 + 20) / 2, rounded
  CHECK(middle.g == 148);  // (236 + 60) / 2
}

TEST_CASE("room --out: map.png, wave.png and the snapshots' pictures, tones at known cells") {
  const test_cli::TempDir dir("room_pictures");
  const std::string world = std::string(WORLDS_DIR) + "/ir_room.room";
  const test_cli::Ran ran = test_cli::run({"room", world, "--strategy", "wavefront", "--goal", "4.7,2.7",
                                           "--snapshot-steps", "50", "--snapshots-at", "1", "--quiet", "--out",
                                           dir.path.string()});
  REQUIRE(ran.status == 0);
  for (const char *name : {"map.png", "wave.png", "snapshots/step50.png", "snapshots/step50_wave.png",
                           "snapshots/t1s.png", "snapshots/t1s_wave.png"}) {
    INFO(name);
    CHECK(std::filesystem::is_regular_file(dir.path / name));
  }
  const test_png::Png map = test_png::read_png(test_png::read_all(dir.path / "map.png"));
  const test_png::Png wave = test_png::read_png(test_png::read_all(dir.path / "wave.png"));
  // 5 m over 600 px: 12 px a cell, where the picture's layout puts the map.
  app::PlainGrid grid;
  grid.cells_x = 50;
  grid.cells_y = 30;
  grid.cell_w_m = grid.cell_h_m = 0.1;
  grid.axes_in_metres = true;
  grid.solid_boundary = app::PlainGridBounds{0.0, 5.0, 0.0, 3.0};
  const app::PlainGridFrame frame = app::plain_grid_frame(grid, app::Figure{});
  REQUIRE(frame.cell_w_px == 12);
  const auto centre = [&frame](double x_m, double y_m) {
    const app::PointPx p = frame.at(x_m, y_m);
    return std::vector<int>{static_cast<int>(p.x), static_cast<int>(p.y)};
  };
  // The shelf's underside (its face at y 1.75, in the cells of row 17): occupied on the map
  // (a dark tone), blocked in the wave.
  const std::vector<int> shelf = centre(4.55, 1.75);
  CHECK(map.at(shelf[0], shelf[1])[0] < 70);
  CHECK(wave.at(shelf[0], shelf[1]) == std::vector<int>{90, 90, 90});
  // Inside the partition (1.0 ... 1.3, 0 ... 1.8): never observed, blocked in the wave.
  const std::vector<int> partition = centre(1.15, 1.0);
  CHECK(map.at(partition[0], partition[1]) == rgb(app::kUnknownTone));
  CHECK(wave.at(partition[0], partition[1]) == std::vector<int>{90, 90, 90});
  // The open middle of the room (2.0, 0.6): seen free (light); reached by the wave (neither
  // blocked nor white).
  const std::vector<int> open = centre(2.05, 0.65);
  CHECK(map.at(open[0], open[1])[0] >= 215);
  CHECK(wave.at(open[0], open[1]) != std::vector<int>{90, 90, 90});
  CHECK(wave.at(open[0], open[1]) != std::vector<int>{255, 255, 255});
  CHECK(has_colour(map, app::kStartColour));
  CHECK(has_colour(map, app::kPathColour));
  CHECK(has_colour(wave, app::kGoalColour));

  // truth.png: the shelf occupied and mapped occupied (near-black); the partition never observed.
  const test_png::Png truth = test_png::read_png(test_png::read_all(dir.path / "truth.png"));
  CHECK(truth.at(shelf[0], shelf[1]) == std::vector<int>{25, 25, 25});
  CHECK(truth.at(partition[0], partition[1]) == rgb(app::kUnknownTone));
  CHECK(truth.at(open[0], open[1]) == std::vector<int>{255, 255, 255});

  // Frontier has no wave: map.png only.
  const test_cli::TempDir frontier("room_pictures_frontier");
  REQUIRE(test_cli::run({"room", world, "--quiet", "--out", frontier.path.string()}).status == 0);
  CHECK(std::filesystem::is_regular_file(frontier.path / "map.png"));
  CHECK_FALSE(std::filesystem::exists(frontier.path / "wave.png"));
}

TEST_CASE("room --out: replay.html in metres, a frame at the start and a step on the IR room's grid, the map at the end") {
  const test_cli::TempDir dir("room_replay");
  const std::string world = std::string(WORLDS_DIR) + "/ir_room.room";
  REQUIRE(test_cli::run({"room", world, "--strategy", "wavefront", "--goal", "4.7,2.7", "--quiet", "--out",
                         dir.path.string()})
              .status == 0);
  const std::string page = test_png::read_all(dir.path / "replay.html");
  const std::string open = "<script type=\"application/json\" id=\"replay-data\">";
  const std::size_t from = page.find(open);
  REQUIRE(from != std::string::npos);
  const std::size_t begin = from + open.size();
  const nlohmann::json data = nlohmann::json::parse(page.substr(begin, page.find("</script>", begin) - begin));
  const nlohmann::json summary = nlohmann::json::parse(test_png::read_all(dir.path / "summary.json"));
  CHECK(data["units"] == "metres");
  CHECK(data["k"] == 1);
  const auto &steps = data["frames"]["step"];
  REQUIRE(steps.size() == summary["steps"].get<std::size_t>() + 1);  // 1500 cells: the start and every step
  CHECK(steps.front() == 0);
  CHECK(steps.back() == summary["steps"]);
  CHECK(data["frames"]["changes"][0].empty());  // nothing learned at the start
  CHECK(data["path"]["xy_mm"].size() == 2 * steps.size());
  CHECK(data["goals"].size() == 2);
  // Every frame's changes applied: the partition never observed, the open middle seen free.
  const long initial = data["initial"].get<long>();
  std::vector<long> cells(50 * 30, initial);
  for (const auto &frame : data["frames"]["changes"]) {
    long at = 0;
    for (std::size_t k = 0; k + 1 < frame.size(); k += 2) {
      at += frame[k].get<long>();
      cells[static_cast<std::size_t>(at)] = frame[k + 1].get<long>();
    }
  }
  CHECK(cells[10 * 50 + 11] == initial);  // (1.15, 1.05)
  const long free_value = cells[6 * 50 + 20];  // (2.05, 0.65): 2 * centi-log-odds, not occupied
  CHECK(free_value < 0);
  CHECK(free_value % 2 == 0);
}

TEST_CASE("room --out: replay.html records a cell seen every step a few dozen times, the last near the map") {
  // The IR room's frontier run: 1500 cells, a frame every step for some 2500 steps, its free
  // cells' log-odds falling an update a step to about -1000.
  const test_cli::TempDir dir("room_replay_size");
  const std::string world = std::string(WORLDS_DIR) + "/ir_room.room";
  REQUIRE(test_cli::run({"room", world, "--quiet", "--out", dir.path.string()}).status == 0);
  const std::string page = test_png::read_all(dir.path / "replay.html");
  const std::string open = "<script type=\"application/json\" id=\"replay-data\">";
  const std::size_t begin = page.find(open) + open.size();
  REQUIRE(begin > open.size());
  const nlohmann::json data = nlohmann::json::parse(page.substr(begin, page.find("</script>", begin) - begin));
  const auto steps = nlohmann::json::parse(test_png::read_all(dir.path / "summary.json"))["steps"].get<std::size_t>();
  REQUIRE(data["frames"]["step"].size() == steps + 1);  // every step a frame still
  const std::size_t width = 50, height = 30;
  std::vector<long> cells(width * height, data["initial"].get<long>());
  std::size_t changes = 0;
  for (const auto &frame : data["frames"]["changes"]) {
    long at = 0;
    for (std::size_t k = 0; k + 1 < frame.size(); k += 2, ++changes) {
      at += frame[k].get<long>();
      cells[static_cast<std::size_t>(at)] = frame[k + 1].get<long>();
    }
  }
  CHECK(changes <= 40 * cells.size());  // every cell every step would be some 800 a cell
  CHECK(page.size() <= 300 * steps + (std::size_t{100} << 10));
  // The last frame against logodds.csv (north row first): occupied alike, the log-odds within
  // one update (the free increment, the smaller) or a quarter of the map's.
  std::istringstream csv(test_png::read_all(dir.path / "logodds.csv"));
  std::string row;
  for (std::size_t j = height; j-- > 0 && std::getline(csv, row);) {
    std::istringstream fields(row);
    std::string field;
    for (std::size_t i = 0; i < width && std::getline(fields, field, ','); ++i) {
      const double map = std::stod(field);
      const long value = cells[j * width + i];
      const double shown = static_cast<double>(value >> 1) / 100.0;  // value = 2 * centi-log-odds + occupied
      CAPTURE(i);
      CAPTURE(j);
      if (std::abs(map) >= 0.01) CHECK((value & 1) == (map > 0 ? 1 : 0));  // the csv's 6 decimals: 0 may be above
      CHECK(std::abs(shown - map) <= std::max(0.41, 0.34 * std::abs(map)) + 0.01);
    }
  }
}

TEST_CASE("room --out: a world file named like an output of every run (truth.png) is refused, not overwritten") {
  const test_cli::TempDir dir("room_out_over_world");
  std::filesystem::create_directories(dir.path);
  const std::filesystem::path world = dir.path / "truth.png";
  std::filesystem::copy_file(std::string(WORLDS_DIR) + "/ir_room.room", world);
  const std::string before = test_png::read_all(world);
  CHECK_THROWS_WITH_AS(test_cli::run({"room", world.string(), "--quiet", "--out", dir.path.string()}),
                       doctest::Contains("is also an input"), common::InputError);
  CHECK(test_png::read_all(world) == before);
}

TEST_CASE("room --out: a core file an earlier run left and this one did not write is removed, the user's kept") {
  const test_cli::TempDir dir("room_out_stale");
  std::filesystem::create_directories(dir.path);
  for (const char *name : {"map.svg", "plan.csv", "notes.txt"}) {
    std::ofstream(dir.path / name) << "earlier\n";
  }
  REQUIRE(test_cli::run({"room", std::string(WORLDS_DIR) + "/ir_room.room", "--quiet", "--out", dir.path.string()})
              .status == 0);
  CHECK_FALSE(std::filesystem::exists(dir.path / "map.svg"));
  CHECK_FALSE(std::filesystem::exists(dir.path / "plan.csv"));
  CHECK(test_png::read_all(dir.path / "notes.txt") == "earlier\n");
  CHECK(std::filesystem::exists(dir.path / "logodds.csv"));
}

TEST_CASE("room --out: map.png, truth.png and wave.png are one size") {
  const test_cli::TempDir dir("room_pictures_same_size");
  const std::string world = std::string(WORLDS_DIR) + "/ir_room.room";
  REQUIRE(test_cli::run({"room", world, "--strategy", "wavefront", "--goal", "4.7,2.7", "--snapshot-steps", "50",
                         "--quiet", "--out", dir.path.string()})
              .status == 0);
  const test_png::Png map = test_png::read_png(test_png::read_all(dir.path / "map.png"));
  for (const char *name : {"truth.png", "wave.png", "snapshots/step50.png", "snapshots/step50_wave.png"}) {
    const test_png::Png other = test_png::read_png(test_png::read_all(dir.path / name));
    CAPTURE(name);
    CHECK(other.width == map.width);
    CHECK(other.height == map.height);
  }
}

TEST_CASE("room --out: the world's boundary drawn as a wall whole all round map.png, truth.png and the snapshots") {
  // The IR room's boundary, 0 ... 5 x 0 ... 3 m, is the map's edge: the walls the lidar hits
  // lie on the grid's boundary line, their cells outside the map.
  const test_cli::TempDir dir("room_pictures_boundary");
  REQUIRE(test_cli::run({"room", std::string(WORLDS_DIR) + "/ir_room.room", "--time-limit", "10", "--snapshot-steps",
                         "50", "--quiet", "--out", dir.path.string()})
              .status == 0);
  int band = 0;
  const app::PlainGridFrame frame = room_frame(50, 30, 0.1, 0.0, 0.0, band);
  CHECK(band == 12);  // a cell wide
  for (const char *name : {"map.png", "truth.png", "snapshots/step50.png"}) {
    CAPTURE(name);
    const test_png::Png png = test_png::read_png(test_png::read_all(dir.path / name));
    CHECK(ring_pixels_not(png, frame, 50, 30, band, app::kBoundaryWallColour) == 0);
  }
  // At 0.15 m the grid (34 x 20 cells) reaches 0.1 m past the east wall at 5 m: the cells
  // past it are wall too, the cells before it the map's.
  const test_cli::TempDir coarse("room_pictures_boundary_coarse");
  REQUIRE(test_cli::run({"room", std::string(WORLDS_DIR) + "/ir_room.room", "--time-limit", "10", "--resolution",
                         "0.15", "--quiet", "--out", coarse.path.string()})
              .status == 0);
  const app::PlainGridFrame coarse_frame = room_frame(34, 20, 0.15, 0.0, 0.0, band);
  const test_png::Png map = test_png::read_png(test_png::read_all(coarse.path / "map.png"));
  CHECK(ring_pixels_not(map, coarse_frame, 34, 20, band, app::kBoundaryWallColour) == 0);
  CHECK(pixel_of(map, coarse_frame, 5.05, 1.5) == rgb(app::kBoundaryWallColour));
  CHECK(pixel_of(map, coarse_frame, 4.5, 0.75) != rgb(app::kBoundaryWallColour));  // free, seen from the start
}

TEST_CASE("room --out on a world with a landmark: a disc of its colour on map.png and truth.png, and in replay.html") {
  // A walled 11 x 11 m course arena centred on the origin, a blue landmark at (-2, 3).
  const test_cli::TempDir dir("room_pictures_landmark");
  REQUIRE(test_cli::run({"room", std::string(TEST_DATA_DIR) + "/worlds/course_arena11.xml", "--time-limit", "5",
                         "--quiet", "--out", dir.path.string()})
              .status == 0);
  int band = 0;
  const app::PlainGridFrame frame = room_frame(110, 110, 0.1, -5.5, -5.5, band);
  for (const char *name : {"map.png", "truth.png"}) {
    CAPTURE(name);
    const test_png::Png png = test_png::read_png(test_png::read_all(dir.path / name));
    CHECK(pixel_of(png, frame, -2.0, 3.0) == std::vector<int>{0, 0, 255});
    CHECK(pixel_of(png, frame, -2.0 + 0.2, 3.0) == std::vector<int>{0, 0, 255});  // inside its 0.25 m
    CHECK(pixel_of(png, frame, -2.0 + 0.35, 3.0) != std::vector<int>{0, 0, 255});  // outside it
    CHECK(ring_pixels_not(png, frame, 110, 110, band, app::kBoundaryWallColour) == 0);
  }
  const std::string page = test_png::read_all(dir.path / "replay.html");
  const std::string open = "<script type=\"application/json\" id=\"replay-data\">";
  const std::size_t begin = page.find(open) + open.size();
  const nlohmann::json data = nlohmann::json::parse(page.substr(begin, page.find("</script>", begin) - begin));
  // In mm from the grid's south-west corner (-5.5, -5.5): (3500, 8500), 250 round, blue.
  CHECK(data["landmarks"] == nlohmann::json::array({3500, 8500, 250, 0, 0, 255}));
}

TEST_CASE("room run in an arena with a supervisor's cylinder: a neutral grey disc, its colour not given") {
  const test_cli::TempDir dir("room_pictures_cylinder");
  maze::Arena arena = maze::load_world(std::string(WORLDS_DIR) + "/ir_room.room").geometry();
  arena.discs.push_back({0.6, 2.4, 0.25});
  app::RunOptions o = app::metres_run_options();
  o.world = "ir_room with a cylinder";
  o.strategy = explore::StrategyKind::frontier;
  o.time_limit_s = 5.0;
  o.output.quiet = true;
  o.output.out_dir = dir.path.string();
  std::ostringstream out;
  app::FilesRecorder recorder;
  app::run_metric_arena(arena, o, out, std::chrono::steady_clock::now(), nullptr, nullptr, &recorder);
  int band = 0;
  const app::PlainGridFrame frame = room_frame(50, 30, 0.1, 0.0, 0.0, band);
  for (const char *name : {"map.png", "truth.png"}) {
    CAPTURE(name);
    const test_png::Png png = test_png::read_png(test_png::read_all(dir.path / name));
    CHECK(pixel_of(png, frame, 0.6, 2.4) == rgb(app::kLandmarkNeutralTone));
  }
  const std::string page = test_png::read_all(dir.path / "replay.html");
  CHECK(page.find("\"landmarks\":[600,2400,250,-1,-1,-1]") != std::string::npos);
}

TEST_CASE("landmarks' legend words: one for those of a given colour, one for those without") {
  const app::LandmarkMark red{{0.0, 0.0}, app::Rgb{255, 0, 0}, 0.25};
  const app::LandmarkMark unknown{{1.0, 0.0}, std::nullopt, 0.25};
  const auto labels = [](const std::vector<app::LandmarkMark> &marks) {
    std::vector<std::string> words;
    for (const app::LegendItem &item : app::landmark_items(marks)) words.push_back(item.label);
    return words;
  };
  CHECK(labels({}).empty());
  CHECK(labels({red}) == std::vector<std::string>{"landmark (its colour)"});
  CHECK(labels({unknown}) == std::vector<std::string>{"landmark, colour not given"});
  CHECK(labels({red, unknown}) == std::vector<std::string>{"landmark (its colour)", "landmark, colour not given"});
  CHECK(rgb(app::landmark_fill(unknown)) == rgb(app::kLandmarkNeutralTone));
  CHECK(rgb(app::landmark_fill(red)) == std::vector<int>{255, 0, 0});
}
