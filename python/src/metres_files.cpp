#include "metres_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "app/picture/metric/map_pictures.hpp"
#include "app/picture/plain_grid_picture.hpp"
#include "app/report/truth_picture.hpp"
#include "maze/world/truth_raster.hpp"

namespace maze_mapper_python {

namespace {

// The grid a replay without a map shows, never observed: this many cells on the world's
// longer side.
constexpr int kPathOnlyGridCells = 100;
// truth.png's grid: this many cells on the world's longer side.
constexpr int kTruthPictureCells = 400;

std::string world_name(const maze::World &world) {
  return world.file.empty() ? world.name() : std::filesystem::path(world.file).filename().string();
}

std::string map_caption(const maze::World &world, const KeptMap *kept) {
  return kept != nullptr ? fmt::format("{}: the controller's map, {}", world_name(world), kept->description())
                         : fmt::format("{}: no map kept (maze_mapper.keep_map)", world_name(world));
}

app::MetricPictureMarks picture_marks(const maze::Arena &arena, const std::vector<PoseTrace::Visit> &visits,
                                      const MetresRunMarks &marks, const KeptMap &kept) {
  app::MetricPictureMarks m;
  const maze::ArenaPose start = arena.start();
  const std::size_t first = start_visit(visits);
  m.start = visits.empty() ? mapping::Point{start.x_m, start.y_m} : mapping::Point{visits[first].x_m, visits[first].y_m};
  if (!arena.goals.empty()) m.goal = mapping::Point{arena.goals[0].x_m, arena.goals[0].y_m};
  m.boundary = app::PlainGridBounds{arena.x_min_m, arena.x_max_m, arena.y_min_m, arena.y_max_m};
  m.landmarks = app::landmark_marks(arena);
  m.caption = map_caption(*marks.world, &kept);
  if (!visits.empty()) m.when = fmt::format("step {}, {:.1f} s", visits.back().step, visits.back().time_s);
  return m;
}

// The world's extent as a grid never observed, for a replay without a map.
mapping::GridGeometry path_only_grid(const maze::Arena &arena) {
  const double cell_m = std::max(arena.width_m(), arena.height_m()) / kPathOnlyGridCells;
  mapping::GridGeometry g;
  g.width_cells = std::max(1, static_cast<int>(std::ceil(arena.width_m() / cell_m - 1e-9)));
  g.height_cells = std::max(1, static_cast<int>(std::ceil(arena.height_m() / cell_m - 1e-9)));
  g.subcells = 1;
  g.cell_size_m = cell_m;
  g.origin = {arena.x_min_m, arena.y_min_m};
  return g;
}

// The replay from pose `first` on (the start a supervisor set the robot down on before it
// moved): the poses before it and the frames that end before it left out, their map changes
// shown in the first frame kept.
void start_at(app::ReplayInput &in, std::size_t first) {
  if (first == 0 || first >= in.path.size()) return;
  in.path.erase(in.path.begin(), in.path.begin() + static_cast<std::ptrdiff_t>(first));
  std::erase_if(in.frames, [first](const app::ReplayFrame &f) { return f.last_pose < first; });
  for (app::ReplayFrame &f : in.frames) f.last_pose -= first;
  in.path.front().placed = false;
}

}  // namespace

std::string world_truth_png(const maze::World &world, const std::vector<PoseTrace::Visit> &visits) {
  const maze::Arena a = world.geometry();
  const double cell_m = std::max(a.width_m(), a.height_m()) / kTruthPictureCells;
  app::PlainGrid grid;
  grid.cells_x = maze::cells_along(a.width_m(), cell_m);
  grid.cells_y = maze::cells_along(a.height_m(), cell_m);
  grid.x0_m = a.x_min_m;
  grid.y0_m = a.y_min_m;
  grid.cell_w_m = a.width_m() / grid.cells_x;
  grid.cell_h_m = a.height_m() / grid.cells_y;
  grid.axes_in_metres = true;
  grid.solid_boundary = app::PlainGridBounds{a.x_min_m, a.x_max_m, a.y_min_m, a.y_max_m};
  const maze::TruthRaster truth = maze::rasterise_truth(a, grid.cells_x, grid.cells_y, 0.0);
  grid.tones.resize(truth.occupied.size());
  for (std::size_t i = 0; i < grid.tones.size(); ++i) grid.tones[i] = truth.occupied[i] != 0 ? app::kInk : app::kWhite;
  const std::vector<app::LandmarkMark> landmarks = app::landmark_marks(a);
  app::Figure legend;
  legend.lines.push_back(fmt::format("{}: the world and the robot's path", world.name()));
  legend.items = {{app::Swatch::box, app::kInk, "solid"},
                  {app::Swatch::box, app::kWhite, "free"},
                  {app::Swatch::line, app::kPathColour, "the robot's path"}};
  for (app::LegendItem &item : app::landmark_items(landmarks)) legend.items.push_back(std::move(item));
  app::Drawing page = app::plain_grid_picture(grid, legend, [&](app::Drawing &p, const app::PlainGridFrame &f) {
    const double px_per_m = f.cell_w_px / f.cell_w_m;
    for (const app::LandmarkMark &l : landmarks) app::draw_landmark(p, l, f.at(l.at.x_m, l.at.y_m), px_per_m);
    // The path driven from the start on, in pieces: none to a pose a supervisor set the robot down on.
    for (std::size_t first = start_visit(visits); first < visits.size();) {
      std::size_t end = first + 1;
      while (end < visits.size() && !visits[end].placed) ++end;
      const auto at = [&](std::size_t k) { return f.at(visits[first + k].x_m, visits[first + k].y_m); };
      if (end - first >= 2) p.polyline(end - first, at, std::max(2.0, px_per_m * 0.02), app::kPathColour);
      first = end;
    }
  });
  return page.encode();
}

std::string kept_map_png(const KeptMap &kept, const std::vector<PoseTrace::Visit> &visits, const MetresRunMarks &marks) {
  const maze::Arena arena = marks.world->geometry();
  const sensing::MetricMap map = kept.metric_map();
  // The path from the start on, in pieces: a pose a supervisor set the robot down on starts one.
  std::vector<mapping::Point> trajectory;
  std::vector<std::size_t> placed;
  trajectory.reserve(visits.size());
  for (std::size_t k = start_visit(visits) + 1; k < visits.size(); ++k) {
    if (visits[k].placed) placed.push_back(trajectory.size());
    trajectory.push_back({visits[k].x_m, visits[k].y_m});
  }
  const app::MetricPictureMarks picture = picture_marks(arena, visits, marks, kept);
  app::MetricRobotMarks robot{trajectory, {}, picture.start, arena.start().yaw_rad, placed};
  if (!visits.empty()) {
    robot.position = {visits.back().x_m, visits.back().y_m};
    robot.yaw_rad = visits.back().yaw_rad;
  }
  return app::metric_map_picture(map, robot, kept.tones(), picture);
}

app::ReplayInput metres_replay_input(const app::MapFrames &frames, const KeptMap *kept,
                                     const std::vector<PoseTrace::Visit> &visits, const MetresRunMarks &marks) {
  const maze::Arena arena = marks.world->geometry();
  app::ReplayInput in;
  frames.fill(in, path_only_grid(arena));
  if (kept == nullptr) in.world_solids = app::world_solid_boxes(arena);
  start_at(in, start_visit(visits));
  for (const maze::ArenaPoint &g : arena.goals) in.goals.push_back({g.x_m, g.y_m});
  in.goal_side_m = 4.0 * marks.body_radius_m;
  in.body_radius_m = marks.body_radius_m;
  in.landmarks = app::landmark_marks(arena);
  in.solid_boundary = app::PlainGridBounds{arena.x_min_m, arena.x_max_m, arena.y_min_m, arena.y_max_m};
  in.title = marks.world->file;
  in.caption = map_caption(*marks.world, kept);
  in.summary = marks.summary;
  return in;
}

}  // namespace maze_mapper_python
