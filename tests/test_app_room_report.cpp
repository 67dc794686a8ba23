// The room run's report (app/room/room_report.hpp): one list of entries, rendered to the
// printed summary and to summary.json.

#include <doctest/doctest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "app/room/room_report.hpp"

namespace {

struct Made {
  app::RoomRunOptions options;
  sensing::RoomGridSpec spec;
  app::RoomSummary summary;
};

Made made() {
  Made m;
  m.options.world = "worlds/ir_room.room";
  m.options.room.strategy = robot::RoomStrategy::waypoints;
  m.spec = sensing::room_grid_from_resolution({0.0, 5.0, 0.0, 3.0}, 0.1);
  m.summary.ending = robot::RoomEnding::arrived;
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
  return m;
}

}  // namespace

TEST_CASE("room report: the printed summary, a line an entry with a label, in order") {
  const Made m = made();
  const auto report = app::room_report(m.options, "ir-fan", sensing::setup(sensing::ModelKind::pie), m.spec, m.summary);
  CHECK(app::room_summary_text(report) ==
        "world         worlds/ir_room.room\n"
        "strategy      waypoints\n"
        "robot         ir-fan (pie set-up)\n"
        "grid          50 x 30 cells of 0.1 m over 0,5,0,3\n"
        "steps         1096\n"
        "sim time      35.07 s\n"
        "ending        arrived: reached all 8 waypoints\n"
        "cells right   1337 of 1500 (89.1 %); observed 1295 of 1440\n"
        "observed      98.56 % of the reachable free area (1229 of 1247 cells)\n"
        "wall time     350 ms\n");
}

TEST_CASE("room report: summary.json has every typed entry in order and no wall time") {
  const Made m = made();
  const auto report = app::room_report(m.options, "ir-fan", sensing::setup(sensing::ModelKind::pie), m.spec, m.summary);
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(app::room_summary_json(report));
  std::string keys;
  for (const auto &item : j.items()) keys += item.key() + " ";
  CHECK(keys ==
        "world strategy robot model cells_x cells_y cell_m boundary_m steps sim_time_s ending message cells_right "
        "cells_total observed_cells observed_cells_right reachable_free reachable_free_observed ");
  CHECK(j["robot"] == "ir-fan");
  CHECK(j["model"] == "pie");
  CHECK(j["cells_x"] == 50);
  CHECK(j["boundary_m"] == nlohmann::ordered_json::array({0.0, 5.0, 0.0, 3.0}));
  CHECK(j["sim_time_s"] == 35.072);
  CHECK(j["ending"] == "arrived");
  CHECK(j["reachable_free_observed"] == 1229);
  CHECK_FALSE(j.contains("wall_time_ms"));
  CHECK_FALSE(j.contains("grid"));
}
