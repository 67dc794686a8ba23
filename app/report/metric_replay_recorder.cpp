// replay.html for a room run (app/report/metric_replay_recorder.hpp).

#include "app/report/metric_replay_recorder.hpp"

#include <algorithm>
#include <cmath>

namespace app {

MetricReplayRecorder::MetricReplayRecorder(const sensing::MetricMap &map, const MapTones &tones, const ReplayPose &start)
    : map_(map), tones_(tones), steps_per_frame_(static_cast<std::int64_t>((map.size() + 1999) / 2000)),
      last_(map.size(), static_cast<float>(map.model().prior_log_odds())), path_{start} {
  frames_.push_back({0, start.step, 0.0, 0});
}

void MetricReplayRecorder::record(const robot::MetricController &c) {
  for (std::size_t n = 0; n < last_.size(); ++n) {
    const auto now = static_cast<float>(map_.log_odds_at(n));
    if (!replay_shows_change(last_[n], now, tones_)) continue;
    last_[n] = now;
    changes_.push_back({static_cast<std::uint32_t>(n), now});
  }
  path_.push_back({c.steps(), c.position(), c.yaw_rad()});
  frames_.push_back({path_.size() - 1, c.steps(), c.time_s(), changes_.size()});
}

void MetricReplayRecorder::on_step(const robot::MetricController &c) {
  if (c.steps() % steps_per_frame_ == 0) record(c);
}

void MetricReplayRecorder::finish(const robot::MetricController &c) {
  if (frames_.back().step != c.steps()) record(c);
}

ReplayInput MetricReplayRecorder::input(const MetricReplayText &text) const {
  ReplayInput in;
  in.units = ReplayUnits::metres;
  in.grid = map_.geometry();
  in.initial_log_odds = static_cast<float>(map_.model().prior_log_odds());
  in.tones = tones_;
  in.path = path_;
  in.changes = changes_;
  in.frames = frames_;
  in.steps_per_frame = static_cast<int>(steps_per_frame_);
  if (text.goal) in.goals.push_back(*text.goal);
  in.goal_side_m = 4.0 * text.body_radius_m;
  in.body_radius_m = text.body_radius_m;
  in.landmarks = text.landmarks;
  in.solid_boundary = text.boundary;
  in.title = text.title;
  in.caption = text.caption;
  in.steps = frames_.back().step;
  in.summary = text.summary;
  return in;
}

}  // namespace app
