#include "app/report/replay.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <iterator>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/report/replay_page.hpp"
#include "common/fixed_decimal.hpp"
#include "mapping/walls.hpp"

namespace app {
namespace {

std::string quoted(const std::string &text) { return nlohmann::json(text).dump(); }

// 2 * round(100 * l) + 1 when occupied by the map's rule (see replay.hpp).
long encoded(float l, const MapTones &tones) {
  return 2 * std::lround(100.0 * static_cast<double>(l)) + (mapping::is_occupied(l, tones.threshold) ? 1 : 0);
}

void append_ints(std::string &out, const std::vector<long> &values) {
  out += '[';
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += ',';
    common::append_int(out, values[i]);
  }
  out += ']';
}

// The changes of log [first, last) as (gap, value) pairs, the last value of each sub-cell.
std::vector<long> frame_changes(const std::deque<GridHistory::Change> &log, std::size_t first, std::size_t last,
                                const MapTones &tones) {
  std::vector<GridHistory::Change> window(log.begin() + static_cast<std::ptrdiff_t>(first),
                                          log.begin() + static_cast<std::ptrdiff_t>(last));
  std::stable_sort(window.begin(), window.end(), [](const auto &a, const auto &b) { return a.index < b.index; });
  std::vector<long> pairs;
  long previous = 0;
  for (std::size_t i = 0; i < window.size(); ++i) {
    if (i + 1 < window.size() && window[i + 1].index == window[i].index) continue;  // a later value wins
    pairs.push_back(static_cast<long>(window[i].index) - previous);
    pairs.push_back(encoded(window[i].value, tones));
    previous = static_cast<long>(window[i].index);
  }
  return pairs;
}

// "path": every arrival; the headings as one letter each.
void append_path(std::string &out, const GridHistory &history) {
  std::vector<long> steps;
  std::vector<long> cells;
  std::string headings;
  for (const GridHistory::Arrival &a : history.arrivals()) {
    steps.push_back(static_cast<long>(a.step));
    cells.push_back(a.cell.x);
    cells.push_back(a.cell.y);
    headings += mapping::to_char(a.heading);
  }
  out += "\"path\":{\"steps\":";
  append_ints(out, steps);
  out += ",\"cells\":";
  append_ints(out, cells);
  out += fmt::format(",\"headings\":\"{}\"}}", headings);
}

// "frames": for each, the last arrival it shows, its step and its changes (written straight
// into `out`: they are most of the page).
void append_frames(std::string &out, const ReplayInput &input, int moves_per_frame) {
  const std::vector<GridHistory::Arrival> &arrivals = input.history->arrivals();
  const std::deque<GridHistory::Change> &log = input.history->change_log();
  const std::size_t per = static_cast<std::size_t>(moves_per_frame);
  const std::size_t count = std::max<std::size_t>(1, (arrivals.size() + per - 1) / per);
  std::vector<long> shows;
  std::vector<long> steps;
  std::vector<std::size_t> ends;  // frame f's changes: log [ends[f - 1], ends[f])
  std::size_t end = 0;
  for (std::size_t f = 0; f < count; ++f) {
    const std::size_t next = std::min((f + 1) * per, arrivals.size());  // the next frame's first arrival
    const bool last_frame = f + 1 == count;
    const std::int64_t until = last_frame ? input.steps + 1 : arrivals[next].step;
    while (end < log.size() && log[end].step < until) ++end;
    shows.push_back(static_cast<long>(next) - 1);
    steps.push_back(static_cast<long>(last_frame ? input.steps : until - 1));
    ends.push_back(end);
  }
  out += "\"frames\":{\"arrival\":";
  append_ints(out, shows);
  out += ",\"step\":";
  append_ints(out, steps);
  out += ",\"changes\":[";
  std::size_t first = 0;
  for (std::size_t f = 0; f < count; ++f) {
    if (f > 0) out += ',';
    append_ints(out, frame_changes(log, first, ends[f], input.tones));
    first = ends[f];
  }
  out += "]}";
}

void append_summary(std::string &out, const ReplayInput &input) {
  out += "\"summary\":[";
  for (std::size_t i = 0; i < input.summary.size(); ++i) {
    if (i > 0) out += ',';
    out += fmt::format("[{},{}]", quoted(input.summary[i].first), quoted(input.summary[i].second));
  }
  out += ']';
}

}  // namespace

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

std::string replay_data_json(const ReplayInput &input, int moves_per_frame) {
  const GridHistory &h = *input.history;
  const mapping::GridGeometry &g = h.geometry();
  const MapTones &t = input.tones;
  std::string out = fmt::format(
      "{{\"version\":1,\"title\":{},\"caption\":{},\"width\":{},\"height\":{},\"k\":{},\"cell_size_m\":{},"
      "\"initial\":{},\"occupied_increment\":{:.4f},\"free_increment\":{:.4f},\"steps\":{},\"moves_per_frame\":{},"
      "\"reachable\":{},",
      quoted(input.title), quoted(input.caption), g.width_cells, g.height_cells, g.subcells, g.cell_size_m,
      encoded(h.initial_log_odds(), t), t.occupied_increment, t.free_increment, input.steps, moves_per_frame,
      input.reachable_cells);
  // About 12 bytes a change and 24 an arrival: reserved, so that the data is not copied as it grows.
  out.reserve(out.size() + 12 * h.change_log().size() + 24 * h.arrivals().size() + 4096);
  std::vector<long> goals;
  for (const mapping::Cell c : input.goals) {
    goals.push_back(c.x);
    goals.push_back(c.y);
  }
  out += "\"goals\":";
  append_ints(out, goals);
  out += ",\"landmarks\":[";
  for (std::size_t i = 0; i < input.landmarks.size(); ++i) {
    const LandmarkMark &l = input.landmarks[i];
    fmt::format_to(std::back_inserter(out), "{}{:.4f},{:.4f},{:.4f},{},{},{}", i == 0 ? "" : ",",
                   (l.at.x_m - g.origin.x_m) / g.cell_size_m, (l.at.y_m - g.origin.y_m) / g.cell_size_m,
                   l.radius_m / g.cell_size_m, static_cast<int>(l.colour.r), static_cast<int>(l.colour.g),
                   static_cast<int>(l.colour.b));
  }
  out += "],";
  append_path(out, h);
  out += ',';
  append_frames(out, input, moves_per_frame);
  out += ',';
  append_summary(out, input);
  out += '}';
  return out;
}

std::optional<Replay> replay_html(const ReplayInput &input) {
  const int moves = std::max<int>(1, static_cast<int>(input.history->arrivals().size()));
  for (int per = 1;; per = std::min(per * 2, moves)) {
    std::string html = page_with_data(kReplayPage, escaped_for_script(replay_data_json(input, per)));
    if (html.size() <= input.max_bytes) return Replay{std::move(html), per};
    if (per >= moves) return std::nullopt;
  }
}

}  // namespace app
