#include "app/report/replay.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/picture/size_rules.hpp"
#include "app/report/replay_page.hpp"
#include "common/fixed_decimal.hpp"
#include "mapping/walls.hpp"
#include "maze/world/truth_raster.hpp"

namespace app {
namespace {

std::string quoted(const std::string &text) { return nlohmann::json(text).dump(); }

long milli(double value) { return std::lround(value * 1000.0); }

void append_ints(std::string &out, const std::vector<long> &values) {
  out += '[';
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += ',';
    common::append_int(out, values[i]);
  }
  out += ']';
}

// The changes [first, last) as (gap, value) pairs, the last value of each sub-cell.
std::vector<long> frame_changes(const std::vector<ReplayChange> &changes, std::size_t first, std::size_t last,
                                const MapTones &tones) {
  std::vector<ReplayChange> window(changes.begin() + static_cast<std::ptrdiff_t>(first),
                                   changes.begin() + static_cast<std::ptrdiff_t>(last));
  std::stable_sort(window.begin(), window.end(), [](const auto &a, const auto &b) { return a.index < b.index; });
  std::vector<long> pairs;
  long previous = 0;
  for (std::size_t i = 0; i < window.size(); ++i) {
    if (i + 1 < window.size() && window[i + 1].index == window[i].index) continue;  // a later value wins
    pairs.push_back(static_cast<long>(window[i].index) - previous);
    pairs.push_back(replay_value(window[i].log_odds, tones));
    previous = static_cast<long>(window[i].index);
  }
  return pairs;
}

// "path": every pose, in mm from the grid's corner and mrad.
void append_path(std::string &out, const ReplayInput &input) {
  std::vector<long> steps;
  std::vector<long> xy;
  std::vector<long> yaw;
  std::vector<long> placed;
  for (const ReplayPose &p : input.path) {
    if (p.placed) placed.push_back(static_cast<long>(steps.size()));
    steps.push_back(static_cast<long>(p.step));
    xy.push_back(milli(p.at.x_m - input.grid.origin.x_m));
    xy.push_back(milli(p.at.y_m - input.grid.origin.y_m));
    yaw.push_back(milli(p.yaw_rad));
  }
  out += "\"path\":{\"steps\":";
  append_ints(out, steps);
  out += ",\"xy_mm\":";
  append_ints(out, xy);
  out += ",\"yaw_mrad\":";
  append_ints(out, yaw);
  out += ",\"placed\":";
  append_ints(out, placed);
  out += fmt::format(",\"start\":{}", input.start_pose);
  out += '}';
}

// "frames": `merged` recorded frames into each, the last one's pose, step and time and the
// group's changes (written straight into `out`: they are most of the page).
void append_frames(std::string &out, const ReplayInput &input, std::size_t merged) {
  std::vector<long> poses;
  std::vector<long> steps;
  std::vector<long> times;
  std::vector<std::size_t> ends;
  for (std::size_t first = 0; first < input.frames.size(); first += merged) {
    const ReplayFrame &f = input.frames[std::min(first + merged, input.frames.size()) - 1];
    poses.push_back(static_cast<long>(f.last_pose));
    steps.push_back(static_cast<long>(f.step));
    times.push_back(f.time_s < 0.0 ? -1 : milli(f.time_s));
    ends.push_back(f.changes_end);
  }
  out += "\"frames\":{\"pose\":";
  append_ints(out, poses);
  out += ",\"step\":";
  append_ints(out, steps);
  out += ",\"t_ms\":";
  append_ints(out, times);
  out += ",\"changes\":[";
  std::size_t first = 0;
  for (std::size_t f = 0; f < ends.size(); ++f) {
    if (f > 0) out += ',';
    append_ints(out, frame_changes(input.changes, first, ends[f], input.tones));
    first = ends[f];
  }
  out += "]}";
}

// "belief": each page frame's, its last recorded frame's; null when the run kept none.
void append_belief(std::string &out, const ReplayInput &input, std::size_t merged) {
  out += "\"belief\":";
  const std::vector<std::vector<int>> &b = input.belief_permille;
  if (b.empty()) {
    out += "null";
    return;
  }
  out += '[';
  for (std::size_t first = 0; first < input.frames.size(); first += merged) {
    if (first > 0) out += ',';
    const std::size_t last = std::min({first + merged, input.frames.size(), b.size()}) - 1;
    append_ints(out, std::vector<long>(b[last].begin(), b[last].end()));
  }
  out += ']';
}

void append_marks(std::string &out, const ReplayInput &input) {
  const mapping::Point o = input.grid.origin;
  std::vector<long> goals;
  for (const mapping::Point &g : input.goals) {
    goals.push_back(milli(g.x_m - o.x_m));
    goals.push_back(milli(g.y_m - o.y_m));
  }
  out += "\"goals\":";
  append_ints(out, goals);
  std::vector<long> landmarks;
  for (const LandmarkMark &l : input.landmarks) {
    landmarks.insert(landmarks.end(), {milli(l.at.x_m - o.x_m), milli(l.at.y_m - o.y_m), milli(l.radius_m)});
    if (l.colour) {
      landmarks.insert(landmarks.end(), {long{l.colour->r}, long{l.colour->g}, long{l.colour->b}});
    } else {
      landmarks.insert(landmarks.end(), {-1L, -1L, -1L});
    }
  }
  out += ",\"landmarks\":";
  append_ints(out, landmarks);
  std::vector<long> boundary;
  if (const std::optional<PlainGridBounds> &b = input.solid_boundary) {
    boundary = {milli(b->x_min_m - o.x_m), milli(b->y_min_m - o.y_m), milli(b->x_max_m - o.x_m), milli(b->y_max_m - o.y_m)};
  }
  out += ",\"boundary_mm\":";
  append_ints(out, boundary);
  std::vector<long> solids;
  for (const PlainGridBounds &b : input.world_solids) {
    solids.insert(solids.end(), {milli(b.x_min_m - o.x_m), milli(b.y_min_m - o.y_m), milli(b.x_max_m - o.x_m),
                                 milli(b.y_max_m - o.y_m)});
  }
  out += ",\"solids_mm\":";
  append_ints(out, solids);
}

void append_summary(std::string &out, const ReplayInput &input) {
  out += "\"summary\":[";
  for (std::size_t i = 0; i < input.summary.size(); ++i) {
    if (i > 0) out += ',';
    out += fmt::format("[{},{}]", quoted(input.summary[i].first), quoted(input.summary[i].second));
  }
  out += ']';
}

// What a frame of the page holds when `merged` recorded frames make one: "" for one move or step.
std::string frame_note(const ReplayInput &input, int merged) {
  if (input.steps_per_frame <= 0) return merged > 1 ? fmt::format("{} moves a frame", merged) : "";
  const long steps = static_cast<long>(merged) * input.steps_per_frame;
  return steps > 1 ? fmt::format("a frame every {} steps", steps) : "";
}

// `page` with its mark <!--REPLAY_DATA--> replaced by `data`.
std::string page_with_data(std::string_view page, const std::string &data) {
  constexpr std::string_view kMark = "<!--REPLAY_DATA-->";
  const std::size_t at = page.find(kMark);
  std::string html;
  html.reserve(page.size() + data.size());
  html += page.substr(0, at);
  html += data;
  html += page.substr(at + kMark.size());
  return html;
}

}  // namespace

long replay_value(float log_odds, const MapTones &tones) {
  return 2 * std::lround(100.0 * static_cast<double>(log_odds)) + (mapping::is_occupied(log_odds, tones.threshold) ? 1 : 0);
}

bool replay_shows_change(float was, float now, const MapTones &tones) {
  if (replay_value(now, tones) == replay_value(was, tones)) return false;  // the same on the page to 0.01
  if (tone(now, tones) != tone(was, tones)) return true;
  const double readout_step = std::min(tones.occupied_increment, -tones.free_increment);
  const double moved = std::abs(static_cast<double>(now) - static_cast<double>(was));
  return moved >= std::max(readout_step, 0.25 * std::abs(static_cast<double>(was)));
}

void add_history(ReplayInput &input, const GridHistory &history, std::int64_t steps) {
  const mapping::GridGeometry &g = history.geometry();
  input.grid = g;
  input.initial_log_odds = history.initial_log_odds();
  input.path.clear();
  for (const GridHistory::Arrival &a : history.arrivals()) {
    const mapping::Point centre{g.origin.x_m + (a.cell.x + 0.5) * g.cell_size_m,
                                g.origin.y_m + (a.cell.y + 0.5) * g.cell_size_m};
    input.path.push_back({a.step, centre, mapping::yaw_rad(a.heading)});
  }
  const std::deque<GridHistory::Change> &log = history.change_log();
  input.changes.clear();
  input.changes.reserve(log.size());
  for (const GridHistory::Change &c : log) input.changes.push_back({c.index, c.value});
  input.frames.clear();
  const std::size_t count = std::max<std::size_t>(1, input.path.size());
  std::size_t end = 0;
  for (std::size_t f = 0; f < count; ++f) {
    const bool last = f + 1 >= input.path.size();
    const std::int64_t until = last ? steps + 1 : input.path[f + 1].step;  // the next arrival's step
    while (end < log.size() && log[end].step < until) ++end;
    input.frames.push_back({f, last ? steps : until - 1, -1.0, end});
  }
}

std::string escaped_for_script(std::string json) {
  std::size_t at = json.find("</");
  if (at == std::string::npos) return json;  // the usual case: nothing to copy
  std::string out;
  out.reserve(json.size() + 16);
  std::size_t from = 0;
  for (; at != std::string::npos; at = json.find("</", at + 2)) {
    out.append(json, from, at + 1 - from);
    out += '\\';
    from = at + 1;
  }
  out.append(json, from, std::string::npos);
  return out;
}

void add_goal_cells(ReplayInput &input, const std::vector<mapping::Cell> &cells) {
  const mapping::GridGeometry &g = input.grid;
  for (const mapping::Cell c : cells) {
    input.goals.push_back({g.origin.x_m + (c.x + 0.5) * g.cell_size_m, g.origin.y_m + (c.y + 0.5) * g.cell_size_m});
  }
  input.goal_side_m = 0.75 * g.cell_size_m;
}

std::string replay_data_json(const ReplayInput &input, int merged) {
  const mapping::GridGeometry &g = input.grid;
  const MapTones &t = input.tones;
  std::string out = fmt::format(
      "{{\"version\":2,\"units\":\"{}\",\"title\":{},\"caption\":{},\"frame_note\":{},\"width\":{},\"height\":{},"
      "\"k\":{},\"cell_size_m\":{},\"origin\":[{},{}],\"initial\":{},\"occupied_increment\":{:.4f},"
      "\"free_increment\":{:.4f},\"steps\":{},\"reachable\":{},\"body_mm\":{},\"goal_mm\":{},"
      "\"mark_rule\":[{},{},{}],",
      input.units == ReplayUnits::cells ? "cells" : "metres", quoted(input.title), quoted(input.caption),
      quoted(frame_note(input, merged)), g.width_cells, g.height_cells, g.subcells, g.cell_size_m, g.origin.x_m,
      g.origin.y_m, replay_value(input.initial_log_odds, t), t.occupied_increment, t.free_increment, input.steps,
      input.reachable_cells, milli(input.body_radius_m), milli(input.goal_side_m), kMarkOfFont, kLeastFontPx,
      kFontShareOfHeight);
  // About 12 bytes a change and 24 a pose: reserved, so that the data is not copied as it grows.
  out.reserve(out.size() + 12 * input.changes.size() + 24 * input.path.size() + 4096);
  append_marks(out, input);
  out += ',';
  append_path(out, input);
  out += ',';
  append_frames(out, input, static_cast<std::size_t>(std::max(1, merged)));
  out += ',';
  append_belief(out, input, static_cast<std::size_t>(std::max(1, merged)));
  out += ',';
  append_summary(out, input);
  out += '}';
  return out;
}

std::optional<Replay> replay_html(const ReplayInput &input) {
  const int all = std::max<int>(1, static_cast<int>(input.frames.size()));
  for (int per = 1;; per = std::min(per * 2, all)) {
    std::string html = page_with_data(kReplayPage, escaped_for_script(replay_data_json(input, per)));
    if (html.size() <= input.max_bytes) return Replay{std::move(html), per};
    if (per >= all) return std::nullopt;
  }
}

std::vector<std::pair<std::string, std::string>> replay_summary(const Report &report) {
  std::vector<std::pair<std::string, std::string>> lines = summary_pairs(report);
  std::erase_if(lines, [](const auto &line) { return line.first == "wall_time_ms"; });
  return lines;
}

std::vector<PlainGridBounds> world_solid_boxes(const maze::Arena &arena) {
  const double cell_m = std::max(arena.width_m(), arena.height_m()) / kWorldSolidCells;
  const maze::TruthRaster truth = maze::rasterise_truth(arena, maze::cells_along(arena.width_m(), cell_m),
                                                        maze::cells_along(arena.height_m(), cell_m), 0.0);
  std::vector<PlainGridBounds> boxes;
  const auto solid = [&truth](int i, int j) { return truth.is_occupied(i, j); };
  for (int j = 0; j < truth.cells_y; ++j) {
    for (int i = 0; i < truth.cells_x;) {
      if (!solid(i, j)) {
        ++i;
        continue;
      }
      const int first = i;
      while (i < truth.cells_x && solid(i, j)) ++i;
      boxes.push_back({truth.x_min_m + first * truth.cell_x_m, truth.x_min_m + i * truth.cell_x_m,
                       truth.y_min_m + j * truth.cell_y_m, truth.y_min_m + (j + 1) * truth.cell_y_m});
    }
  }
  return boxes;
}

}  // namespace app
