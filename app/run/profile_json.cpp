#include "app/run/profile_json.hpp"

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "common/input_file.hpp"
#include "maze/world/world.hpp"

namespace app {
namespace {

using Json = nlohmann::ordered_json;
using maze::sim::BumperSpec;
using maze::sim::DistanceSensorSpec;
using maze::sim::LidarSpec;
using maze::sim::LookupRow;
using maze::sim::RobotProfile;

// ---- writing ----

Json to_json(const LidarSpec &l) {
  return Json{{"name", l.name},
              {"horizontal_resolution", l.horizontal_resolution},
              {"fov_rad", l.fov_rad},
              {"min_range_m", l.min_range_m},
              {"max_range_m", l.max_range_m},
              {"noise", l.noise},
              {"frequency_hz", l.frequency_hz},
              {"resolution_m", l.resolution_m},
              {"height_m", l.height_m}};
}

Json to_json(const LookupRow &r) {
  return Json{{"distance_m", r.distance_m}, {"value", r.value}, {"noise_fraction", r.noise_fraction}};
}

Json to_json(const DistanceSensorSpec &d) {
  Json table = Json::array();
  for (const LookupRow &r : d.lookup_table) table.push_back(to_json(r));
  return Json{{"name", d.name},
              {"angle_rad", d.angle_rad},
              {"aperture_rad", d.aperture_rad},
              {"rays", d.rays},
              {"lookup_table", table},
              {"type", std::string(maze::sim::to_string(d.type))},
              {"gaussian_width", d.gaussian_width}};
}

Json to_json(const BumperSpec &b) {
  return Json{{"name", b.name}, {"angle_rad", b.angle_rad}, {"half_arc_rad", b.half_arc_rad}};
}

template <typename T>
Json list(const std::vector<T> &items) {
  Json out = Json::array();
  for (const T &item : items) out.push_back(to_json(item));
  return out;
}

// ---- reading: each value by its key path, every key required, no other allowed ----

class Node {
 public:
  Node(const Json &json, std::string path) : json_(json), path_(std::move(path)) {}

  // Checks that this is an object with these keys and no other, each present unless it is one
  // of `optional` (which must also be among `keys`).
  const Node &object(std::initializer_list<const char *> keys, std::initializer_list<const char *> optional = {}) const {
    if (!json_.is_object()) fail("must be an object");
    for (const auto &item : json_.items()) {
      if (std::none_of(keys.begin(), keys.end(), [&](const char *k) { return item.key() == k; })) {
        std::string known;
        for (const char *k : keys) known += fmt::format("{}{}", known.empty() ? "" : ", ", k);
        Node(item.value(), key_path(item.key())).fail(fmt::format("is not a known key (known: {})", known));
      }
    }
    for (const char *k : keys) {
      const bool may_miss = std::any_of(optional.begin(), optional.end(), [&](const char *o) { return std::string_view(o) == k; });
      if (!may_miss && !json_.contains(k)) Node(json_, key_path(k)).fail("is missing");
    }
    return *this;
  }

  Node at(const char *key) const { return Node(json_.at(key), key_path(key)); }
  bool has(const char *key) const { return json_.is_object() && json_.contains(key); }

  double number(const char *key) const {
    const Node n = at(key);
    if (!n.json_.is_number()) n.fail("must be a number");
    return n.json_.get<double>();
  }

  int whole_number(const char *key) const {
    const Node n = at(key);
    if (!n.json_.is_number_integer()) n.fail("must be a whole number");
    if (n.json_.is_number_unsigned() && n.json_.get<unsigned long long>() > 1'000'000'000ULL) {
      n.fail(fmt::format("is out of range (got {})", n.json_.get<unsigned long long>()));
    }
    const auto v = n.json_.get<long long>();
    if (v < -1'000'000'000LL || v > 1'000'000'000LL) n.fail(fmt::format("is out of range (got {})", v));
    return static_cast<int>(v);
  }

  std::string text(const char *key) const {
    const Node n = at(key);
    if (!n.json_.is_string()) n.fail("must be a string");
    return n.json_.get<std::string>();
  }

  template <typename T>
  std::vector<T> items(const char *key, T (*read)(const Node &)) const {
    const Node n = at(key);
    if (!n.json_.is_array()) n.fail("must be a list");
    std::vector<T> out;
    for (std::size_t i = 0; i < n.json_.size(); ++i) {
      out.push_back(read(Node(n.json_[i], fmt::format("{}[{}]", n.path_, i))));
    }
    return out;
  }

  [[noreturn]] void fail(const std::string &what) const {
    throw common::InputError(fmt::format("{} {}", path_.empty() ? "the profile" : path_, what));
  }

 private:
  std::string key_path(const std::string &key) const { return path_.empty() ? key : path_ + "." + key; }

  const Json &json_;
  std::string path_;
};

// resolution_m (0: ranges not quantised) and height_m (0: at the robot's origin) may be left
// out, so a profile saved before lidars had them still loads.
LidarSpec read_lidar(const Node &n) {
  n.object({"name", "horizontal_resolution", "fov_rad", "min_range_m", "max_range_m", "noise",
            "frequency_hz", "resolution_m", "height_m"},
           {"resolution_m", "height_m"});
  return {n.text("name"),         n.whole_number("horizontal_resolution"), n.number("fov_rad"),
          n.number("min_range_m"), n.number("max_range_m"),                n.number("noise"),
          n.number("frequency_hz"), n.has("resolution_m") ? n.number("resolution_m") : 0.0,
          n.has("height_m") ? n.number("height_m") : 0.0};
}

LookupRow read_row(const Node &n) {
  n.object({"distance_m", "value", "noise_fraction"});
  return {n.number("distance_m"), n.number("value"), n.number("noise_fraction")};
}

maze::sim::DistanceSensorType read_sensor_type(const Node &n) {
  const std::string text = n.text("type");
  const auto type = maze::sim::parse_distance_sensor_type(text);
  if (!type) n.at("type").fail(fmt::format("must be \"generic\", \"infra-red\" or \"sonar\" (got \"{}\")", text));
  return *type;
}

DistanceSensorSpec read_distance_sensor(const Node &n) {
  n.object({"name", "angle_rad", "aperture_rad", "rays", "lookup_table", "type", "gaussian_width"});
  return {n.text("name"),     n.number("angle_rad"),          n.number("aperture_rad"), n.whole_number("rays"),
          n.items("lookup_table", &read_row), read_sensor_type(n), n.number("gaussian_width")};
}

BumperSpec read_bumper(const Node &n) {
  n.object({"name", "angle_rad", "half_arc_rad"});
  return {n.text("name"), n.number("angle_rad"), n.number("half_arc_rad")};
}

RobotProfile read_profile(const Node &n) {
  if (n.has("speed_run")) {
    n.object({"name", "description", "wheel_radius_m", "axle_m", "body_radius_m",
              "max_wheel_velocity_rad_s", "left_motor", "right_motor", "left_encoder",
              "right_encoder", "imu", "gps", "lidars", "distance_sensors", "bumpers", "speed_run"});
  } else {
    n.object({"name", "description", "wheel_radius_m", "axle_m", "body_radius_m",
              "max_wheel_velocity_rad_s", "left_motor", "right_motor", "left_encoder",
              "right_encoder", "imu", "gps", "lidars", "distance_sensors", "bumpers"});
  }
  RobotProfile p;
  if (n.has("speed_run")) {
    const Node s = n.at("speed_run");
    s.object({"acceleration_m_s2", "top_speed_m_s"});
    p.speed_run = maze::sim::SpeedRunProfile{s.number("acceleration_m_s2"), s.number("top_speed_m_s")};
  }
  p.name = n.text("name");
  p.description = n.text("description");
  p.wheel_radius_m = n.number("wheel_radius_m");
  p.axle_m = n.number("axle_m");
  p.body_radius_m = n.number("body_radius_m");
  p.max_wheel_velocity_rad_s = n.number("max_wheel_velocity_rad_s");
  p.left_motor = n.text("left_motor");
  p.right_motor = n.text("right_motor");
  p.left_encoder = n.text("left_encoder");
  p.right_encoder = n.text("right_encoder");
  p.imu = n.text("imu");
  p.gps = n.text("gps");
  p.lidars = n.items("lidars", &read_lidar);
  p.distance_sensors = n.items("distance_sensors", &read_distance_sensor);
  p.bumpers = n.items("bumpers", &read_bumper);
  return p;
}

// Line and column (from 1, in bytes) of the byte at `offset` (from 0).
common::SourceLocation location_of(std::string_view text, std::size_t offset, const std::string &file) {
  offset = std::min(offset, text.size());
  const std::string_view before = text.substr(0, offset);
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const std::size_t last_newline = before.rfind('\n');
  const std::size_t column = last_newline == std::string_view::npos ? offset + 1 : offset - last_newline;
  return {file, static_cast<int>(line), static_cast<int>(column)};
}

// nlohmann's message without its "[json.exception.parse_error.101] parse error at line L,
// column C: " prefix (the location is ours).
std::string parse_reason(const std::string &what) {
  const std::size_t column = what.find("column ");
  const std::size_t colon = column == std::string::npos ? std::string::npos : what.find(": ", column);
  if (colon != std::string::npos) return what.substr(colon + 2);
  const std::size_t bracket = what.find("] ");
  return bracket == std::string::npos ? what : what.substr(bracket + 2);
}

// Where the parser gave up, as its SAX interface reports it: the parse errors nlohmann
// throws without a byte offset (a number past a double's range, out_of_range.406) get one.
class StopLocator final : public nlohmann::json_sax<Json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t &) override { return true; }
  bool string(string_t &) override { return true; }
  bool binary(binary_t &) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t &) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string &last_token, const nlohmann::detail::exception &) override {
    token_start = position - std::min(position, last_token.size());
    token = last_token;
    return false;
  }
  std::size_t token_start = 0;  // from 0
  std::string token;
};

// The located error for a number nlohmann reads past a double's range ("1e999").
common::InputError number_out_of_range(std::string_view text, const std::string &file) {
  StopLocator locator;
  Json::sax_parse(text.begin(), text.end(), &locator);
  return common::InputError(location_of(text, locator.token_start, file),
                            fmt::format("{} is not a finite number (past a double's range)", locator.token));
}

}  // namespace

std::string profile_to_json(const RobotProfile &p) {
  Json j{{"name", p.name},
               {"description", p.description},
               {"wheel_radius_m", p.wheel_radius_m},
               {"axle_m", p.axle_m},
               {"body_radius_m", p.body_radius_m},
               {"max_wheel_velocity_rad_s", p.max_wheel_velocity_rad_s},
               {"left_motor", p.left_motor},
               {"right_motor", p.right_motor},
               {"left_encoder", p.left_encoder},
               {"right_encoder", p.right_encoder},
               {"imu", p.imu},
               {"gps", p.gps},
               {"lidars", list(p.lidars)},
               {"distance_sensors", list(p.distance_sensors)},
               {"bumpers", list(p.bumpers)}};
  if (p.speed_run) {
    j["speed_run"] = Json{{"acceleration_m_s2", p.speed_run->acceleration_m_s2},
                          {"top_speed_m_s", p.speed_run->top_speed_m_s}};
  }
  return j.dump(2) + "\n";
}

RobotProfile profile_from_json(std::string_view text, const std::string &file) {
  Json json;
  try {
    json = Json::parse(text.begin(), text.end());
  } catch (const Json::parse_error &e) {
    // e.byte counts from 1 and names the last byte read (0 for an empty input).
    const std::size_t offset = e.byte == 0 ? 0 : e.byte - 1;
    throw common::InputError(location_of(text, offset, file),
                             "invalid JSON: " + parse_reason(e.what()));
  } catch (const Json::out_of_range &) {
    throw number_out_of_range(text, file);
  }
  try {
    const RobotProfile profile = read_profile(Node(json, ""));
    maze::sim::validate_profile(profile);
    return profile;
  } catch (const common::InputError &e) {
    throw common::InputError(common::SourceLocation{file, 0, 0}, e.message());
  }
}

bool names_a_profile_file(std::string_view robot) {
  return robot.find('/') != std::string_view::npos || robot.ends_with(".json");
}

RobotProfile resolve_robot(const std::string &robot) {
  if (!names_a_profile_file(robot)) return maze::sim::find_profile(robot);
  return profile_from_json(common::read_text(robot, "robot profile (JSON)", common::kRobotProfileLimits), robot);
}

}  // namespace app
