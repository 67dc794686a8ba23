// run --out's trace.csv mapped again by map-log: a depth and a bump run of
// lab4x4 on bumper-depth, mapped at 0.1 m cells, checked against the true maze's walls by a
// plain distance-to-segment test; map-log --out's pictures read back by libpng.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_runner.hpp"
#include "common/error.hpp"
#include "common/input_file.hpp"
#include "png_reader.hpp"
#include "app/picture/plain_grid_picture.hpp"
#include "app/run/run.hpp"
#include "maze/world/world.hpp"

namespace {

namespace fs = std::filesystem;

// `maze_mapper ARGS...`, which must succeed; its standard output.
std::string run_cli(const std::vector<std::string> &args) {
  const test_cli::Ran ran = test_cli::run(args);
  CHECK(ran.status == 0);
  return ran.out;
}

std::vector<std::vector<double>> read_grid_csv(const fs::path &path) {
  std::istringstream in(test_png::read_all(path));
  std::vector<std::vector<double>> rows;  // north row first
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) row.push_back(std::stod(f));
    rows.push_back(row);
  }
  return rows;
}

double segment_distance(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double t = std::clamp(((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
}

// The distance from (x, y) to the nearest true wall (the line along a cell side).
double wall_distance(const maze::Maze &m, double x, double y) {
  const double s = m.cell_size_m();
  double best = 1e9;
  for (int cy = 0; cy < m.height(); ++cy) {
    for (int cx = 0; cx < m.width(); ++cx) {
      const double x0 = m.origin_x_m() + cx * s, y0 = m.origin_y_m() + cy * s;
      if (m.has_wall({cx, cy}, maze::Side::north)) best = std::min(best, segment_distance(x, y, x0, y0 + s, x0 + s, y0 + s));
      if (m.has_wall({cx, cy}, maze::Side::south)) best = std::min(best, segment_distance(x, y, x0, y0, x0 + s, y0));
      if (m.has_wall({cx, cy}, maze::Side::east)) best = std::min(best, segment_distance(x, y, x0 + s, y0, x0 + s, y0 + s));
      if (m.has_wall({cx, cy}, maze::Side::west)) best = std::min(best, segment_distance(x, y, x0, y0, x0, y0 + s));
    }
  }
  return best;
}

// Of the grid's cells (cell_m over lab4x4's 4 m): the occupied ones (log-odds > 0) and how many
// of them lie within a cell of a true wall; the wall cells (a wall through the cell) and how
// many of those are occupied.
struct WallCheck {
  int occupied = 0, occupied_on_wall = 0, wall_cells = 0, wall_cells_occupied = 0, free_cells = 0;
};

WallCheck check_walls(const std::vector<std::vector<double>> &rows, const maze::Maze &m, double cell_m) {
  WallCheck c;
  const int ny = static_cast<int>(rows.size());
  for (int r = 0; r < ny; ++r) {
    for (std::size_t i = 0; i < rows[static_cast<std::size_t>(r)].size(); ++i) {
      const double l = rows[static_cast<std::size_t>(r)][i];
      const double d = wall_distance(m, (static_cast<double>(i) + 0.5) * cell_m, (ny - 1 - r + 0.5) * cell_m);
      if (l > 0.0) ++c.occupied, c.occupied_on_wall += d <= 1.5 * cell_m ? 1 : 0;
      if (l < 0.0) ++c.free_cells;
      if (d < 0.5 * cell_m) ++c.wall_cells, c.wall_cells_occupied += l > 0.0 ? 1 : 0;
    }
  }
  return c;
}

std::string trace_header(const fs::path &trace) {
  std::istringstream in(test_png::read_all(trace));
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace

TEST_CASE("map-log maps a depth run's trace.csv: the occupied cells lie on the maze's walls") {
  const test_cli::TempDir dir("trace");
  const std::string world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  const std::string run_dir = (dir.path / "run").string();
  run_cli({"run", world, "--model", "depth", "--noise", "0", "--quiet", "--out", run_dir});
  CHECK(trace_header(dir.path / "run" / "trace.csv") ==
        "step,time_s,true_x_m,true_y_m,true_yaw_rad,cell_x,cell_y,action,subcells_updated,gps_x_m,gps_y_m,"
        "imu_yaw_rad,depth_1_m,depth_2_m,depth_3_m,depth_4_m,depth_5_m,depth_6_m,depth_7_m,depth_8_m,depth_9_m");
  const std::string out = run_cli({"map-log", run_dir + "/trace.csv", "--sensor", "depth", "--cells", "40,40",
                                   "--boundary", "0,4,0,4", "--depth-angles", "60,45,30,15,0,-15,-30,-45,-60",
                                   "--out", (dir.path / "log").string()});
  CHECK(out.find("sensor depth, 40 x 40 cells") != std::string::npos);
  const maze::Maze truth = maze::load_world(world).maze();
  const WallCheck c = check_walls(read_grid_csv(dir.path / "log" / "logodds.csv"), truth, 0.1);
  MESSAGE("occupied ", c.occupied, " on a wall ", c.occupied_on_wall, "; wall cells ", c.wall_cells, " occupied ",
          c.wall_cells_occupied, "; free ", c.free_cells);
  CHECK(c.occupied > 100);
  CHECK(c.occupied_on_wall >= 0.98 * c.occupied);
  CHECK(c.wall_cells_occupied >= 0.6 * c.wall_cells);
  CHECK(c.free_cells > 600);  // the corridors: 16 cells of 1 m, less the walls' cells
}

TEST_CASE("map-log --out into the run's own directory keeps the run's files beside its own") {
  const test_cli::TempDir dir("trace");
  const std::string world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  const std::string run_dir = (dir.path / "run").string();
  run_cli({"run", world, "--model", "bump", "--noise", "0", "--quiet", "--out", run_dir});
  const test_cli::Ran ran = test_cli::run({"map-log", run_dir + "/trace.csv", "--sensor", "bump", "--cells", "20,20",
                                           "--boundary", "0,4,0,4", "--snapshots-at", "1", "--out", run_dir});
  CHECK(ran.status == 0);
  for (const char *kept : {"summary.json", "trace.csv", "map.png", "truth.png", "replay.html", "logodds.csv",
                           "logodds.png", "thresholded.txt", "thresholded.png"}) {
    INFO(kept);
    CHECK(fs::exists(dir.path / "run" / kept));
  }
}

TEST_CASE("map-log maps a bump run's trace.csv: pressed bumps lie on the maze's walls") {
  const test_cli::TempDir dir("trace");
  const std::string world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  const std::string run_dir = (dir.path / "run").string();
  run_cli({"run", world, "--model", "bump", "--noise", "0", "--quiet", "--out", run_dir});
  CHECK(trace_header(dir.path / "run" / "trace.csv").ends_with(",gps_x_m,gps_y_m,imu_yaw_rad,bump_right,bump_left,bump_front"));
  // 0.05 m cells: at 0.1 m the robot, 0.096 m from the wall it presses, stands in the contact
  // point's cell, and its steps there free it more than its presses mark it.
  run_cli({"map-log", run_dir + "/trace.csv", "--sensor", "bump", "--cells", "80,80", "--boundary", "0,4,0,4",
           "--bump-radius", "0.09", "--out", (dir.path / "log").string()});
  const maze::Maze truth = maze::load_world(world).maze();
  const WallCheck c = check_walls(read_grid_csv(dir.path / "log" / "logodds.csv"), truth, 0.05);
  MESSAGE("occupied ", c.occupied, " on a wall ", c.occupied_on_wall, "; free ", c.free_cells);
  CHECK(c.occupied >= 15);
  CHECK(c.occupied_on_wall >= 0.98 * c.occupied);
}

TEST_CASE("map-log --out: a log-odds picture per snapshot and the thresholded map, tones at known cells") {
  const test_cli::TempDir dir("map_log_png");
  const std::string log = std::string(TEST_DATA_DIR) + "/logs/room_depth.csv";
  run_cli({"map-log", log, "--cells", "25,25", "--boundary", "0,6,0,6", "--out", dir.path.string()});
  const auto rows = read_grid_csv(dir.path / "logodds.csv");
  REQUIRE(rows.size() == 25);
  const test_png::Png picture = test_png::read_png(test_png::read_all(dir.path / "logodds.png"));
  const test_png::Png thresholded = test_png::read_png(test_png::read_all(dir.path / "thresholded.png"));
  // 6 m over 600 px: 24 px a cell, north row first, where the picture's layout puts the map.
  const int cell_px = 24;
  app::PlainGrid grid;
  grid.cells_x = grid.cells_y = 25;
  grid.cell_w_m = grid.cell_h_m = 0.24;
  const app::PlainGridFrame frame = app::plain_grid_frame(grid, app::Figure{});
  CHECK(frame.cell_w_px == cell_px);
  const int left = static_cast<int>(frame.origin.x), top = static_cast<int>(frame.origin.y);
  int seen[3] = {0, 0, 0};  // occupied, free, never updated
  for (int r = 0; r < 25; ++r) {
    for (int i = 0; i < 25; ++i) {
      const double l = rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)];
      const std::vector<int> p = picture.at(left + i * cell_px + cell_px / 2, top + r * cell_px + cell_px / 2);
      if (l > 0.0) {
        CHECK(p[0] <= 70);
        CHECK(p[0] == p[2]);
        ++seen[0];
      } else if (l < 0.0) {
        CHECK(p[0] >= 215);
        CHECK(p[0] == p[2]);
        ++seen[1];
      } else {
        CHECK(p == std::vector<int>{150, 160, 190});
        ++seen[2];
      }
      const int want = l >= -0.5 ? 0 : 255;
      CHECK(thresholded.at(left + i * cell_px + cell_px / 2, top + r * cell_px + cell_px / 2) ==
            std::vector<int>{want, want, want});
    }
  }
  CHECK(seen[0] > 0);
  CHECK(seen[1] > 0);
  CHECK(seen[2] > 0);
  std::vector<std::string> snapshots;
  for (const auto &entry : fs::directory_iterator(dir.path)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("logodds_step") && name.ends_with(".png")) snapshots.push_back(test_png::read_all(entry.path()));
  }
  REQUIRE(snapshots.size() == 3);
  CHECK(snapshots[0] != snapshots[1]);
  CHECK(snapshots[1] != snapshots[2]);
  CHECK(snapshots[0] != snapshots[2]);
}

TEST_CASE("demo pie --png: the updated cells in map.png's tones, as many as the CSV has") {
  const test_cli::TempDir dir("pie_png");
  fs::create_directories(dir.path);
  const std::string csv = (dir.path / "pie.csv").string(), png = (dir.path / "pie.png").string();
  const std::string out = run_cli({"demo", "pie", "--csv", csv, "--png", png});
  CHECK(out.ends_with("\nwrote " + csv + "\nwrote " + png + "\n"));
  std::istringstream in(test_png::read_all(csv));
  std::string line;
  std::getline(in, line);
  int occupied = 0, clear = 0;
  while (std::getline(in, line)) (std::stod(line.substr(line.rfind(',') + 1)) > 0.0 ? occupied : clear) += 1;
  const test_png::Png picture = test_png::read_png(test_png::read_all(png));
  const test_png::Box map = test_png::map_box(picture);
  int dark = 0, light = 0, robot = 0;
  for (int y = map.y; y < map.y + map.h; ++y) {
    for (int x = map.x; x < map.x + map.w; ++x) {
      const std::vector<int> p = picture.at(x, y);
      const bool grey = p[0] == p[1] && p[1] == p[2];
      dark += grey && p[0] <= 70 ? 1 : 0;
      light += grey && p[0] >= 215 && p[0] < 255 ? 1 : 0;
      robot += p == std::vector<int>{30, 90, 220} ? 1 : 0;
    }
  }
  REQUIRE(occupied > 0);
  REQUIRE(clear > 0);
  CHECK(robot > 0);
  // Each cell is the same square of pixels, less what the slices' edges cover: the
  // dark-to-light ratio is the occupied-to-clear one.
  const double pixels = static_cast<double>(dark) / light, cells = static_cast<double>(occupied) / clear;
  MESSAGE("dark ", dark, " light ", light, "; occupied ", occupied, " clear ", clear);
  CHECK(pixels == doctest::Approx(cells).epsilon(0.25));
}

TEST_CASE("demo cone --png: the CSV's marked cells dark, no other cell so") {
  const test_cli::TempDir dir("cone_png");
  fs::create_directories(dir.path);
  const std::string csv = (dir.path / "cone.csv").string(), png = (dir.path / "cone.png").string();
  run_cli({"demo", "cone", "--sensor", "sonar", "--pose", "0.5,0.5,30", "--csv", csv, "--png", png});
  std::istringstream in(test_png::read_all(csv));
  std::string line;
  std::getline(in, line);
  std::vector<std::pair<int, int>> marked;
  while (std::getline(in, line)) marked.emplace_back(std::stoi(line), std::stoi(line.substr(line.find(',') + 1)));
  REQUIRE(marked.size() > 10);
  // The picture spans the marked cells and the sensor's cell (10, 10 at 0.05 m), two cells
  // of margin west and south, three east and north (the cells' far edges).
  int i0 = 10, i1 = 10, j0 = 10, j1 = 10;
  for (const auto &[i, j] : marked) i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
  i0 -= 2, j0 -= 2, i1 += 3, j1 += 3;
  const test_png::Png picture = test_png::read_png(test_png::read_all(png));
  const test_png::Box map = test_png::map_box(picture);
  const int cell_px = map.h / (j1 - j0);
  REQUIRE(map.h == cell_px * (j1 - j0));
  REQUIRE(map.w == cell_px * (i1 - i0));
  int marked_dark = 0, other_dark = 0;
  for (int j = j0; j < j1; ++j) {
    for (int i = i0; i < i1; ++i) {
      const bool dark = picture.at(map.x + (i - i0) * cell_px + cell_px / 2, map.y + (j1 - 1 - j) * cell_px + cell_px / 2) ==
                        std::vector<int>{35, 35, 35};
      const bool is_marked = std::find(marked.begin(), marked.end(), std::pair{i, j}) != marked.end();
      (is_marked ? marked_dark : other_dark) += dark ? 1 : 0;
    }
  }
  CHECK(other_dark == 0);
  CHECK(marked_dark >= 0.8 * static_cast<double>(marked.size()));  // the beam's red edges cross a few
}

namespace {

// The largest difference between two grids of the same shape (1e9 when the shapes differ).
double largest_difference(const std::vector<std::vector<double>> &a, const std::vector<std::vector<double>> &b) {
  if (a.size() != b.size() || a.empty()) return 1e9;
  double worst = 0.0;
  for (std::size_t r = 0; r < a.size(); ++r) {
    if (a[r].size() != b[r].size()) return 1e9;
    for (std::size_t i = 0; i < a[r].size(); ++i) worst = std::max(worst, std::abs(a[r][i] - b[r][i]));
  }
  return worst;
}

}  // namespace

TEST_CASE("room --model depth: map-log on the run's trace.csv gives the run's grid, range or axial from an origin") {
  const std::string world = std::string(WORLDS_DIR) + "/ir_room.room";
  struct Convention {
    std::vector<std::string> room, map_log;
  };
  const std::vector<std::string> angles{"--depth-angles", "60,45,30,15,0,-15,-30,-45,-60"};
  const Convention conventions[] = {
      // rays on the rim: trace.csv's depths are ranges from the centre; a miss reads 4.09 m
      {{}, {"--depth-max", "4.09"}},
      // a depth camera 5 cm ahead and 2 cm left of the centre: its depth along the heading
      {{"--depth-reading", "axial", "--depth-origin", "0.05,0.02"},
       {"--depth-reading", "axial", "--depth-origin", "0.05,0.02", "--depth-max", "4"}},
      {{"--depth-origin", "-0.03,0"}, {"--depth-origin", "-0.03,0", "--depth-max", "4"}},
  };
  for (const Convention &c : conventions) {
    const test_cli::TempDir dir("room_depth");
    std::vector<std::string> room{"room", world, "--model", "depth", "--strategy", "wander", "--time-limit", "20",
                                  "--quiet", "-o", (dir.path / "run").string()};
    room.insert(room.end(), c.room.begin(), c.room.end());
    const std::string summary = run_cli(room);
    CHECK((c.room.empty() || summary.find("\ndepth: ") != std::string::npos));
    // The readings land where the walls are: most observed cells right against the truth
    // (about 83 % after 20 s of wander, whichever convention; read wrongly, the walls move).
    const std::size_t at = summary.find("; observed ");
    REQUIRE(at != std::string::npos);
    int right = 0, observed = 0;
    REQUIRE(std::sscanf(summary.c_str() + at, "; observed %d of %d", &right, &observed) == 2);
    CHECK(right >= 0.78 * observed);
    std::vector<std::string> log{"map-log", (dir.path / "run" / "trace.csv").string(), "--sensor", "depth", "--cells",
                                 "50,30", "--boundary", "0,5,0,3", "--out", (dir.path / "log").string()};
    log.insert(log.end(), angles.begin(), angles.end());
    log.insert(log.end(), c.map_log.begin(), c.map_log.end());
    run_cli(log);
    const auto live = read_grid_csv(dir.path / "run" / "logodds.csv");
    const auto again = read_grid_csv(dir.path / "log" / "logodds.csv");
    INFO(c.map_log.back());
    CHECK(largest_difference(live, again) < 1e-4);  // the CSVs' six decimals
    // Some cells occupied, many free: the rays saw the room.
    int occupied = 0, free_cells = 0;
    for (const auto &row : live) {
      for (const double l : row) occupied += l > 0.0 ? 1 : 0, free_cells += l < -0.1 ? 1 : 0;
    }
    CHECK(occupied > 30);
    CHECK(free_cells > 200);
  }
}

TEST_CASE("map-log: a log of NUL bytes or one endless line is refused at once, not read whole") {
  const test_cli::TempDir dir("map_log_limits");
  std::filesystem::create_directories(dir.path);
  const std::string file = (dir.path / "log.csv").string();
  const auto error = [&](const std::string &text) {
    std::ofstream(file, std::ios::binary) << text;
    try {
      test_cli::run({"map-log", file, "--boundary", "0,4,0,4"});
    } catch (const common::InputError &e) {
      return e.diagnostic().substr(file.size());
    }
    return std::string("(no error)");
  };
  CHECK(error(std::string(300'000, '\0')) == ":1:1: error: not a log (CSV) file: a NUL byte");
  CHECK(error("t,x,y,theta,bump_right,bump_left,bump_front\n" + std::string(common::kMiB + 1, '1')) ==
        ":2: error: not a log (CSV) file: line 2 is longer than 1 MiB");
}
