#include "app/report/map_frames.hpp"

#include <utility>

namespace app {
namespace {

bool same_grid(const sensing::MetricGridSpec &a, const sensing::MetricGridSpec &b) {
  return a.cells_x == b.cells_x && a.cells_y == b.cells_y && a.cell_m == b.cell_m &&
         a.boundary.x_start_m == b.boundary.x_start_m && a.boundary.y_start_m == b.boundary.y_start_m;
}

// Every recorded frame, or every n-th (and the last) past kPathOnlyFrames, holding no change;
// `stride` is n.
std::vector<ReplayFrame> thinned(const std::vector<ReplayFrame> &frames, std::int64_t &stride) {
  stride = static_cast<std::int64_t>((frames.size() + kPathOnlyFrames - 1) / kPathOnlyFrames);
  if (stride <= 1 || frames.empty()) {
    stride = 1;
    return frames;
  }
  std::vector<ReplayFrame> every{frames.front()};
  for (std::size_t f = static_cast<std::size_t>(stride); f < frames.size(); f += static_cast<std::size_t>(stride)) {
    every.push_back(frames[f]);
  }
  if (every.back().step != frames.back().step) every.push_back(frames.back());
  for (ReplayFrame &f : every) f.changes_end = 0;
  return every;
}

}  // namespace

mapping::GridGeometry replay_grid(const sensing::MetricGridSpec &spec) {
  mapping::GridGeometry g;
  g.width_cells = spec.cells_x;
  g.height_cells = spec.cells_y;
  g.subcells = 1;
  g.cell_size_m = spec.cell_m;
  g.origin = {spec.boundary.x_start_m, spec.boundary.y_start_m};
  return g;
}

void MapFrames::keep(MapView view) {
  const bool same = !view_.empty() && same_grid(view_.spec, view.spec);
  view_ = std::move(view);
  if (same) return;
  steps_per_frame_ = static_cast<std::int64_t>((view_.size() + 1999) / 2000);
  last_.assign(view_.size(), view_.initial_log_odds);
  changes_.clear();
  for (ReplayFrame &f : frames_) f.changes_end = 0;
}

void MapFrames::take_changes() {
  if (view_.empty() || !view_.read(now_) || now_.size() != last_.size()) return;
  for (std::size_t n = 0; n < now_.size(); ++n) {
    if (now_[n] == last_[n] || !replay_shows_change(last_[n], now_[n], view_.tones)) continue;
    last_[n] = now_[n];
    changes_.push_back({static_cast<std::uint32_t>(n), now_[n]});
  }
}

void MapFrames::record_frame(const ReplayPose &pose, double time_s) {
  if (path_poses_ == PathPoses::at_frames) path_.push_back(pose);
  take_changes();
  frames_.push_back({path_.size() - 1, pose.step, time_s, changes_.size()});
  poses_since_frame_ = 0;
}

void MapFrames::on_step(const ReplayPose &pose, double time_s) {
  if (path_poses_ == PathPoses::every_step) path_.push_back(pose);
  if (!frames_.empty() && ++poses_since_frame_ < steps_per_frame_) return;
  record_frame(pose, time_s);
}

void MapFrames::finish(const ReplayPose &pose, double time_s) {
  if (!frames_.empty() && frames_.back().step == pose.step) {
    take_changes();  // what the controller changed after its last step
    frames_.back().changes_end = changes_.size();
    return;
  }
  if (path_poses_ == PathPoses::every_step && (path_.empty() || path_.back().step != pose.step)) path_.push_back(pose);
  record_frame(pose, time_s);
}

void MapFrames::fill(ReplayInput &input, const mapping::GridGeometry &without_map) const {
  input.units = ReplayUnits::metres;
  if (!view_.empty()) {
    input.grid = replay_grid(view_.spec);
    input.initial_log_odds = view_.initial_log_odds;
    input.tones = view_.tones;
    input.changes = changes_;
    input.frames = frames_;
    input.steps_per_frame = static_cast<int>(steps_per_frame_);
  } else {
    input.grid = without_map;
    std::int64_t stride = 1;
    input.frames = thinned(frames_, stride);
    input.steps_per_frame = static_cast<int>(stride);
  }
  input.path = path_;
  input.steps = frames_.empty() ? 0 : frames_.back().step;
}

}  // namespace app
