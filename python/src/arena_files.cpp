// map.png and replay.html of a Python controller's run on an arena (python/src/arena_files.hpp).

#include "arena_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "app/report/truth_picture.hpp"
#include "app/picture/metric_map_pictures.hpp"

namespace maze_mapper_python {

namespace {

// The grid a replay without a map shows, never observed: this many cells on the arena's
// longer side.
constexpr int kPathOnlyGridCells = 100;

mapping::GridGeometry geometry_of(const sensing::MetricGridSpec &spec) {
  mapping::GridGeometry g;
  g.width_cells = spec.cells_x;
  g.height_cells = spec.cells_y;
  g.subcells = 1;
  g.cell_size_m = spec.cell_m;
  g.origin = {spec.boundary.x_start_m, spec.boundary.y_start_m};
  return g;
}

bool same_grid(const sensing::MetricGridSpec &a, const sensing::MetricGridSpec &b) {
  return a.cells_x == b.cells_x && a.cells_y == b.cells_y && a.cell_m == b.cell_m &&
         a.boundary.x_start_m == b.boundary.x_start_m && a.boundary.y_start_m == b.boundary.y_start_m;
}

std::string world_name(const maze::World &world) {
  return world.file.empty() ? world.name() : std::filesystem::path(world.file).filename().string();
}

std::string map_caption(const maze::World &world, const KeptMap *kept) {
  return kept != nullptr ? fmt::format("{}: the controller's map, {}", world_name(world), kept->description())
                         : fmt::format("{}: no map kept (maze_mapper.keep_map)", world_name(world));
}

app::MetricPictureMarks picture_marks(const maze::Arena &arena, const std::vector<PoseTrace::Visit> &visits,
                                    const ArenaRunMarks &marks, const KeptMap &kept) {
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

// The frames of a run without a map: every recorded one, or every n-th (and the last) past
// kPathOnlyFrames.
std::vector<app::ReplayFrame> thinned(const std::vector<app::ReplayFrame> &frames, std::int64_t &stride) {
  stride = static_cast<std::int64_t>((frames.size() + kPathOnlyFrames - 1) / kPathOnlyFrames);
  if (stride <= 1 || frames.empty()) {
    stride = 1;
    return frames;
  }
  std::vector<app::ReplayFrame> every{frames.front()};
  for (std::size_t f = static_cast<std::size_t>(stride); f < frames.size(); f += static_cast<std::size_t>(stride)) {
    every.push_back(frames[f]);
  }
  if (every.back().step != frames.back().step) every.push_back(frames.back());
  for (app::ReplayFrame &f : every) f.changes_end = 0;
  return every;
}

// The arena's extent as a grid never observed, for a replay without a map.
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

}  // namespace

void ArenaReplayRecorder::keep(const KeptMap &kept) {
  tones_ = kept.tones();
  if (spec_.cells_x != 0 && same_grid(spec_, kept.spec())) return;
  spec_ = kept.spec();
  steps_per_frame_ = static_cast<std::int64_t>((kept.size() + 1999) / 2000);
  last_.assign(kept.size(), kept.initial_log_odds());
  changes_.clear();
  for (app::ReplayFrame &f : frames_) f.changes_end = 0;
}

void ArenaReplayRecorder::take_changes(const KeptMap *kept) {
  if (kept == nullptr || !kept->read(now_) || now_.size() != last_.size()) return;
  for (std::size_t n = 0; n < now_.size(); ++n) {
    if (now_[n] == last_[n] || !app::replay_shows_change(last_[n], now_[n], tones_)) continue;
    last_[n] = now_[n];
    changes_.push_back({static_cast<std::uint32_t>(n), now_[n]});
  }
}

void ArenaReplayRecorder::on_step(const std::vector<PoseTrace::Visit> &visits, const KeptMap *kept) {
  if (!frames_.empty() && ++rows_since_frame_ < steps_per_frame_) return;
  take_changes(kept);
  frames_.push_back({visits.size() - 1, visits.back().step, visits.back().time_s, changes_.size()});
  rows_since_frame_ = 0;
}

void ArenaReplayRecorder::finish(const std::vector<PoseTrace::Visit> &visits, const KeptMap *kept) {
  if (visits.empty()) return;
  if (frames_.empty() || frames_.back().step != visits.back().step) {
    rows_since_frame_ = steps_per_frame_;
    on_step(visits, kept);
    return;
  }
  take_changes(kept);  // what the controller changed after its last step
  frames_.back().changes_end = changes_.size();
}

std::string arena_map_png(const KeptMap &kept, const std::vector<PoseTrace::Visit> &visits,
                          const ArenaRunMarks &marks) {
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

app::ReplayInput arena_replay_input(const ArenaReplayRecorder &recorder, const KeptMap *kept,
                                    const std::vector<PoseTrace::Visit> &visits, const ArenaRunMarks &marks) {
  const maze::Arena arena = marks.world->geometry();
  app::ReplayInput in;
  in.units = app::ReplayUnits::metres;
  if (kept != nullptr) {
    in.grid = geometry_of(kept->spec());
    in.initial_log_odds = kept->initial_log_odds();
    in.tones = kept->tones();
    in.changes = recorder.changes();
    in.frames = recorder.frames();
    in.steps_per_frame = static_cast<int>(recorder.steps_per_frame());
  } else {
    in.grid = path_only_grid(arena);
    std::int64_t stride = 1;
    in.frames = thinned(recorder.frames(), stride);
    in.steps_per_frame = static_cast<int>(stride);
  }
  in.path.reserve(visits.size());
  for (const PoseTrace::Visit &v : visits) in.path.push_back({v.step, {v.x_m, v.y_m}, v.yaw_rad, v.placed});
  in.start_pose = start_visit(visits);
  for (const maze::ArenaPoint &g : arena.goals) in.goals.push_back({g.x_m, g.y_m});
  in.goal_side_m = 4.0 * marks.body_radius_m;
  in.body_radius_m = marks.body_radius_m;
  in.landmarks = app::landmark_marks(arena);
  in.solid_boundary = app::PlainGridBounds{arena.x_min_m, arena.x_max_m, arena.y_min_m, arena.y_max_m};
  in.title = marks.world->file;
  in.caption = map_caption(*marks.world, kept);
  in.steps = visits.empty() ? 0 : visits.back().step;
  in.summary = marks.summary;
  return in;
}

}  // namespace maze_mapper_python
