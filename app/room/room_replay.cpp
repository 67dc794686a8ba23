// replay.html for a room run (app/room/room_replay.hpp).

#include "app/room/room_replay.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/room/room_replay_page.hpp"

namespace app {
namespace {

std::uint32_t packed(Rgb c) {
  return (static_cast<std::uint32_t>(c.r) << 16) | (static_cast<std::uint32_t>(c.g) << 8) | c.b;
}

std::string quoted(const std::string &text) { return nlohmann::json(text).dump(); }

template <typename T>
void append_list(std::string &out, const std::vector<T> &values) {
  out += '[';
  for (std::size_t i = 0; i < values.size(); ++i) fmt::format_to(std::back_inserter(out), "{}{}", i == 0 ? "" : ",", values[i]);
  out += ']';
}

}  // namespace

RoomReplay::RoomReplay(const sensing::RoomMap &map, const MapTones &tones)
    : map_(map), tones_(tones), initial_(packed(tone(tones.initial_log_odds, tones))),
      steps_per_frame_(static_cast<std::int64_t>((map.size() + 1999) / 2000)), last_(map.size(), initial_) {}

std::uint32_t RoomReplay::rgb_at(std::size_t n) const {
  return packed(tone(static_cast<float>(map_.log_odds_at(n)), tones_));
}

void RoomReplay::record(const robot::RoomController &c) {
  Frame f;
  f.step = c.steps();
  f.t_ms = std::lround(c.time_s() * 1000.0);
  f.x_mm = std::lround(c.position().x_m * 1000.0);
  f.y_mm = std::lround(c.position().y_m * 1000.0);
  f.yaw_mrad = std::lround(c.yaw_rad() * 1000.0);
  for (std::size_t n = 0; n < last_.size(); ++n) {
    const std::uint32_t now = rgb_at(n);
    if (now == last_[n]) continue;
    last_[n] = now;
    f.changes.emplace_back(static_cast<std::uint32_t>(n), now);
  }
  frames_.push_back(std::move(f));
}

void RoomReplay::on_step(const robot::RoomController &c) {
  if (c.steps() == 1 || c.steps() % steps_per_frame_ == 0) record(c);
}

void RoomReplay::finish(const robot::RoomController &c) {
  if (frames_.empty() || frames_.back().step != c.steps()) record(c);
}

std::vector<RoomReplay::Frame> RoomReplay::merged(std::size_t per) const {
  if (per <= 1) return frames_;
  std::vector<Frame> out;
  for (std::size_t first = 0; first < frames_.size(); first += per) {
    const std::size_t last = std::min(first + per, frames_.size()) - 1;
    std::map<std::uint32_t, std::uint32_t> changes;  // later frames overwrite
    for (std::size_t k = first; k <= last; ++k) {
      for (const auto &ch : frames_[k].changes) changes[ch.first] = ch.second;
    }
    Frame f = frames_[last];
    f.changes.assign(changes.begin(), changes.end());
    out.push_back(std::move(f));
  }
  return out;
}

std::string RoomReplay::data_json(const RoomReplayText &text, std::size_t per) const {
  const sensing::RoomBoundary &b = map_.spec().boundary;
  std::string out = fmt::format(
      "{{\"version\":1,\"title\":{},\"caption\":{},\"cells_x\":{},\"cells_y\":{},\"cell_m\":{},\"origin\":[{},{}],"
      "\"initial\":{},\"body_m\":{},\"start\":[{},{}],\"goal\":",
      quoted(text.title), quoted(text.caption), map_.cells_x(), map_.cells_y(), map_.cell_m(), b.x_start_m,
      b.y_start_m, initial_, text.body_radius_m, text.start.x_m, text.start.y_m);
  out += text.goal ? fmt::format("[{},{}]", text.goal->x_m, text.goal->y_m) : std::string("[]");
  std::vector<std::int64_t> steps;
  std::vector<long> times;
  std::vector<long> poses;
  std::string changes = "[";
  for (const Frame &f : merged(per)) {
    steps.push_back(f.step);
    times.push_back(f.t_ms);
    poses.insert(poses.end(), {f.x_mm, f.y_mm, f.yaw_mrad});
    std::vector<long> pairs;
    long previous = 0;
    for (const auto &ch : f.changes) {
      pairs.push_back(static_cast<long>(ch.first) - previous);
      pairs.push_back(static_cast<long>(ch.second));
      previous = static_cast<long>(ch.first);
    }
    if (changes.size() > 1) changes += ',';
    append_list(changes, pairs);
  }
  out += ",\"frames\":{\"step\":";
  append_list(out, steps);
  out += ",\"t_ms\":";
  append_list(out, times);
  out += ",\"pose\":";
  append_list(out, poses);
  out += ",\"changes\":" + changes + "]},\"summary\":[";
  for (std::size_t i = 0; i < text.summary.size(); ++i) {
    out += fmt::format("{}[{},{}]", i == 0 ? "" : ",", quoted(text.summary[i].first), quoted(text.summary[i].second));
  }
  return out + "]}";
}

std::optional<std::string> RoomReplay::html(const RoomReplayText &text, std::size_t max_bytes) const {
  const std::size_t all = std::max<std::size_t>(1, frames_.size());
  for (std::size_t per = 1;; per = std::min(per * 2, all)) {
    std::string page = page_with_data(kRoomReplayPage, escaped_for_script(data_json(text, per)));
    if (page.size() <= max_bytes) return page;
    if (per >= all) return std::nullopt;
  }
}

}  // namespace app
