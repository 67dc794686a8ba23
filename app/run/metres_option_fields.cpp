// A run in metres' own options, described once as the run's are (app/run/option_fields.hpp).

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "app/run/option_fields.hpp"
#include "app/run/option_values.hpp"
#include "common/error.hpp"

namespace app {

namespace {

using Metres = MetresOptions;

mapping::Point point_of(const std::string &text, const std::string &option) {
  const std::vector<double> v = parse_number_list(text, option, 2);
  return {v[0], v[1]};
}

void set_cells(Metres &o, const std::string &text) {
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
void set_waypoints(Metres &o, const std::string &text) {
  o.controller.waypoints.clear();
  std::size_t start = 0;
  for (;;) {
    const std::size_t semi = text.find(';', start);
    const std::size_t length = semi == std::string::npos ? std::string::npos : semi - start;
    o.controller.waypoints.push_back(point_of(text.substr(start, length), "--waypoints"));
    if (semi == std::string::npos) return;
    start = semi + 1;
  }
}

void set_snapshot_steps(Metres &o, const std::string &text) {
  o.snapshot_steps.clear();
  for (const double v : parse_number_list(text, "--snapshot-steps")) {
    if (!(v >= 1 && v == std::floor(v))) throw common::InputError("--snapshot-steps must be whole numbers >= 1");
    o.snapshot_steps.push_back(static_cast<std::int64_t>(v));
  }
}

void set_depth_reading(Metres &o, const std::string &text) {
  if (text != "range" && text != "axial") {
    throw common::InputError("--depth-reading must be range or axial (got " + text + ")");
  }
  o.depth_reading = text == "axial" ? sensing::DepthReading::axial : sensing::DepthReading::range;
}

// A field CLI11 reads as it is.
OptionField<Metres> metres_plain(std::string_view flag, std::string (*help)(const Metres &),
                                 FieldRef (*value)(Metres &)) {
  return {flag.substr(2), flag, "", help, value, nullptr, "", nullptr};
}

// A field whose text `parse` reads.
OptionField<Metres> metres_parsed(std::string_view flag, std::string (*help)(const Metres &),
                                  void (*parse)(Metres &, const std::string &)) {
  return {flag.substr(2), flag, "", help, nullptr, parse, "", nullptr};
}

}  // namespace

template <>
std::span<const OptionField<MetresOptions>> option_fields() {
  static const std::vector<OptionField<Metres>> fields{
      {"start", "--start", "", nullptr, nullptr, nullptr, "", nullptr},
      {"resolution", "--resolution", "", nullptr, nullptr, nullptr, "", nullptr},
      metres_parsed("--cells", [](const Metres &) { return std::string("X,Y: numCells over the boundary (square cells)"); },
                    set_cells),
      metres_parsed("--waypoints",
                    [](const Metres &) { return std::string("X,Y;X,Y;...: the points to visit, m (waypoints)"); },
                    set_waypoints),
      metres_plain("--laps",
                   [](const Metres &d) {
                     return fmt::format("N: drive the waypoints N times over; 0: until --time-limit (default {})",
                                        d.controller.laps);
                   },
                   [](Metres &o) -> FieldRef { return &o.controller.laps; }),
      metres_parsed("--goal",
                    [](const Metres &) {
                      return std::string("X,Y: the goal, m, of wavefront (default the world file's first goal)");
                    },
                    [](Metres &o, const std::string &text) { o.controller.goal = point_of(text, "--goal"); }),
      metres_plain("--dilate",
                   [](const Metres &d) {
                     return fmt::format("N: wavefront: obstacles grown by N cells for planning (default {})",
                                        d.controller.dilate);
                   },
                   [](Metres &o) -> FieldRef { return &o.controller.dilate; }),
      metres_parsed("--snapshots-at",
                    [](const Metres &) { return std::string("T1,T2,...: print the map at these simulated seconds"); },
                    [](Metres &o, const std::string &text) {
                      o.snapshots_at_s = parse_number_list(text, "--snapshots-at");
                    }),
      metres_parsed("--snapshot-steps",
                    [](const Metres &) { return std::string("N1,N2,...: print the map at these control steps"); },
                    set_snapshot_steps),
      metres_parsed("--depth-reading",
                    [](const Metres &) {
                      return std::string(
                          "range or axial (--model depth): the depth rays report the range along the ray, or the "
                          "depth along the heading from --depth-origin, as a depth camera and the homework's "
                          "simulator do (default range)");
                    },
                    set_depth_reading),
      metres_parsed("--depth-origin",
                    [](const Metres &) {
                      return std::string(
                          "X,Y (--model depth): the depth rays leave this point of the robot, m, x forward, y "
                          "left (default none: each from the rim, trace.csv's depths from the centre)");
                    },
                    [](Metres &o, const std::string &text) { o.depth_origin = point_of(text, "--depth-origin"); }),
      metres_plain("--verbose",
                   [](const Metres &) {
                     return std::string(
                         "frontier: after the end line, why it ended: the frontier cells left and the groups set "
                         "aside (as summary.json's frontier)");
                   },
                   [](Metres &o) -> FieldRef { return &o.verbose; }),
  };
  return fields;
}

}  // namespace app
