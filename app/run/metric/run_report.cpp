// The room run's report (app/run/metric/run_report.hpp).

#include "app/run/metric/run_report.hpp"
#include "app/run/report_keys.hpp"

#include <cmath>

#include <fmt/format.h>

namespace app {
namespace {

using Json = nlohmann::ordered_json;

double share_percent(std::size_t part, std::size_t whole) {
  return whole == 0 ? 100.0 : 100.0 * static_cast<double>(part) / static_cast<double>(whole);
}
double two_decimals(double percent) { return std::round(percent * 100.0) / 100.0; }

void add_grid(Report &e, const sensing::MetricGridSpec &spec) {
  const sensing::MetricBoundary &b = spec.boundary;
  e.both("grid",
         fmt::format("{} x {} cells of {:g} m over {:g},{:g},{:g},{:g}", spec.cells_x, spec.cells_y, spec.cell_m,
                     b.x_start_m, b.x_end_m, b.y_start_m, b.y_end_m),
         nullptr);
  e.json_only("cells_x", spec.cells_x);
  e.json_only("cells_y", spec.cells_y);
  e.json_only("cell_m", spec.cell_m);
  e.json_only("boundary_m", Json::array({b.x_start_m, b.x_end_m, b.y_start_m, b.y_end_m}));
}

void add_model(Report &e, const RunOptions &options, const sensing::SetUp &setup) {
  e.both("model", std::string(setup.name));
  if (options.metres.depth_reading == sensing::DepthReading::axial || options.metres.depth_origin) {
    const mapping::Point o = options.metres.depth_origin.value_or(mapping::Point{});
    const char *reading = options.metres.depth_reading == sensing::DepthReading::axial ? "axial" : "range";
    e.both("depth", fmt::format("{} from {:g},{:g} m", reading, o.x_m, o.y_m),
           Json{{"reading", reading}, {"origin_m", Json::array({o.x_m, o.y_m})}});
  } else {
    e.json_only("depth", nullptr);
  }
}

void add_score(Report &e, const MetricRunSummary &s) {
  const double right = share_percent(s.cells_right, s.cells_total);
  e.both(std::string(report_key::cell_accuracy),
         fmt::format("{:.2f}% ({} of {} cells right; observed {} of {})", right, s.cells_right, s.cells_total,
                     s.observed_cells_right, s.observed_cells),
         two_decimals(right));
  e.json_only("cells_right", s.cells_right);
  e.json_only("cells_total", s.cells_total);
  e.json_only("observed_cells", s.observed_cells);
  e.json_only("observed_cells_right", s.observed_cells_right);
  const double covered = 100.0 * s.observed_share();
  e.both(std::string(report_key::coverage),
         fmt::format("{:.2f}% ({} of {} reachable free cells observed)", covered, s.reachable_free_observed,
                     s.reachable_free),
         two_decimals(covered));
  e.json_only("reachable_free", s.reachable_free);
  e.json_only("reachable_free_observed", s.reachable_free_observed);
  e.both(std::string(report_key::coverage_final_step), std::to_string(s.coverage_final_step),
         Json(s.coverage_final_step));
  e.both(std::string(report_key::path_length_m), fmt::format("{:.2f}", s.path_length_m),
         Json(std::round(s.path_length_m * 1000.0) / 1000.0));
  if (s.sweep) {
    e.both("sweep_legs",
           fmt::format("{} legs onto unobserved ground ({} probes past cells the echoes closed); {} cells first "
                       "observed by the body",
                       s.sweep->legs, s.sweep->probes, s.sweep->body_observed),
           s.sweep->legs);
    e.json_only("sweep_probes", s.sweep->probes);
    e.json_only("body_observed", s.sweep->body_observed);
  }
}

// The frontier left and set aside at the end: summary.json's, and with --verbose a line after
// the end line.
void add_frontier(Report &e, const MetricRunSummary &s, bool verbose) {
  if (!s.frontier) return;
  const explore::FrontierSetAside &a = s.frontier->set_aside;
  Json json{{"detail", s.frontier->detail},
            {"left_cells", s.frontier->left_cells},
            {"small_groups", a.small_groups},
            {"small_cells", a.small_cells},
            {"enclosed_groups", a.enclosed_groups},
            {"enclosed_cells", a.enclosed_cells},
            {"no_room_groups", a.no_room_groups},
            {"no_room_cells", a.no_room_cells}};
  if (!verbose) {
    e.json_only("frontier", std::move(json));
    return;
  }
  const std::string detail = s.frontier->detail.empty() ? "no frontier left" : s.frontier->detail;
  e.both("frontier",
         fmt::format("{}; set aside: {} small groups ({} cells), {} enclosed ({} cells), {} without room for the "
                     "body ({} cells)",
                     detail, a.small_groups, a.small_cells, a.enclosed_groups, a.enclosed_cells, a.no_room_groups,
                     a.no_room_cells),
         std::move(json));
}

}  // namespace

Report metric_run_report(const RunOptions &options, const std::string &robot_name, const sensing::SetUp &setup,
                   const sensing::MetricGridSpec &spec, const MetricRunSummary &summary) {
  Report e;
  e.both("world", options.world);
  add_grid(e, spec);
  add_model(e, options, setup);
  e.both("strategy", std::string(explore::to_string(options.strategy)));
  e.both("robot", robot_name);
  e.both("seed", std::to_string(options.simulation.seed), Json(options.simulation.seed));
  const std::string ending(robot::to_string(summary.ending));
  e.both("end", end_text(ending, summary.message), Json(ending));
  e.json_only("end_message", summary.message);
  add_frontier(e, summary, options.metres.verbose);
  e.both("steps", std::to_string(summary.steps), Json(summary.steps));
  add_score(e, summary);
  e.both("sim_time_s", fmt::format("{:.3f}", summary.sim_time_s), Json(summary.sim_time_s));
  e.both("wall_time_ms", fmt::format("{:.0f}", summary.wall_time_ms), Json(summary.wall_time_ms));
  return e;
}

}  // namespace app
