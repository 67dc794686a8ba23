#include "metres_files.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "app/picture/metric/map_pictures.hpp"
#include "app/picture/plain_grid_picture.hpp"
#include "app/picture/size_rules.hpp"
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

// An axis-aligned box in metres that grows to hold what is added to it.
struct Box {
  double x_min = std::numeric_limits<double>::infinity();
  double y_min = std::numeric_limits<double>::infinity();
  double x_max = -std::numeric_limits<double>::infinity();
  double y_max = -std::numeric_limits<double>::infinity();
  void add(double x_m, double y_m, double radius_m = 0.0) {
    x_min = std::min(x_min, x_m - radius_m);
    y_min = std::min(y_min, y_m - radius_m);
    x_max = std::max(x_max, x_m + radius_m);
    y_max = std::max(y_max, y_m + radius_m);
  }
};

// The robot's start: where it stood when it first moved (a supervisor may set it down first).
mapping::Point start_point(const maze::Arena &arena, const std::vector<PoseTrace::Visit> &visits) {
  if (visits.empty()) return {arena.start().x_m, arena.start().y_m};
  const PoseTrace::Visit &v = visits[start_visit(visits)];
  return {v.x_m, v.y_m};
}

std::vector<mapping::Point> goal_points(const maze::Arena &arena) {
  std::vector<mapping::Point> goals;
  for (const maze::ArenaPoint &g : arena.goals) goals.push_back({g.x_m, g.y_m});
  return goals;
}

// The solid boundary a picture draws: a walled world's; an open floor has no wall at its edge.
std::optional<app::PlainGridBounds> walled_boundary(const maze::Arena &arena) {
  if (!arena.boundary_walled) return std::nullopt;
  return app::PlainGridBounds{arena.x_min_m, arena.x_max_m, arena.y_min_m, arena.y_max_m};
}

app::MetricPictureMarks picture_marks(const maze::Arena &arena, const std::vector<PoseTrace::Visit> &visits,
                                      const MetresRunMarks &marks, const KeptMap &kept) {
  app::MetricPictureMarks m;
  const maze::ArenaPose start = arena.start();
  const std::size_t first = start_visit(visits);
  m.start = visits.empty() ? mapping::Point{start.x_m, start.y_m} : mapping::Point{visits[first].x_m, visits[first].y_m};
  m.goals = goal_points(arena);
  m.boundary = walled_boundary(arena);
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

maze::Arena shown_part(const maze::Arena &arena, const std::vector<PoseTrace::Visit> &visits) {
  if (arena.boundary_walled) return arena;
  Box box;
  for (const maze::Obstacle &o : arena.obstacles) {
    const std::array<double, 4> b = o.bounds();
    box.add(b[0], b[1]);
    box.add(b[2], b[3]);
  }
  for (const maze::ArenaDisc &d : arena.discs) box.add(d.centre_x_m, d.centre_y_m, d.radius_m);
  for (const mapping::Point &g : goal_points(arena)) box.add(g.x_m, g.y_m);
  const mapping::Point start = start_point(arena, visits);
  box.add(start.x_m, start.y_m);
  for (std::size_t k = visits.empty() ? 0 : start_visit(visits); k < visits.size(); ++k) box.add(visits[k].x_m, visits[k].y_m);
  const double margin = app::crop_margin_m(std::max(box.x_max - box.x_min, box.y_max - box.y_min));
  maze::Arena shown = arena;
  shown.x_min_m = std::max(arena.x_min_m, box.x_min - margin);
  shown.y_min_m = std::max(arena.y_min_m, box.y_min - margin);
  shown.x_max_m = std::min(arena.x_max_m, box.x_max + margin);
  shown.y_max_m = std::min(arena.y_max_m, box.y_max + margin);
  // A box wholly off the floor (a robot driven far off it) keeps the floor.
  if (!(shown.x_min_m < shown.x_max_m && shown.y_min_m < shown.y_max_m)) return arena;
  return shown;
}

namespace {

// The path driven from the start on, in pieces: none to a pose a supervisor set the robot down on.
void draw_path(app::Drawing &p, const app::PlainGridFrame &f, const std::vector<PoseTrace::Visit> &visits) {
  const double px_per_m = f.cell_w_px / f.cell_w_m;
  for (std::size_t first = start_visit(visits); first < visits.size();) {
    std::size_t end = first + 1;
    while (end < visits.size() && !visits[end].placed) ++end;
    const auto at = [&](std::size_t k) { return f.at(visits[first + k].x_m, visits[first + k].y_m); };
    if (end - first >= 2) p.polyline(end - first, at, std::max(2.0, px_per_m * 0.02), app::kPathColour);
    first = end;
  }
}

// The start (a square), the goals (frames) and the robot where it ended (a disc of its body,
// a white tick its heading), each at least the page's least mark (app/picture/size_rules.hpp).
void draw_run_marks(app::Drawing &p, const app::PlainGridFrame &f, const maze::Arena &arena,
                    const std::vector<PoseTrace::Visit> &visits, double body_radius_m) {
  const double px_per_m = f.cell_w_px / f.cell_w_m;
  const double side = std::max(f.least_mark_px, 2.0 * body_radius_m * px_per_m);
  const mapping::Point s = start_point(arena, visits);
  const app::PointPx start = f.at(s.x_m, s.y_m);
  p.fill_rect({start.x - side / 2, start.y - side / 2, side, side}, app::kStartColour);
  const double goal_side = 1.5 * side;
  for (const mapping::Point &g : goal_points(arena)) {
    const app::PointPx at = f.at(g.x_m, g.y_m);
    p.stroke_rect({at.x - goal_side / 2, at.y - goal_side / 2, goal_side, goal_side}, goal_side / 6, app::kGoalColour);
  }
  if (visits.empty()) return;
  const PoseTrace::Visit &end = visits.back();
  const app::PointPx at = f.at(end.x_m, end.y_m);
  const double r = side / 2;
  p.ringed_disc(at, r, app::kEndColour, std::max(1.0, r / 4), app::kWhite);
  p.polyline({at, {at.x + r * std::cos(end.yaw_rad), at.y - r * std::sin(end.yaw_rad)}}, std::max(1.0, r / 3),
             app::kWhite);
}

app::Figure truth_legend(const maze::World &world, const maze::Arena &shown, const std::vector<app::LandmarkMark> &landmarks,
                         bool has_path) {
  app::Figure legend;
  legend.lines.push_back(fmt::format("{}: the world and the robot's path", world.name()));
  legend.items = {{app::Swatch::box, app::kInk, "solid"}, {app::Swatch::box, app::kWhite, "free"}};
  if (has_path) legend.items.push_back({app::Swatch::line, app::kPathColour, "the robot's path"});
  legend.items.push_back({app::Swatch::square, app::kStartColour, "start"});
  if (has_path) legend.items.push_back({app::Swatch::disc, app::kEndColour, "robot"});
  if (!shown.goals.empty()) legend.items.push_back({app::Swatch::frame, app::kGoalColour, "goal"});
  for (app::LegendItem &item : app::landmark_items(landmarks)) legend.items.push_back(std::move(item));
  return legend;
}

}  // namespace

std::string world_truth_png(const maze::World &world, const std::vector<PoseTrace::Visit> &visits, double body_radius_m) {
  const maze::Arena shown = shown_part(world.geometry(), visits);
  const double cell_m = std::max(shown.width_m(), shown.height_m()) / kTruthPictureCells;
  app::PlainGrid grid;
  // Square cells (a picture's cells are whole pixels, the same across and down): the shorter
  // side covered by a whole number of them, past the shown part by less than one.
  grid.cells_x = std::max(1, static_cast<int>(std::ceil(shown.width_m() / cell_m - 1e-9)));
  grid.cells_y = std::max(1, static_cast<int>(std::ceil(shown.height_m() / cell_m - 1e-9)));
  maze::Arena a = shown;
  a.x_max_m = a.x_min_m + grid.cells_x * cell_m;
  a.y_max_m = a.y_min_m + grid.cells_y * cell_m;
  grid.x0_m = a.x_min_m;
  grid.y0_m = a.y_min_m;
  grid.cell_w_m = grid.cell_h_m = cell_m;
  grid.axes_in_metres = true;
  grid.solid_boundary = walled_boundary(shown);
  const maze::TruthRaster truth = maze::rasterise_truth(a, grid.cells_x, grid.cells_y, 0.0);
  grid.tones.resize(truth.occupied.size());
  for (std::size_t i = 0; i < grid.tones.size(); ++i) grid.tones[i] = truth.occupied[i] != 0 ? app::kInk : app::kWhite;
  const std::vector<app::LandmarkMark> landmarks = app::landmark_marks(a);
  const app::Figure legend = truth_legend(world, a, landmarks, !visits.empty());
  app::Drawing page = app::plain_grid_picture(grid, legend, [&](app::Drawing &p, const app::PlainGridFrame &f) {
    const double px_per_m = f.cell_w_px / f.cell_w_m;
    for (const app::LandmarkMark &l : landmarks) app::draw_landmark(p, l, f.at(l.at.x_m, l.at.y_m), px_per_m, f.least_mark_px);
    draw_path(p, f, visits);
    draw_run_marks(p, f, a, visits, body_radius_m);
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
  // Without a kept map the page shows the part of the world the pictures show (the crop of
  // app/picture/size_rules.hpp); a kept map's page its map's extent.
  const maze::Arena arena = shown_part(marks.world->geometry(), visits);
  app::ReplayInput in;
  frames.fill(in, path_only_grid(arena));
  if (kept == nullptr) in.world_solids = app::world_solid_boxes(arena);
  start_at(in, start_visit(visits));
  for (const maze::ArenaPoint &g : arena.goals) in.goals.push_back({g.x_m, g.y_m});
  in.goal_side_m = 4.0 * marks.body_radius_m;
  in.body_radius_m = marks.body_radius_m;
  in.landmarks = app::landmark_marks(arena);
  in.solid_boundary = walled_boundary(arena);
  in.title = marks.world->file;
  in.caption = map_caption(*marks.world, kept);
  in.summary = marks.summary;
  return in;
}

}  // namespace maze_mapper_python
