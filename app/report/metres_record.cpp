#include "app/report/metres_record.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "app/report/outputs.hpp"
#include "app/report/truth_picture.hpp"
#include "app/run/metric/map_text.hpp"
#include "app/run/report.hpp"
#include "app/run/report_keys.hpp"

namespace app {
namespace {

// What the pictures mark besides the controller's state: the start, the goal, the arena's
// boundary, the landmarks, the caption.
MetricPictureMarks picture_marks(const RunOptions &options, const MetresRunStart &start) {
  MetricPictureMarks marks;
  marks.start = start.strategy.start;
  // The world's goal points, and the run's own goal (--goal, or the one the wavefront plans to)
  // where it is not one of them.
  for (const maze::ArenaPoint &g : start.arena.goals) marks.goals.push_back({g.x_m, g.y_m});
  const std::optional<mapping::Point> own = start.strategy.goal;
  const auto same = [&own](const mapping::Point &g) { return g.x_m == own->x_m && g.y_m == own->y_m; };
  if (own && std::none_of(marks.goals.begin(), marks.goals.end(), same)) marks.goals.push_back(*own);
  marks.boundary = PlainGridBounds{start.arena.x_min_m, start.arena.x_max_m, start.arena.y_min_m, start.arena.y_max_m};
  marks.landmarks = landmark_marks(start.arena);
  marks.caption = fmt::format("room {}, {}, --model {}", std::filesystem::path(options.world).filename().string(),
                              explore::to_string(start.strategy.strategy), start.setup.name);
  return marks;
}

// trace.csv's first line: t,x,y,theta and the bump or depth columns map-log reads back.
std::string trace_header_of(sensing::ModelKind kind) {
  std::string header = "t,x,y,theta";
  if (kind == sensing::ModelKind::bump) header += ",bump_right,bump_left,bump_front";
  if (kind == sensing::ModelKind::depth) {
    for (int n = 1; n <= sensing::kDepthRays; ++n) header += fmt::format(",depth_{}", n);
  }
  return header + '\n';
}

std::string logodds_csv(const sensing::MetricMap &map) {
  std::ostringstream csv;
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) csv << (i == 0 ? "" : ",") << fmt::format("{:.6f}", map.log_odds({i, j}));
    csv << '\n';
  }
  return csv.str();
}

std::string pgm_of(const sensing::MetricMap &map) {
  std::string pgm = fmt::format("P5\n{} {}\n255\n", map.cells_x(), map.cells_y());
  const auto l0 = static_cast<float>(map.model().prior_log_odds());
  for (int j = map.cells_y() - 1; j >= 0; --j) {
    for (int i = 0; i < map.cells_x(); ++i) {
      pgm += static_cast<char>(pgm_pixel(static_cast<float>(map.log_odds({i, j})), l0));
    }
  }
  return pgm;
}

}  // namespace

const std::vector<std::string> &metres_own_names() {
  static const std::vector<std::string> names{"logodds.csv", "thresholded.txt", "wave.png"};
  return names;
}

MetresRecord::MetresRecord(const RunOptions &options, const MetresRunStart &start)
    : kind_(options.model.kind), wavefront_(start.strategy.strategy == explore::StrategyKind::wavefront),
      threshold_(start.threshold), world_(options.world), body_radius_m_(start.strategy.body_radius_m),
      tones_(metric_map_tones(start.map, sensing::probabilities_in_effect(start.setup, options.sensor), start.threshold)),
      marks_(picture_marks(options, start)), trace_(trace_header_of(kind_)) {
  replay_.keep(map_view(start.map, tones_));
  replay_.on_step(ReplayPose{0, {start.start.x_m, start.start.y_m}, start.start.yaw_rad}, 0.0);
}

void MetresRecord::on_step(const RunStep &step) {
  const robot::MetricController &c = *step.metres;
  const sensing::PoseStep &s = c.senses().pose_step();
  trace_ += fmt::format("{},{},{},{}", s.t, s.x_m, s.y_m, s.theta_rad);
  if (kind_ == sensing::ModelKind::bump) {
    trace_ += fmt::format(",{},{},{}", s.bump_right ? 1 : 0, s.bump_left ? 1 : 0, s.bump_front ? 1 : 0);
  }
  if (kind_ == sensing::ModelKind::depth) {
    for (const double d : s.depth_m) trace_ += fmt::format(",{}", d);
  }
  trace_ += '\n';
  replay_.on_step(ReplayPose{c.steps(), c.position(), c.yaw_rad()}, c.time_s());
  for (const std::string &name : step.snapshots) {
    for (NamedFile &picture : pictures_now(c, name, name + "_wave")) snapshots_.push_back(std::move(picture));
  }
}

std::vector<NamedFile> MetresRecord::pictures_now(const robot::MetricController &c, const std::string &map,
                                                         const std::string &wave) const {
  MetricPictureMarks marks = marks_;
  marks.when = fmt::format("step {}, {:.1f} s", c.steps(), c.time_s());
  std::vector<NamedFile> pictures{{map + ".png", metric_map_picture(c, tones_, marks)}};
  if (wavefront_ && !c.wave().empty()) pictures.push_back({wave + ".png", metric_wave_picture(c, marks)});
  return pictures;
}

void MetresRecord::write(OutputDir &out, const MetresRunEnd &end) {
  // What matters most first: after a stop signal the files have a bounded time (output_dir.hpp).
  out.write("summary.json", report_json(end.report).dump(2) + "\n");
  out.write("trace.csv", trace_);
  const robot::MetricController &c = end.controller;
  const std::vector<NamedFile> last = pictures_now(c, "map", "wave");  // map.png, wave.png
  const MetricTruthScores scores{end.report.text(report_key::cell_accuracy), end.report.text(report_key::coverage)};
  replay_.finish(ReplayPose{c.steps(), c.position(), c.yaw_rad()}, c.time_s());
  ReplayInput page;  // what replay.html shows besides the frames
  replay_.fill(page, c.map().geometry());
  page.title = world_;
  page.caption = marks_.caption;
  page.goals = marks_.goals;
  page.goal_side_m = 4.0 * body_radius_m_;
  page.body_radius_m = body_radius_m_;
  page.landmarks = marks_.landmarks;
  page.solid_boundary = marks_.boundary;
  page.summary = replay_summary(end.report);
  // The core files in the order every run writes them, then the room's own.
  out.write("map.pgm", pgm_of(c.map()));
  out.write("map.yaml", map_yaml(c.map().geometry(), "map.pgm"));
  out.write(last.front().name, last.front().bytes);
  out.write("truth.png", metric_truth_picture(c, end.truth, threshold_, marks_, scores));
  for (const NamedFile &snapshot : snapshots_) out.write(snapshot.name, snapshot.bytes);
  if (const std::optional<Replay> replay = replay_html(page)) out.write("replay.html", replay->html);
  out.write("logodds.csv", logodds_csv(c.map()));
  out.write("thresholded.txt", metric_binary_map(c.map(), threshold_));
  for (std::size_t i = 1; i < last.size(); ++i) out.write(last[i].name, last[i].bytes);
}

}  // namespace app
