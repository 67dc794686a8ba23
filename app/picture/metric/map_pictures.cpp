// The room run's pictures (app/picture/metric/map_pictures.hpp).

#include "app/picture/metric/map_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <fmt/format.h>

#include "app/picture/figure.hpp"
#include "app/picture/plain_grid_picture.hpp"
#include "plan/metric/wavefront.hpp"

namespace app {
namespace {

constexpr Rgb kBlockedTone{90, 90, 90};
constexpr Rgb kUnreachedTone{255, 255, 255};
constexpr Rgb kNearTone{255, 236, 170};
constexpr Rgb kFarTone{20, 60, 170};
constexpr Rgb kOccupiedRightTone{25, 25, 25};
constexpr Rgb kMissedTone{220, 40, 40};
constexpr Rgb kPhantomTone{200, 40, 200};
constexpr Rgb kUnreachableFreeTone{205, 205, 205};

// A cell's verdict: the map's state (never observed, or thresholded) against the truth's.
Rgb truth_tone(const sensing::MetricMap &map, const maze::TruthRaster &truth, double threshold, std::size_t n) {
  const sensing::MetricCell cell = map.cell_of_index(n);
  const bool occupied = truth.is_occupied(cell.i, cell.j);
  if (map.unobserved_at(n)) return kUnknownTone;
  const bool mapped_occupied = map.log_odds_at(n) >= threshold;
  if (occupied) return mapped_occupied ? kOccupiedRightTone : kMissedTone;
  if (mapped_occupied) return kPhantomTone;
  return truth.is_reachable(cell.i, cell.j) ? kWhite : kUnreachableFreeTone;
}

// The map's cells as a plain grid, each in `tone_of(flat index)`.
template <typename ToneOf>
PlainGrid room_grid(const sensing::MetricMap &map, const MetricPictureMarks &marks, ToneOf tone_of) {
  PlainGrid g;
  g.solid_boundary = marks.boundary;
  g.cells_x = map.cells_x();
  g.cells_y = map.cells_y();
  g.x0_m = map.spec().boundary.x_start_m;
  g.y0_m = map.spec().boundary.y_start_m;
  g.cell_w_m = g.cell_h_m = map.cell_m();
  g.axes_in_metres = true;
  g.tones.reserve(map.size());
  for (std::size_t n = 0; n < map.size(); ++n) g.tones.push_back(tone_of(n));
  return g;
}

// The last plan's cells' centres, in pixels.
std::vector<PointPx> plan_px(const sensing::MetricMap &map, std::span<const std::size_t> plan,
                             const PlainGridFrame &frame) {
  std::vector<PointPx> points;
  for (const std::size_t n : plan) {
    const mapping::Point p = map.centre_of(map.cell_of_index(n));
    points.push_back(frame.at(p.x_m, p.y_m));
  }
  return points;
}

MetricRobotMarks robot_marks(const robot::MetricController &c) {
  return {c.trajectory(), c.path(), c.position(), c.yaw_rad()};
}

// The path from `start` along the trajectory, a polyline a piece (a pose the robot was set
// down on starts a piece); returns every point, the start first.
std::vector<PointPx> draw_trail(Drawing &page, const PlainGridFrame &frame, mapping::Point start,
                                const MetricRobotMarks &robot) {
  std::vector<PointPx> trail{frame.at(start.x_m, start.y_m)};
  for (const mapping::Point &p : robot.trajectory) trail.push_back(frame.at(p.x_m, p.y_m));
  const double width_px = std::max(1.5, frame.cell_w_px / 6);
  std::size_t first = 0;  // into trail (trajectory index + 1)
  for (const std::size_t placed : robot.placed) {
    page.polyline(std::vector<PointPx>(trail.begin() + static_cast<std::ptrdiff_t>(first),
                                       trail.begin() + static_cast<std::ptrdiff_t>(placed + 1)),
                  width_px, kPathColour);
    first = placed + 1;
  }
  page.polyline(std::vector<PointPx>(trail.begin() + static_cast<std::ptrdiff_t>(first), trail.end()), width_px,
                kPathColour);
  return trail;
}

// A mark's size: most of a map cell, and at least the page's least (app/picture/size_rules.hpp).
double mark_px(const PlainGridFrame &frame) { return std::max(frame.cell_w_px * 0.8, frame.least_mark_px); }

void draw_goals(Drawing &page, const PlainGridFrame &frame, const MetricPictureMarks &marks) {
  const double side = mark_px(frame) * 1.5;
  for (const mapping::Point &goal : marks.goals) {
    const PointPx g = frame.at(goal.x_m, goal.y_m);
    page.stroke_rect({g.x - side / 2, g.y - side / 2, side, side}, std::max(1.5, side / 6), kGoalColour);
  }
}

void draw_start(Drawing &page, const PlainGridFrame &frame, PointPx start) {
  const double side = mark_px(frame);
  page.fill_rect({start.x - side / 2, start.y - side / 2, side, side}, kStartColour);
}

void draw_robot(Drawing &page, const PlainGridFrame &frame, const MetricRobotMarks &robot) {
  const PointPx at = frame.at(robot.position.x_m, robot.position.y_m);
  const double r = mark_px(frame) / 2;
  page.ringed_disc(at, r, kEndColour, std::max(1.0, r / 4), kWhite);
  // its heading: a white tick from the centre to the rim
  page.polyline({at, {at.x + r * std::cos(robot.yaw_rad), at.y - r * std::sin(robot.yaw_rad)}}, std::max(1.0, r / 3),
                kWhite);
}

void draw_plan(Drawing &page, const PlainGridFrame &frame, const sensing::MetricMap &map,
               std::span<const std::size_t> plan) {
  const std::vector<PointPx> points = plan_px(map, plan, frame);
  if (points.size() >= 2) page.polyline(points, std::max(1.5, frame.cell_w_px / 5), kPlannedColour);
}

// Under every other mark: the landmarks, each a disc of its radius.
void draw_room_landmarks(Drawing &page, const PlainGridFrame &frame, const MetricPictureMarks &marks) {
  for (const LandmarkMark &l : marks.landmarks) {
    draw_landmark(page, l, frame.at(l.at.x_m, l.at.y_m), frame.cell_w_px / frame.cell_w_m, frame.least_mark_px);
  }
}

// The legend's items every room picture has after its own: the boundary's wall, the landmarks.
void add_world_items(Figure &legend, const MetricPictureMarks &marks) {
  if (marks.boundary) legend.items.push_back({Swatch::box, kBoundaryWallColour, "boundary wall"});
  for (LegendItem &item : landmark_items(marks.landmarks)) legend.items.push_back(std::move(item));
}

// The caption and, when the picture has one, the moment it shows.
std::vector<std::string> caption_lines(const MetricPictureMarks &marks) {
  std::vector<std::string> lines{marks.caption};
  if (!marks.when.empty()) lines.push_back(marks.when);
  return lines;
}

// A score as the picture prints it: its percentage, without the counts in brackets.
std::string percentage(const std::string &score) { return score.substr(0, score.find(" (")); }

Figure map_legend(const MetricPictureMarks &marks, const MapTones &tones, bool has_plan) {
  Figure legend;
  legend.lines = caption_lines(marks);
  legend.items = {{Swatch::line, kPathColour, "trajectory"},
                  {Swatch::square, kStartColour, "start"},
                  {Swatch::disc, kEndColour, "robot"}};
  if (has_plan) legend.items.push_back({Swatch::line, kPlannedColour, "last plan"});
  if (!marks.goals.empty()) legend.items.push_back({Swatch::frame, kGoalColour, "goal"});
  add_world_items(legend, marks);
  legend.bar = map_tone_bar(tones, "never observed (prior)");
  return legend;
}

Figure truth_legend(const MetricPictureMarks &marks, const MetricTruthScores &scores) {
  Figure legend;
  legend.lines = caption_lines(marks);
  legend.lines.push_back(fmt::format("cell_accuracy {}, coverage {}", percentage(scores.cell_accuracy),
                                     percentage(scores.coverage)));
  legend.items = {{Swatch::box, kOccupiedRightTone, "occupied, mapped occupied"},
                  {Swatch::box, kMissedTone, "occupied, mapped free"},
                  {Swatch::box, kPhantomTone, "free, mapped occupied"},
                  {Swatch::box, kUnknownTone, "never observed"},
                  {Swatch::box, kUnreachableFreeTone, "free, not reachable"},
                  {Swatch::line, kPathColour, "trajectory"},
                  {Swatch::square, kStartColour, "start"},
                  {Swatch::disc, kEndColour, "robot"}};
  if (!marks.goals.empty()) legend.items.push_back({Swatch::frame, kGoalColour, "goal"});
  add_world_items(legend, marks);
  return legend;
}

Figure wave_legend(const MetricPictureMarks &marks, std::int32_t top, bool has_plan) {
  Figure legend;
  legend.lines = caption_lines(marks);
  legend.lines.push_back(fmt::format("the wave's numbers: 1 blocked, 2 the goal, up to {} the farthest", top));
  legend.items = {{Swatch::box, kBlockedTone, "1: obstacle, grown"}, {Swatch::box, kGoalColour, "2: goal"}};
  if (has_plan) legend.items.push_back({Swatch::line, kPlannedColour, "path"});
  legend.items.push_back({Swatch::disc, kEndColour, "robot"});
  add_world_items(legend, marks);
  ColourBar bar;
  bar.name = "wave";
  const int samples = 60;
  for (int k = 0; k < samples; ++k) {
    bar.tones.push_back(wave_tone(plan::kWaveGoal + 1 + (top - plan::kWaveGoal - 1) * k / (samples - 1), top));
  }
  bar.ticks = {{0.0, fmt::format("{}", plan::kWaveGoal + 1), ""},
               {1.0, fmt::format("{}", std::max(top, plan::kWaveGoal + 1)), ""}};
  bar.left_word = "near the goal";
  bar.right_word = "far";
  bar.extra = LegendItem{Swatch::box, kUnreachedTone, "0: not reached"};
  legend.bar = bar;
  return legend;
}

}  // namespace

MapTones metric_map_tones(const sensing::MetricMap &map, const sensing::MarkProbabilities &p, double threshold) {
  MapTones tones;
  tones.initial_log_odds = static_cast<float>(map.model().prior_log_odds());
  tones.threshold = static_cast<float>(threshold);
  tones.occupied_increment = map.model().increment_for(p.p_occ);
  tones.free_increment = map.model().increment_for(p.p_free);
  return tones;
}

std::string metric_map_picture(const robot::MetricController &c, const MapTones &tones, const MetricPictureMarks &marks,
                             PictureFormat format) {
  return metric_map_picture(c.map(), robot_marks(c), tones, marks, format);
}

std::string metric_map_picture(const sensing::MetricMap &map, const MetricRobotMarks &robot, const MapTones &tones,
                             const MetricPictureMarks &marks, PictureFormat format) {
  const PlainGrid g = room_grid(map, marks, [&](std::size_t n) { return tone(static_cast<float>(map.log_odds_at(n)), tones); });
  const PlainGridOverlay overlay = [&](Drawing &page, const PlainGridFrame &frame) {
    draw_room_landmarks(page, frame, marks);
    const std::vector<PointPx> trail = draw_trail(page, frame, marks.start, robot);
    draw_plan(page, frame, map, robot.plan);
    draw_start(page, frame, trail.front());
    draw_goals(page, frame, marks);
    draw_robot(page, frame, robot);
  };
  return plain_grid_picture(g, map_legend(marks, tones, robot.plan.size() >= 2), overlay, format,
                            metric_page(map, marks))
      .encode();
}

std::string metric_truth_picture(const robot::MetricController &c, const maze::TruthRaster &truth, double threshold,
                               const MetricPictureMarks &marks, const MetricTruthScores &scores, PictureFormat format) {
  const sensing::MetricMap &map = c.map();
  const PlainGrid g = room_grid(map, marks, [&](std::size_t n) { return truth_tone(map, truth, threshold, n); });
  const PlainGridOverlay overlay = [&](Drawing &page, const PlainGridFrame &frame) {
    draw_room_landmarks(page, frame, marks);
    const MetricRobotMarks robot = robot_marks(c);
    const std::vector<PointPx> trail = draw_trail(page, frame, marks.start, robot);
    draw_start(page, frame, trail.front());
    draw_goals(page, frame, marks);
    draw_robot(page, frame, robot);
  };
  return plain_grid_picture(g, truth_legend(marks, scores), overlay, format, metric_page(map, marks)).encode();
}

Rgb wave_tone(std::int32_t value, std::int32_t top) {
  if (value == plan::kWaveBlocked) return kBlockedTone;
  if (value == plan::kWaveGoal) return kGoalColour;
  if (value <= plan::kWaveUnreached) return kUnreachedTone;
  const double f = top <= plan::kWaveGoal + 1
                       ? 1.0
                       : static_cast<double>(value - plan::kWaveGoal - 1) / static_cast<double>(top - plan::kWaveGoal - 1);
  const auto mix = [f](unsigned char a, unsigned char b) {
    return static_cast<unsigned char>(std::lround(a + f * (static_cast<double>(b) - a)));
  };
  return Rgb{mix(kNearTone.r, kFarTone.r), mix(kNearTone.g, kFarTone.g), mix(kNearTone.b, kFarTone.b)};
}

std::string metric_wave_picture(const robot::MetricController &c, const MetricPictureMarks &marks, PictureFormat format) {
  const std::vector<std::int32_t> &wave = c.wave();
  const std::int32_t top = wave.empty() ? plan::kWaveGoal : *std::max_element(wave.begin(), wave.end());
  const PlainGrid g = room_grid(c.map(), marks, [&](std::size_t n) { return wave_tone(wave[n], top); });
  const PlainGridOverlay overlay = [&](Drawing &page, const PlainGridFrame &frame) {
    draw_room_landmarks(page, frame, marks);
    draw_plan(page, frame, c.map(), c.path());
    draw_goals(page, frame, marks);
    draw_robot(page, frame, robot_marks(c));
  };
  return plain_grid_picture(g, wave_legend(marks, top, c.path().size() >= 2), overlay, format,
                            metric_page(c.map(), marks))
      .encode();
}

PageFrame metric_page(const sensing::MetricMap &map, const MetricPictureMarks &marks) {
  const PlainGrid g = room_grid(map, marks, [](std::size_t) { return kWhite; });
  MetricPictureMarks widest = marks;
  widest.when = "step 9999999, 99999.9 s";
  widest.goals = {mapping::Point{}};
  const MetricTruthScores scores{"100.00%", "100.00%"};
  const auto most = static_cast<std::int32_t>(map.size()) + plan::kWaveGoal;
  // The map's legend with the default tones: its colour bar is as wide whatever the set-up.
  return shared_page({plain_grid_figure(g, map_legend(widest, MapTones{}, true)),
                      plain_grid_figure(g, truth_legend(widest, scores)),
                      plain_grid_figure(g, wave_legend(widest, most, true))});
}

}  // namespace app
