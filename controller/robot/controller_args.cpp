#include "common/parse_number.hpp"
#include "robot/controller_args.hpp"

#include <cmath>
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

void max_steps(const Arg &a, ControllerOptions &o) {
  const auto v = number<std::int64_t>(a.value);
  if (!v) bad(a.text, "an integer");
  o.motion.max_steps = *v;
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

std::string num(double v) { return fmt::format("{}", v); }

// What a key writes: one value, several (a repeated key) or none (an option at its default).
using Values = std::vector<std::string>;
using Setter = void (*)(const Arg &, ControllerOptions &);
using Writer = void (*)(const ControllerOptions &o, const ControllerOptions &defaults, Values &out);

// A key's reading and its writing side by side: each key is described here once.
struct Key {
  std::string_view key;
  Setter set;
  Writer write;
};

using O = const ControllerOptions &;

// The grid, the start and goals, and the mapping options.
std::vector<Key> map_keys() {
  return {
      {"size", size,
       [](O o, O, Values &v) { v.push_back(fmt::format("{}x{}", o.geometry.width_cells, o.geometry.height_cells)); }},
      {"cell-size", [](const Arg &a, ControllerOptions &o) { o.geometry.cell_size_m = real(a); },
       [](O o, O, Values &v) { v.push_back(num(o.geometry.cell_size_m)); }},
      {"origin", origin,
       [](O o, O, Values &v) {
         v.push_back(fmt::format("{},{}", num(o.geometry.origin.x_m), num(o.geometry.origin.y_m)));
       }},
      {"subcells", [](const Arg &a, ControllerOptions &o) { o.geometry.subcells = integer(a); },
       [](O o, O, Values &v) { v.push_back(std::to_string(o.geometry.subcells)); }},
      {"start", [](const Arg &a, ControllerOptions &o) { o.start = cell(a); },
       [](O o, O, Values &v) { v.push_back(fmt::format("{},{}", o.start.x, o.start.y)); }},
      {"heading", [](const Arg &a, ControllerOptions &o) { o.start_heading = heading(a); },
       [](O o, O, Values &v) { v.emplace_back(1, mapping::to_char(o.start_heading)); }},
      {"goal", [](const Arg &a, ControllerOptions &o) { o.goals.push_back(cell(a)); },
       [](O o, O, Values &v) { for (const mapping::Cell g : o.goals) v.push_back(fmt::format("{},{}", g.x, g.y)); }},
      {"model", [](const Arg &a, ControllerOptions &o) { o.model.kind = sensing::parse_model(a.value); },
       [](O o, O, Values &v) { v.emplace_back(sensing::to_string(o.model.kind)); }},
      {"strategy", [](const Arg &a, ControllerOptions &o) { o.strategy = explore::parse_strategy(a.value); },
       [](O o, O, Values &v) { v.emplace_back(explore::to_string(o.strategy)); }},
      {"hit-depth", [](const Arg &a, ControllerOptions &o) { o.model.hit_depth = integer(a); },
       [](O o, O d, Values &v) {
         if (o.model.hit_depth != d.model.hit_depth) v.push_back(std::to_string(o.model.hit_depth));
       }},
      {"ignore-no-return", [](const Arg &a, ControllerOptions &o) { o.model.ignore_no_return = flag(a); },
       [](O o, O, Values &v) { if (o.model.ignore_no_return) v.emplace_back("true"); }},
      {"threshold", [](const Arg &a, ControllerOptions &o) { o.occupied_threshold = static_cast<float>(real(a)); },
       [](O o, O, Values &v) { if (o.occupied_threshold) v.push_back(num(*o.occupied_threshold)); }},
      {"p-free", [](const Arg &a, ControllerOptions &o) { o.sensor.p_free = real(a); },
       [](O o, O d, Values &v) { if (o.sensor.p_free != d.sensor.p_free) v.push_back(num(o.sensor.p_free)); }},
      {"p-occ", [](const Arg &a, ControllerOptions &o) { o.sensor.p_occ = real(a); },
       [](O o, O d, Values &v) { if (o.sensor.p_occ != d.sensor.p_occ) v.push_back(num(o.sensor.p_occ)); }},
      {"prior", [](const Arg &a, ControllerOptions &o) { o.sensor.prior = real(a); },
       [](O o, O d, Values &v) { if (o.sensor.prior != d.sensor.prior) v.push_back(num(o.sensor.prior)); }},
      {"log-base", log_base,
       [](O o, O, Values &v) { if (o.sensor.base == mapping::LogBase::ten) v.emplace_back("10"); }},
      {"clamp", clamp,
       [](O o, O, Values &v) {
         if (o.sensor.clamp) v.push_back(fmt::format("{},{}", num(o.sensor.clamp->min), num(o.sensor.clamp->max)));
       }},
      {"pie-beta-rad", [](const Arg &a, ControllerOptions &o) { o.sensing.range_model.pie_half_angle_rad = real(a); },
       [](O o, O d, Values &v) {
         const double x = o.sensing.range_model.pie_half_angle_rad;
         if (x != d.sensing.range_model.pie_half_angle_rad) v.push_back(num(x));
       }},
      {"pie-alpha", [](const Arg &a, ControllerOptions &o) { o.sensing.range_model.pie_contact_m = real(a); },
       [](O o, O d, Values &v) {
         const double x = o.sensing.range_model.pie_contact_m;
         if (x != d.sensing.range_model.pie_contact_m) v.push_back(num(x));
       }},
      {"pie-usable", [](const Arg &a, ControllerOptions &o) { o.sensing.range_model.pie_usable_fraction = real(a); },
       [](O o, O d, Values &v) {
         const double x = o.sensing.range_model.pie_usable_fraction;
         if (x != d.sensing.range_model.pie_usable_fraction) v.push_back(num(x));
       }},
  };
}

// The run's limits and the robot's description.
std::vector<Key> robot_keys() {
  return {
      {"speed-run", [](const Arg &a, ControllerOptions &o) { o.speed_run = flag(a); },
       [](O o, O, Values &v) { if (o.speed_run) v.emplace_back("true"); }},
      {"max-steps", max_steps, [](O o, O, Values &v) { v.push_back(std::to_string(o.motion.max_steps)); }},
      {"wheel-radius", [](const Arg &a, ControllerOptions &o) { o.motion.wheel_radius_m = real(a); },
       [](O o, O, Values &v) { v.push_back(num(o.motion.wheel_radius_m)); }},
      {"axle", [](const Arg &a, ControllerOptions &o) { o.motion.axle_m = real(a); },
       [](O o, O, Values &v) { v.push_back(num(o.motion.axle_m)); }},
      {"lidar-noise", [](const Arg &a, ControllerOptions &o) { o.scan_filter.range_noise_m = real(a); },
       [](O o, O, Values &v) { v.push_back(num(o.scan_filter.range_noise_m)); }},
      {"left-motor", [](const Arg &a, ControllerOptions &o) { o.devices.left_motor = name(a); },
       [](O o, O, Values &v) { v.push_back(o.devices.left_motor); }},
      {"right-motor", [](const Arg &a, ControllerOptions &o) { o.devices.right_motor = name(a); },
       [](O o, O, Values &v) { v.push_back(o.devices.right_motor); }},
      {"left-encoder", [](const Arg &a, ControllerOptions &o) { o.devices.left_encoder = name(a); },
       [](O o, O, Values &v) { v.push_back(o.devices.left_encoder); }},
      {"right-encoder", [](const Arg &a, ControllerOptions &o) { o.devices.right_encoder = name(a); },
       [](O o, O, Values &v) { v.push_back(o.devices.right_encoder); }},
      {"imu", [](const Arg &a, ControllerOptions &o) { o.devices.imu = name(a); },
       [](O o, O, Values &v) { v.push_back(o.devices.imu); }},
      {"gps", [](const Arg &a, ControllerOptions &o) { o.devices.gps = std::string(a.value); },
       [](O o, O, Values &v) { v.push_back(o.devices.gps); }},
      {"lidar", [](const Arg &a, ControllerOptions &o) { o.devices.lidar = name(a); },
       [](O o, O, Values &v) { v.push_back(o.devices.lidar); }},
      {"bumper", bumper,
       [](O o, O, Values &v) {
         for (const BumperMount &b : o.sensing.bumpers) {
           v.push_back(fmt::format("{},{},{}", num(b.angle_rad), num(b.offset_m), b.name));
         }
       }},
      {"range", range,
       [](O o, O, Values &v) {
         for (const RangeSensorMount &r : o.sensing.ranges) {
           v.push_back(fmt::format("{},{},{},{},{},{}", num(r.angle_rad), num(r.offset_m), num(r.max_range_m),
                                   num(r.aperture_rad), num(r.range_error), r.name));
         }
       }},
  };
}

// Every key the controller reads, in the order format_controller_args writes them.
const std::vector<Key> &keys() {
  static const std::vector<Key> table = [] {
    std::vector<Key> all = map_keys();
    for (Key &k : robot_keys()) all.push_back(k);
    return all;
  }();
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
  const ControllerOptions defaults;
  std::vector<std::string> args;
  Values values;
  for (const Key &k : keys()) {
    values.clear();
    k.write(o, defaults, values);
    for (const std::string &value : values) args.push_back(fmt::format("--{}={}", k.key, value));
  }
  return args;
}

std::vector<std::string_view> controller_arg_keys() {
  std::vector<std::string_view> names;
  for (const Key &k : keys()) names.push_back(k.key);
  return names;
}

}  // namespace robot
