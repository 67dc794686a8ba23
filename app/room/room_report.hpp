#pragma once
// The room run's report: every fact its summary shows, built once from the run's options and
// its result; the printed summary and summary.json are its two renderers, so a fact's key,
// printed form and typed form are stated here and nowhere else.
//
//   key               printed line                                        summary.json
//   world             world         worlds/ir_room.room                   "world": "worlds/ir_room.room"
//   robot             robot         ir-fan (pie set-up)                   "robot": "ir-fan"
//   model             (in robot's line)                                   "model": "pie"
//   grid              grid          50 x 30 cells of 0.1 m over 0,5,0,3   (its parts: cells_x ... boundary_m)
//   sim_time_s        sim time      35.07 s                               "sim_time_s": 35.07
//   wall_time_ms      wall time     350 ms                                (none: the same run writes the same file)
//
// An entry with a label is a line of the printed summary, an entry with a JSON value a key of
// summary.json, both in the report's order.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/room/room_run.hpp"
#include "sensing/room_map.hpp"
#include "sensing/setups.hpp"

namespace app {

struct RoomReportEntry {
  std::string key;                             // summary.json's key
  std::string label;                           // the printed line's name; "": no line
  std::string text;                            // the printed value, with its unit
  std::optional<nlohmann::ordered_json> json;  // summary.json's value; nothing: not in the file
};

std::vector<RoomReportEntry> room_report(const RoomRunOptions &options, const std::string &robot_name,
                                         const sensing::SetUp &setup, const sensing::RoomGridSpec &spec,
                                         const RoomSummary &summary);

// The printed summary: `label` padded to 14 columns, then the text; a line an entry with a label.
std::string room_summary_text(const std::vector<RoomReportEntry> &report);
// summary.json's text: an object of every entry with a JSON value, in order.
std::string room_summary_json(const std::vector<RoomReportEntry> &report);

}  // namespace app
