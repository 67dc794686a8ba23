#include "common/parse_number.hpp"
#include "robot/controller_args.hpp"

#include <cmath>
#include <functional>
#include <optional>

#include <fmt/format.h>

#include "common/error.hpp"

namespace robot {

namespace {

// A value that does not read: the message says which argument and what was expected.
[[noreturn]] void bad(std::string_view arg, std::string_view expected) {
  throw common::InputError(fmt::format("controller argument '{}': expected {}", arg, expected));
}

template <typename Number>
std::optional<Number> number(std::string_view text) {
  return common::parse_number<Number>(text);
}

// Splits at the first `count` separators; the last part keeps the rest (a name with commas).
std::optional<std::vector<std::string_view>> split(std::string_view text, char sep, std::size_t parts) {
  std::vector<std::string_view> out;
  while (out.size() + 1 < parts) {
    const std::size_t at = text.find(sep);
    if (at == std::string_view::npos) return std::nullopt;
    out.push_back(text.substr(0, at));
    text.remove_prefix(at + 1);
  }
  out.push_back(text);
  return out;
}

// Reads `parts` numbers separated by `sep`.
template <typename Number>
std::optional<std::vector<Number>> numbers(std::string_view text, char sep, std::size_t parts) {
  const auto fields = split(text, sep, parts);
  if (!fields) return std::nullopt;
  std::vector<Number> out;
  for (const std::string_view f : *fields) {
    const auto v = number<Number>(f);
    if (!v) return std::nullopt;
    out.push_back(*v);
  }
  return out;
}

struct Arg {
  std::string_view text;   // the whole argument, for messages
  std::string_view value;  // after '='
};

double real(const Arg &a) {
  const auto v = number<double>(a.value);
  if (!v) bad(a.text, "a number");
  return *v;
}

int integer(const Arg &a) {
  const auto v = number<int>(a.value);
  if (!v) bad(a.text, "an integer");
  return *v;
}

bool flag(const Arg &a) {
  if (a.value == "true") return true;
  if (a.value == "false") return false;
  bad(a.text, "true or false");
}

mapping::Cell cell(const Arg &a) {
  const auto v = numbers<int>(a.value, ',', 2);
  if (!v) bad(a.text, "X,Y cell coordinates, e.g. 0,0");
  return {(*v)[0], (*v)[1]};
}

mapping::Heading heading(const Arg &a) {
  for (const mapping::Heading h : mapping::kHeadings) {
    if (a.value.size() == 1 && a.value[0] == mapping::to_char(h)) return h;
  }
  bad(a.text, "N, E, S or W");
}

std::string name(const Arg &a) {
  if (a.value.empty()) bad(a.text, "a device name");
  return std::string(a.value);
}

void size(const Arg &a, ControllerOptions &o) {
  const auto v = numbers<int>(a.value, 'x', 2);
  if (!v) bad(a.text, "WxH, e.g. 4x4");
  o.geometry.width_cells = (*v)[0];
  o.geometry.height_cells = (*v)[1];
}

void origin(const Arg &a, ControllerOptions &o) {
  const auto v = numbers<double>(a.value, ',', 2);
  if (!v) bad(a.text, "X,Y in metres, e.g. 0,0");
  o.geometry.origin = {(*v)[0], (*v)[1]};
}

void log_base(const Arg &a, ControllerOptions &o) {
  if (a.value == "e") {
    o.sensor.base = mapping::LogBase::e;
  } else if (a.value == "10") {
    o.sensor.base = mapping::LogBase::ten;
  } else {
    bad(a.text, "e or 10");
  }
}

void clamp(const Arg &a, ControllerOptions &o) {
  const auto v = numbers<double>(a.value, ',', 2);
  if (!v) bad(a.text, "MIN,MAX log-odds, e.g. -2,3.5");
  o.sensor.clamp = mapping::Clamp{(*v)[0], (*v)[1]};
}

void bumper(const Arg &a, ControllerOptions &o) {
  const auto f = split(a.value, ',', 3);
  const auto angle = f ? number<double>((*f)[0]) : std::nullopt;
  const auto offset = f ? number<double>((*f)[1]) : std::nullopt;
  if (!angle || !offset || (*f)[2].empty()) bad(a.text, "ANGLE_RAD,OFFSET_M,NAME");
  o.sensing.bumpers.push_back({std::string((*f)[2]), *angle, *offset});
}

void range(const Arg &a, ControllerOptions &o) {
  const auto f = split(a.value, ',', 6);
  std::vector<double> v;
  for (std::size_t i = 0; f && i < 5; ++i) {
    if (const auto x = number<double>((*f)[i])) v.push_back(*x);
  }
  if (v.size() != 5 || (*f)[5].empty()) bad(a.text, "ANGLE_RAD,OFFSET_M,MAX_M,APERTURE_RAD,ERROR,NAME");
  o.sensing.ranges.push_back({std::string((*f)[5]), v[0], v[1], v[2], v[3], v[4]});
}

using Setter = std::function<void(const Arg &, ControllerOptions &)>;

struct Key {
  std::string_view key;
  Setter set;
};

// Every key the controller reads, in the order format_controller_args writes them.
const std::vector<Key> &keys() {
  static const std::vector<Key> table = {
      {"size", size},
      {"cell-size", [](const Arg &a, ControllerOptions &o) { o.geometry.cell_size_m = real(a); }},
      {"origin", origin},
      {"subcells", [](const Arg &a, ControllerOptions &o) { o.geometry.subcells = integer(a); }},
      {"start", [](const Arg &a, ControllerOptions &o) { o.start = cell(a); }},
      {"heading", [](const Arg &a, ControllerOptions &o) { o.start_heading = heading(a); }},
      {"goal", [](const Arg &a, ControllerOptions &o) { o.goals.push_back(cell(a)); }},
      {"model", [](const Arg &a, ControllerOptions &o) { o.model.kind = sensing::parse_model(a.value); }},
      {"strategy", [](const Arg &a, ControllerOptions &o) { o.strategy = explore::parse_strategy(a.value); }},
      {"hit-depth", [](const Arg &a, ControllerOptions &o) { o.model.hit_depth = integer(a); }},
      {"ignore-no-return", [](const Arg &a, ControllerOptions &o) { o.model.ignore_no_return = flag(a); }},
      {"threshold", [](const Arg &a, ControllerOptions &o) { o.occupied_threshold = static_cast<float>(real(a)); }},
      {"p-free", [](const Arg &a, ControllerOptions &o) { o.sensor.p_free = real(a); }},
      {"p-occ", [](const Arg &a, ControllerOptions &o) { o.sensor.p_occ = real(a); }},
      {"prior", [](const Arg &a, ControllerOptions &o) { o.sensor.prior = real(a); }},
      {"log-base", log_base},
      {"clamp", clamp},
      {"pie-beta-rad", [](const Arg &a, ControllerOptions &o) { o.sensing.range_model.pie_half_angle_rad = real(a); }},
      {"pie-alpha", [](const Arg &a, ControllerOptions &o) { o.sensing.range_model.pie_contact_m = real(a); }},
      {"pie-usable", [](const Arg &a, ControllerOptions &o) { o.sensing.range_model.pie_usable_fraction = real(a); }},
      {"speed-run", [](const Arg &a, ControllerOptions &o) { o.speed_run = flag(a); }},
      {"max-steps", [](const Arg &a, ControllerOptions &o) {
         const auto v = number<std::int64_t>(a.value);
         if (!v) bad(a.text, "an integer");
         o.motion.max_steps = *v;
       }},
      {"wheel-radius", [](const Arg &a, ControllerOptions &o) { o.motion.wheel_radius_m = real(a); }},
      {"axle", [](const Arg &a, ControllerOptions &o) { o.motion.axle_m = real(a); }},
      {"lidar-noise", [](const Arg &a, ControllerOptions &o) { o.scan_filter.range_noise_m = real(a); }},
      {"left-motor", [](const Arg &a, ControllerOptions &o) { o.devices.left_motor = name(a); }},
      {"right-motor", [](const Arg &a, ControllerOptions &o) { o.devices.right_motor = name(a); }},
      {"left-encoder", [](const Arg &a, ControllerOptions &o) { o.devices.left_encoder = name(a); }},
      {"right-encoder", [](const Arg &a, ControllerOptions &o) { o.devices.right_encoder = name(a); }},
      {"imu", [](const Arg &a, ControllerOptions &o) { o.devices.imu = name(a); }},
      {"gps", [](const Arg &a, ControllerOptions &o) { o.devices.gps = std::string(a.value); }},
      {"lidar", [](const Arg &a, ControllerOptions &o) { o.devices.lidar = name(a); }},
      {"bumper", bumper},
      {"range", range},
  };
  return table;
}

std::string known_keys() {
  std::string out;
  for (const Key &k : keys()) out += fmt::format("{}--{}", out.empty() ? "" : ", ", k.key);
  return out;
}

void apply_arg(std::string_view text, ControllerOptions &options) {
  const std::size_t eq = text.find('=');
  if (text.starts_with("--") && eq != std::string_view::npos) {
    const std::string_view key = text.substr(2, eq - 2);
    for (const Key &k : keys()) {
      if (k.key == key) return k.set(Arg{text, text.substr(eq + 1)}, options);
    }
  }
  throw common::InputError(
      fmt::format("unknown controller argument '{}' (known, as --key=value: {})", text, known_keys()));
}

std::string num(double v) { return fmt::format("{}", v); }

}  // namespace

ControllerOptions parse_controller_args(std::span<const std::string> args) {
  ControllerOptions options;
  bool sized = false;
  for (const std::string &arg : args) {
    apply_arg(arg, options);
    sized = sized || std::string_view(arg).starts_with("--size=");
  }
  if (!sized) throw common::InputError("missing controller argument --size=WxH (the maze's size in cells)");
  validate(options);
  return options;
}

std::vector<std::string> format_controller_args(const ControllerOptions &o) {
  const ControllerOptions d;
  std::vector<std::string> a;
  const auto put = [&a](std::string_view key, const std::string &value) { a.push_back(fmt::format("--{}={}", key, value)); };
  const mapping::GridGeometry &g = o.geometry;
  put("size", fmt::format("{}x{}", g.width_cells, g.height_cells));
  put("cell-size", num(g.cell_size_m));
  put("origin", fmt::format("{},{}", num(g.origin.x_m), num(g.origin.y_m)));
  put("subcells", std::to_string(g.subcells));
  put("start", fmt::format("{},{}", o.start.x, o.start.y));
  put("heading", std::string(1, mapping::to_char(o.start_heading)));
  for (const mapping::Cell goal : o.goals) put("goal", fmt::format("{},{}", goal.x, goal.y));
  put("model", std::string(sensing::to_string(o.model.kind)));
  put("strategy", std::string(explore::to_string(o.strategy)));
  if (o.model.hit_depth != d.model.hit_depth) put("hit-depth", std::to_string(o.model.hit_depth));
  if (o.model.ignore_no_return) put("ignore-no-return", "true");
  if (o.occupied_threshold) put("threshold", num(*o.occupied_threshold));
  if (o.sensor.p_free != d.sensor.p_free) put("p-free", num(o.sensor.p_free));
  if (o.sensor.p_occ != d.sensor.p_occ) put("p-occ", num(o.sensor.p_occ));
  if (o.sensor.prior != d.sensor.prior) put("prior", num(o.sensor.prior));
  if (o.sensor.base == mapping::LogBase::ten) put("log-base", "10");
  if (o.sensor.clamp) put("clamp", fmt::format("{},{}", num(o.sensor.clamp->min), num(o.sensor.clamp->max)));
  const sensing::RangeModelOptions &r = o.sensing.range_model;
  if (r.pie_half_angle_rad != d.sensing.range_model.pie_half_angle_rad) put("pie-beta-rad", num(r.pie_half_angle_rad));
  if (r.pie_contact_m != d.sensing.range_model.pie_contact_m) put("pie-alpha", num(r.pie_contact_m));
  if (r.pie_usable_fraction != d.sensing.range_model.pie_usable_fraction) put("pie-usable", num(r.pie_usable_fraction));
  if (o.speed_run) put("speed-run", "true");
  put("max-steps", std::to_string(o.motion.max_steps));
  put("wheel-radius", num(o.motion.wheel_radius_m));
  put("axle", num(o.motion.axle_m));
  put("lidar-noise", num(o.scan_filter.range_noise_m));
  put("left-motor", o.devices.left_motor);
  put("right-motor", o.devices.right_motor);
  put("left-encoder", o.devices.left_encoder);
  put("right-encoder", o.devices.right_encoder);
  put("imu", o.devices.imu);
  put("gps", o.devices.gps);
  put("lidar", o.devices.lidar);
  for (const BumperMount &b : o.sensing.bumpers) put("bumper", fmt::format("{},{},{}", num(b.angle_rad), num(b.offset_m), b.name));
  for (const RangeSensorMount &s : o.sensing.ranges) {
    put("range", fmt::format("{},{},{},{},{},{}", num(s.angle_rad), num(s.offset_m), num(s.max_range_m),
                             num(s.aperture_rad), num(s.range_error), s.name));
  }
  return a;
}

}  // namespace robot
