// The room run's report (app/room/room_report.hpp).

#include "app/room/room_report.hpp"

#include <utility>

#include <fmt/format.h>

namespace app {
namespace {

using Json = nlohmann::ordered_json;

// Appends entries in order.
class Entries {
 public:
  explicit Entries(std::vector<RoomReportEntry> &entries) : entries_(entries) {}
  // Printed as `label  text`, in summary.json as `json`.
  void both(std::string key, std::string label, std::string text, Json json) {
    entries_.push_back({std::move(key), std::move(label), std::move(text), std::move(json)});
  }
  void json_only(std::string key, Json json) { entries_.push_back({std::move(key), "", "", std::move(json)}); }
  void text_only(std::string key, std::string label, std::string text) {
    entries_.push_back({std::move(key), std::move(label), std::move(text), std::nullopt});
  }

 private:
  std::vector<RoomReportEntry> &entries_;
};

double percent(std::size_t part, std::size_t whole) {
  return whole == 0 ? 100.0 : 100.0 * static_cast<double>(part) / static_cast<double>(whole);
}

void add_grid(Entries &e, const sensing::RoomGridSpec &spec) {
  const sensing::RoomBoundary &b = spec.boundary;
  e.text_only("grid", "grid",
              fmt::format("{} x {} cells of {:g} m over {:g},{:g},{:g},{:g}", spec.cells_x, spec.cells_y, spec.cell_m,
                          b.x_start_m, b.x_end_m, b.y_start_m, b.y_end_m));
  e.json_only("cells_x", spec.cells_x);
  e.json_only("cells_y", spec.cells_y);
  e.json_only("cell_m", spec.cell_m);
  e.json_only("boundary_m", Json::array({b.x_start_m, b.x_end_m, b.y_start_m, b.y_end_m}));
}

void add_score(Entries &e, const RoomSummary &s) {
  e.both("cells_right", "cells right",
         fmt::format("{} of {} ({:.1f} %); observed {} of {}", s.cells_right, s.cells_total,
                     percent(s.cells_right, s.cells_total), s.observed_cells_right, s.observed_cells),
         s.cells_right);
  e.json_only("cells_total", s.cells_total);
  e.json_only("observed_cells", s.observed_cells);
  e.json_only("observed_cells_right", s.observed_cells_right);
  e.both("reachable_free", "observed",
         fmt::format("{:.2f} % of the reachable free area ({} of {} cells)", 100.0 * s.observed_share(),
                     s.reachable_free_observed, s.reachable_free),
         s.reachable_free);
  e.json_only("reachable_free_observed", s.reachable_free_observed);
  if (s.sweep) {
    e.both("sweep_legs", "body sweep",
           fmt::format("{} legs onto unobserved ground ({} probes past cells the echoes closed); {} cells first "
                       "observed by the body",
                       s.sweep->legs, s.sweep->probes, s.sweep->body_observed),
           s.sweep->legs);
    e.json_only("sweep_probes", s.sweep->probes);
    e.json_only("body_observed", s.sweep->body_observed);
  }
}

}  // namespace

std::vector<RoomReportEntry> room_report(const RoomRunOptions &options, const std::string &robot_name,
                                         const sensing::SetUp &setup, const sensing::RoomGridSpec &spec,
                                         const RoomSummary &summary) {
  std::vector<RoomReportEntry> entries;
  Entries e(entries);
  e.both("world", "world", options.world, options.world);
  const std::string strategy(robot::to_string(options.room.strategy));
  e.both("strategy", "strategy", strategy, strategy);
  std::string depth;
  if (options.depth_reading == sensing::DepthReading::axial || options.depth_origin) {
    const mapping::Point o = options.depth_origin.value_or(mapping::Point{});
    depth = fmt::format("; depth {} from {:g},{:g} m", options.depth_reading == sensing::DepthReading::axial ? "axial" : "range",
                        o.x_m, o.y_m);
  }
  e.both("robot", "robot", fmt::format("{} ({} set-up{})", robot_name, setup.name, depth), robot_name);
  e.json_only("model", std::string(setup.name));
  add_grid(e, spec);
  e.both("steps", "steps", fmt::format("{}", summary.steps), summary.steps);
  e.both("sim_time_s", "sim time", fmt::format("{:.2f} s", summary.sim_time_s), summary.sim_time_s);
  const std::string ending(robot::to_string(summary.ending));
  e.both("ending", "ending", fmt::format("{}: {}", ending, summary.message), ending);
  e.json_only("message", summary.message);
  add_score(e, summary);
  e.text_only("wall_time_ms", "wall time", fmt::format("{:.0f} ms", summary.wall_time_ms));
  return entries;
}

std::string room_summary_text(const std::vector<RoomReportEntry> &report) {
  std::string out;
  for (const RoomReportEntry &entry : report) {
    if (!entry.label.empty()) out += fmt::format("{:<13} {}\n", entry.label, entry.text);
  }
  return out;
}

std::string room_summary_json(const std::vector<RoomReportEntry> &report) {
  Json j = Json::object();
  for (const RoomReportEntry &entry : report) {
    if (entry.json) j[entry.key] = *entry.json;
  }
  return j.dump(2) + "\n";
}

}  // namespace app
