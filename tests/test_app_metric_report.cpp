// The room run's report (app/run/metric/run_report.hpp): one list of entries, rendered to the
// printed summary and to summary.json.

#include <doctest/doctest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "app/run/metric/run_report.hpp"
#include "app/run/report.hpp"

namespace {

struct Made {
  app::RunOptions options = app::metres_run_options();
  sensing::MetricGridSpec spec;
  app::MetricRunSummary summary;
};

Made made() {
  Made m;
  m.options.world = "worlds/ir_room.room";
  m.options.strategy = explore::StrategyKind::waypoints;
  m.spec = sensing::metric_grid_from_resolution({0.0, 5.0, 0.0, 3.0}, 0.1);
  m.summary.ending = robot::MetricEnding::arrived;
  m.summary.message = "reached all 8 waypoints";
  m.summary.steps = 1096;
  m.summary.sim_time_s = 35.072;
  m.summary.wall_time_ms = 349.6;
  m.summary.cells_right = 1337;
  m.summary.cells_total = 1500;
  m.summary.observed_cells_right = 1295;
  m.summary.observed_cells = 1440;
  m.summary.reachable_free = 1247;
  m.summary.reachable_free_observed = 1229;
  m.summary.coverage_final_step = 1040;
  m.summary.path_length_m = 12.3456;
  return m;
}

}  // namespace

TEST_CASE("room report: the summary block is the run's key: value lines, end: included, in order") {
  const Made m = made();
  const app::Report report =
      app::metric_run_report(m.options, "ir-fan", sensing::setup(sensing::ModelKind::pie), m.spec, m.summary);
  CHECK(app::format_summary(report) ==
        "world: worlds/ir_room.room\n"
        "grid: 50 x 30 cells of 0.1 m over 0,5,0,3\n"
        "model: pie\n"
        "strategy: waypoints\n"
        "robot: ir-fan\n"
        "seed: 42\n"
        "end: arrived (reached all 8 waypoints)\n"
        "steps: 1096\n"
        "cell_accuracy: 89.13% (1337 of 1500 cells right; observed 1295 of 1440)\n"
        "coverage: 98.56% (1229 of 1247 reachable free cells observed)\n"
        "coverage_final_step: 1040\n"
        "path_length_m: 12.35\n"
        "sim_time_s: 35.072\n"
        "wall_time_ms: 350\n");
}

TEST_CASE("room report: summary.json has every entry in order, with the core keys of every kind of run") {
  const Made m = made();
  const app::Report report =
      app::metric_run_report(m.options, "ir-fan", sensing::setup(sensing::ModelKind::pie), m.spec, m.summary);
  const nlohmann::ordered_json j = app::report_json(report);
  std::string keys;
  for (const auto &item : j.items()) keys += item.key() + " ";
  CHECK(keys ==
        "world grid cells_x cells_y cell_m boundary_m model depth strategy robot seed end end_message steps "
        "cell_accuracy cells_right cells_total observed_cells observed_cells_right coverage reachable_free "
        "reachable_free_observed coverage_final_step path_length_m sim_time_s wall_time_ms ");
  CHECK(j["coverage_final_step"] == 1040);
  CHECK(j["path_length_m"] == 12.346);
  CHECK(j["robot"] == "ir-fan");
  CHECK(j["model"] == "pie");
  CHECK(j["cells_x"] == 50);
  CHECK(j["boundary_m"] == nlohmann::ordered_json::array({0.0, 5.0, 0.0, 3.0}));
  CHECK(j["sim_time_s"] == 35.072);
  CHECK(j["end"] == "arrived");
  CHECK(j["end_message"] == "reached all 8 waypoints");
  CHECK(j["coverage"] == 98.56);
  CHECK(j["cell_accuracy"] == 89.13);
  CHECK(j["reachable_free_observed"] == 1229);
  CHECK(j["grid"].is_null());
  CHECK(j["depth"].is_null());
}
