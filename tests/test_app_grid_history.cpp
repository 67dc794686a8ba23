// --snapshots: the steps they are taken at, and three pictures of one run that differ, the
// map filling in, the last one the final map.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "app/report/files_recorder.hpp"
#include "app/report/grid_history.hpp"
#include "app/picture/map_picture.hpp"
#include "app/run/run.hpp"
#include "png_reader.hpp"

namespace {

namespace fs = std::filesystem;
using test_png::Png;

// The map's part of a picture (the legend below it differs by its caption).
std::vector<unsigned char> map_part(const Png &png, int map_height) {
  return {png.rgb.begin(), png.rgb.begin() + static_cast<std::ptrdiff_t>(png.width) * map_height * 3};
}

int unknown_pixels(const Png &png, int map_height) {
  int n = 0;
  for (int y = 0; y < map_height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      if (png.is(x, y, app::kUnknownTone)) ++n;
    }
  }
  return n;
}

}  // namespace

TEST_CASE("snapshots are taken at equal fractions of the run's steps, the last at its end") {
  CHECK(app::snapshot_steps(2696, 3) == std::vector<std::int64_t>{898, 1797, 2696});
  CHECK(app::snapshot_steps(10, 1) == std::vector<std::int64_t>{10});
  CHECK(app::snapshot_steps(2, 4) == std::vector<std::int64_t>{0, 1, 1, 2});
}

TEST_CASE("the history rebuilds the grid and the path after any step") {
  mapping::GridGeometry g;
  g.width_cells = 2;
  g.height_cells = 1;
  mapping::OccupancyGrid grid(g, 0.0f);
  app::GridHistory history(g, 0.0f);
  history.arrived(1, {0, 0});
  grid.at_index(4) = 0.4f;
  history.record(1, grid);
  history.record(2, grid);  // nothing changed
  grid.at_index(4) = 0.8f;
  grid.at_index(10) = -0.8f;
  history.arrived(3, {1, 0});
  history.record(3, grid);
  CHECK(history.changes() == 3);
  CHECK(history.grid_at(0).at_index(4) == 0.0f);
  CHECK(history.grid_at(2).at_index(4) == 0.4f);
  CHECK(history.grid_at(2).at_index(10) == 0.0f);
  CHECK(history.grid_at(3).at_index(4) == 0.8f);
  CHECK(history.grid_at(3).at_index(10) == -0.8f);
  CHECK(history.path_at(2) == std::vector<mapping::Cell>{{0, 0}});
  CHECK(history.path_at(3) == std::vector<mapping::Cell>{{0, 0}, {1, 0}});
}

TEST_CASE("run --snapshots 3: three pictures that differ, the map filling in, the last the final map") {
  const fs::path dir = fs::temp_directory_path() / ("maze_mapper_snapshots_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  app::RunOptions o;
  o.world = std::string(WORLDS_DIR) + "/lab4x4.txt";
  o.output.quiet = true;
  o.output.out_dir = dir.string();
  o.output.snapshots = 3;
  std::ostringstream out;
  app::run_and_write(o, out);
  const int map_height = 12 * 34;
  std::vector<Png> shots;
  for (const char *name : {"01.png", "02.png", "03.png"}) {
    shots.push_back(test_png::read_png(test_png::read_all(dir / "snapshots" / name)));
  }
  const Png final_map = test_png::read_png(test_png::read_all(dir / "map.png"));
  CHECK(std::distance(fs::directory_iterator(dir / "snapshots"), fs::directory_iterator()) == 3);
  fs::remove_all(dir);
  CHECK(map_part(shots[0], map_height) != map_part(shots[1], map_height));
  CHECK(map_part(shots[1], map_height) != map_part(shots[2], map_height));
  CHECK(map_part(shots[0], map_height) != map_part(shots[2], map_height));
  CHECK(unknown_pixels(shots[0], map_height) > unknown_pixels(shots[1], map_height));
  CHECK(unknown_pixels(shots[1], map_height) > unknown_pixels(shots[2], map_height));
  CHECK(map_part(shots[2], map_height) == map_part(final_map, map_height));
}

TEST_CASE("with the grid's change log the history records what the whole-grid compare records") {
  mapping::GridGeometry g;
  g.width_cells = 3;
  g.height_cells = 2;
  mapping::OccupancyGrid grid(g, 0.0f);
  std::vector<std::uint32_t> written;
  grid.set_change_log(&written);
  app::GridHistory logged(g, 0.0f);
  app::GridHistory compared(g, 0.0f);
  grid.at_index(7) = 0.5f;
  grid.at_index(2) = -0.5f;
  grid.at_index(7) = 0.5f;  // written twice, one change
  CHECK(written == std::vector<std::uint32_t>{7, 2, 7});
  logged.record(1, grid, written);
  compared.record(1, grid);
  CHECK(written.empty());
  grid.at_index(2) = -0.5f;  // written, unchanged
  grid.at_index(40) = 1.0f;
  logged.record(2, grid, written);
  compared.record(2, grid);
  REQUIRE(logged.changes() == compared.changes());
  for (std::size_t i = 0; i < logged.changes(); ++i) {
    CHECK(logged.change_log()[i].step == compared.change_log()[i].step);
    CHECK(logged.change_log()[i].index == compared.change_log()[i].index);
    CHECK(logged.change_log()[i].value == compared.change_log()[i].value);
  }
  const mapping::OccupancyGrid copy = grid;  // a copy logs nothing
  mapping::OccupancyGrid other = copy;
  other.at_index(3) = 1.0f;
  CHECK(written.empty());
}
