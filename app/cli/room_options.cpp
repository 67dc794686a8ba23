#include "app/cli/room_options.hpp"

#include <cmath>
#include <cstdint>
#include <string_view>

#include <fmt/format.h>

#include "app/cli/demo_commands.hpp"
#include "common/error.hpp"

namespace app {
namespace {

using O = MetricRunOptions;

mapping::Point point_of(const std::string &text, const std::string &option) {
  const std::vector<double> v = parse_number_list(text, option, 2);
  return {v[0], v[1]};
}

void set_cells(O &o, const std::string &text) {
  const std::vector<double> c = parse_number_list(text, "--cells", 2);
  for (const double v : c) {
    if (!(v >= 1 && v <= sensing::kMaxMetricCellsPerSide && v == std::floor(v))) {
      throw common::InputError(fmt::format("--cells must be X,Y with each a whole number 1 to {} (got {})",
                                           sensing::kMaxMetricCellsPerSide, text));
    }
  }
  o.cells_x = static_cast<int>(c[0]);
  o.cells_y = static_cast<int>(c[1]);
}

// "X,Y;X,Y;...": the waypoints in metres.
void set_waypoints(O &o, const std::string &text) {
  o.room.waypoints.clear();
  std::size_t start = 0;
  for (;;) {
    const std::size_t semi = text.find(';', start);
    const std::size_t length = semi == std::string::npos ? std::string::npos : semi - start;
    o.room.waypoints.push_back(point_of(text.substr(start, length), "--waypoints"));
    if (semi == std::string::npos) return;
    start = semi + 1;
  }
}

void set_snapshot_steps(O &o, const std::string &text) {
  o.snapshot_steps.clear();
  for (const double v : parse_number_list(text, "--snapshot-steps")) {
    if (!(v >= 1 && v == std::floor(v))) throw common::InputError("--snapshot-steps must be whole numbers >= 1");
    o.snapshot_steps.push_back(static_cast<std::int64_t>(v));
  }
}

void set_depth_reading(O &o, const std::string &text) {
  if (text != "range" && text != "axial") {
    throw common::InputError("--depth-reading must be range or axial (got " + text + ")");
  }
  o.depth_reading = text == "axial" ? sensing::DepthReading::axial : sensing::DepthReading::range;
}

void set_model(O &o, const std::string &text) {
  if (text == "cell") {
    throw common::InputError("--model cell reads a maze's cell sides; in a room the lidar marks with --model ray");
  }
  o.model.kind = sensing::parse_model(text);
}

// A field CLI11 reads as it is.
OptionField<O> plain(std::string_view flag, std::string (*help)(const O &), FieldRef (*value)(O &)) {
  return {flag.substr(2), flag, "", help, value, nullptr, "", nullptr};
}

// A field whose text `parse` reads.
OptionField<O> parsed(std::string_view flag, std::string (*help)(const O &), void (*parse)(O &, const std::string &),
                      std::string_view value_type = "") {
  return {flag.substr(2), flag, "", help, nullptr, parse, value_type, nullptr};
}

// Registered by its own code (room_options.hpp says which).
OptionField<O> own(std::string_view flag) { return {flag.substr(2), flag, "", nullptr, nullptr, nullptr, "", nullptr}; }

bool waypoints(const O &o) { return o.room.strategy == robot::MetricStrategy::waypoints; }
bool wavefront(const O &o) { return o.room.strategy == robot::MetricStrategy::wavefront; }

// The room's own rules; the depth rays' read like the set-up table's (app/run/model_rules.hpp).
constexpr OptionUse<O> kRoomOptionUses[] = {
    {"--waypoints", "without --strategy waypoints", waypoints},
    {"--laps", "without --strategy waypoints", waypoints},
    {"--goal", "without --strategy wavefront", wavefront},
    {"--dilate", "without --strategy wavefront (frontier keeps the body's radius clear)", wavefront},
};

}  // namespace

template <>
std::span<const OptionField<O>> option_fields() {
  static const std::vector<OptionField<O>> fields{
      own("--start"),
      own("--resolution"),
      parsed("--strategy",
             [](const O &d) {
               return fmt::format("waypoints, wavefront, frontier or wander (default {})", robot::to_string(d.room.strategy));
             },
             [](O &o, const std::string &text) { o.room.strategy = robot::parse_metric_strategy(text); }),
      parsed("--model",
             [](const O &d) {
               return fmt::format("ray (lidar), pie or cone (IR/sonar ring), bump or depth (default {})",
                                  sensing::to_string(d.model.kind));
             },
             set_model),
      plain("--robot", [](const O &) { return std::string("a robot profile or JSON file (default the set-up's robot)"); },
                         [](O &o) -> FieldRef { return &o.robot; }),
      parsed("--cells", [](const O &) { return std::string("X,Y: numCells over the boundary (square cells)"); }, set_cells),
      parsed("--waypoints", [](const O &) { return std::string("X,Y;X,Y;...: the points to visit, m (waypoints)"); },
             set_waypoints),
      plain("--laps",
                 [](const O &d) {
                   return fmt::format("N: drive the waypoints N times over; 0: until --time-limit (default {})", d.room.laps);
                 },
                 [](O &o) -> FieldRef { return &o.room.laps; }),
      parsed("--goal", [](const O &) { return std::string("X,Y: the goal, m, of wavefront (default the world file's first goal)"); },
             [](O &o, const std::string &text) { o.room.goal = point_of(text, "--goal"); }),
      plain("--dilate",
                 [](const O &d) {
                   return fmt::format("N: wavefront: obstacles grown by N cells for planning (default {})", d.room.dilate);
                 },
                 [](O &o) -> FieldRef { return &o.room.dilate; }),
      plain("--time-limit",
                    [](const O &) { return std::string("S: stop after S simulated seconds; wander needs it (default none)"); },
                    [](O &o) -> FieldRef { return &o.room.time_limit_s; }),
      parsed("--snapshots-at", [](const O &) { return std::string("T1,T2,...: print the map at these simulated seconds"); },
             [](O &o, const std::string &text) { o.snapshots_at_s = parse_number_list(text, "--snapshots-at"); }),
      parsed("--snapshot-steps", [](const O &) { return std::string("N1,N2,...: print the map at these control steps"); },
             set_snapshot_steps),
      plain("--threshold",
                    [](const O &) { return std::string("log-odds drawn W at or above (default 0; bump and depth -0.5)"); },
                    [](O &o) -> FieldRef { return &o.threshold; }),
      plain("--max-steps", [](const O &) { return std::string("control steps at most (default 2000000)"); },
                          [](O &o) -> FieldRef { return &o.max_steps; }),
      parsed("--depth-reading",
             [](const O &) {
               return std::string("range or axial (--model depth): the depth rays report the range along the ray, or the "
                                  "depth along the heading from --depth-origin, as a depth camera and the homework's "
                                  "simulator do (default range)");
             },
             set_depth_reading),
      parsed("--depth-origin",
             [](const O &) {
               return std::string("X,Y (--model depth): the depth rays leave this point of the robot, m, x forward, y "
                                  "left (default none: each from the rim, trace.csv's depths from the centre)");
             },
             [](O &o, const std::string &text) { o.depth_origin = point_of(text, "--depth-origin"); }),
      plain("--quiet", [](const O &) { return std::string("print the summary only"); },
                  [](O &o) -> FieldRef { return &o.quiet; }),
  };
  return fields;
}

std::vector<std::string> check_room_options_apply(const GivenOptions &given, const MetricRunOptions &options) {
  std::vector<std::string> warnings;
  add_no_effect_warnings(given, std::span<const OptionUse<O>>(kRoomOptionUses), options, warnings);
  if (options.model.kind != sensing::ModelKind::depth) {
    for (const char *option : {"--depth-reading", "--depth-origin"}) {
      if (!given.given(option)) continue;
      warnings.push_back(fmt::format("warning: {} has no effect with the {} model (read by depth)", option,
                                     sensing::to_string(options.model.kind)));
    }
  }
  return warnings;
}

void check_room_options(const MetricRunOptions &o) {
  if (o.cells_x && o.resolution_m) throw common::InputError("give --cells or --resolution, not both");
  if (o.threshold && !std::isfinite(*o.threshold)) {
    throw common::InputError(fmt::format("--threshold must be a finite log-odds value (got {})", *o.threshold));
  }
}

}  // namespace app
