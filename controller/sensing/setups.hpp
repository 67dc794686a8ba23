#pragma once
// The set-ups: a row per `--model`, the one place that says what a set-up is. Everything
// that differs between set-ups is read from its row - the devices it needs, the robot it runs
// on by default, the run options its model reads, the numbers it marks with, what the robot
// does on arriving in a cell, and the model's mark functions on a maze's sub-cells and on a
// room's metric map - so nothing else switches on the model. Adding a set-up: a ModelKind, a
// row in setups.cpp, its model file, its tests.
//
//   name   reads          default robot  own numbers (p free / p occupied)   on arrival        in metres
//   cell   lidar          hambot         --p-free / --p-occ                  resolve, confirm  the rays
//   ray    lidar          hambot         --p-free / --p-occ                  resolve, confirm  the rays
//   bump   bumpers        bumper-depth   0.3 / 0.99999 (course)              probe             the pose log
//   depth  range sensors  bumper-depth   0.4 ray, 0.3 robot / 0.99999 (c.)   look around       the pose log
//   pie    range sensors  ir-ring        0.4 / 0.7 (course)                  resolve, confirm  pie slices
//   cone   range sensors  ir-ring        --p-free / --p-occ                  resolve, confirm  cone arcs

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "sensing/range_models.hpp"
#include "sensing/scan.hpp"

namespace sensing {

enum class ModelKind { cell, ray, bump, depth, pie, cone };

// The options of the lidar models (the range models' are RangeModelOptions).
struct ModelOptions {
  ModelKind kind = ModelKind::cell;
  // cell: a side is a wall when its beam returns closer than the distance from the sensor
  // to that side plus wall_margin * cell size (0.5 + 0.25 cells from a centred robot).
  double wall_margin = 0.25;
  // ray: sub-cells behind the hit sub-cell also marked occupied (--hit-depth), 0 ... 8.
  int hit_depth = 0;
  // ray: beams with no return update nothing instead of freeing up to max range.
  bool ignore_no_return = false;
};

// Throws common::InputError when an option is out of range (wall_margin in [0, 0.5),
// hit_depth 0 ... 8).
void validate(const ModelOptions &options);

// A lidar set-up's model: gathers one scan's marks into `update` (nothing applied).
using LidarMark = void (*)(const ModelOptions &options, const mapping::OccupancyGrid &grid, const LidarScan &scan,
                           mapping::Cell robot_cell, mapping::ScanUpdate &update);
// A range-sensor set-up's model: one reading of every range sensor, the robot at `robot`.
using RangeMark = void (*)(const mapping::OccupancyGrid &grid, const RangeModelOptions &options, mapping::Point robot,
                           std::span<const RangeReading> readings, LeveledUpdate &update);
// A bumper set-up's model: one reading of every bumper.
using BumpMark = void (*)(const mapping::OccupancyGrid &grid, mapping::Point robot,
                          std::span<const BumpReading> bumpers, LeveledUpdate &update);

// What the robot does in a cell after its first scan there (robot/arrival.hpp).
enum class Arrival {
  resolve_and_confirm,  // rescan and face the sides still unknown; rescan an open side the last scan calls a wall
                        // (the lidar's cell-model reading, or the range sensor facing it)
  resolve,              // rescan and face the sides still unknown
  probe,                // feel each side still unknown with the bumpers
  look_around,          // in a new cell, face each side once and scan
};

// The kinds of range sensor (Webots' DistanceSensor types) a range set-up's model is made
// for, a bit set. On other kinds it maps wrongly: the pie slices are an IR sensor's narrow
// beam, the cone sweep needs a cone, the depth rays are single rays (docs/models.md).
enum RangeSensorKind : unsigned {
  kGenericSensor = 1u << 0,   // "generic": the depth rays
  kInfraRedSensor = 1u << 1,  // "infra-red"
  kSonarSensor = 1u << 2,     // "sonar"
};
// "generic", "infra-red" or "sonar", Webots' spelling.
std::string_view to_string(RangeSensorKind kind);

// The run options a set-up's model may read besides those every set-up reads (K, --prior,
// --log-base, --clamp, --threshold). A bit set.
enum ModelOption : unsigned {
  kProbabilities = 1u << 0,   // --p-free, --p-occ
  kHitDepth = 1u << 1,        // --hit-depth
  kIgnoreNoReturn = 1u << 2,  // --ignore-no-return
  kPieBeta = 1u << 3,         // --pie-beta
  kPieAlpha = 1u << 4,        // --pie-alpha
};
inline constexpr ModelOption kModelOptions[] = {kProbabilities, kHitDepth, kIgnoreNoReturn, kPieBeta, kPieAlpha};
// "--p-free/--p-occ", "--hit-depth", ...
std::string_view option_name(ModelOption option);

// The probabilities a set-up marks with: a free and an occupied one, and where it has
// them, a third (depth: the robot's own sub-cell).
struct MarkProbabilities {
  double p_free = 0.0;
  double p_occ = 0.0;
  std::optional<double> p_robot;
};

class MetricMap;
class MetricMarks;
using MetricRangeMark = void (*)(const MetricMap &map, const RangeModelOptions &options,
                                 std::span<const RangeReading> readings, MetricMarks &marks);

struct SetUp {
  ModelKind kind;
  std::string_view name;          // --model NAME
  std::string_view description;   // for --help and `maze_mapper explain`
  std::string_view default_robot; // a built-in robot profile that has the devices
  unsigned options;               // ModelOption bits
  // The course's fixed numbers, or nothing: the sensor model's --p-free / --p-occ.
  std::optional<MarkProbabilities> fixed;
  Arrival arrival;
  // The model, and with it the devices: a lidar, range sensors or bumpers.
  std::variant<LidarMark, RangeMark, BumpMark> mark;
  // The range and bump models' marks and their levels; nothing for the lidar models.
  LeveledUpdate (*make_update)(const mapping::SensorModelOptions &sensor) = nullptr;
  // The range set-ups: the RangeSensorKind bits their model is made for; 0 for the others.
  unsigned range_sensor_kinds = 0;
  // In metres (a room's metric map): how one scan of the range sensors marks it (pie's slices,
  // the cone's arcs); nothing for the lidar (its rays are traced, mark_metric_lidar) and for
  // bump and depth, whose poses and readings mark it as the course's pose log does
  // (sensing/bump_depth_marks.hpp).
  MetricRangeMark metres_range_mark = nullptr;

  bool uses(ModelOption option) const { return (options & option) != 0; }
  bool reads_lidar() const { return std::holds_alternative<LidarMark>(mark); }
  bool reads_ranges() const { return std::holds_alternative<RangeMark>(mark); }
  bool reads_bumpers() const { return std::holds_alternative<BumpMark>(mark); }
  // "lidar", "range sensors", "bumpers": what a robot "has no" or a set-up "needs a robot with"
  std::string_view devices() const;
  // The kinds in range_sensor_kinds: "infra-red", "infra-red or sonar".
  std::string range_sensor_kind_names() const;
};

// Every set-up, in the order --help lists them.
std::span<const SetUp> setups();
const SetUp &setup(ModelKind kind);
// The set-up named NAME; throws common::InputError naming --model and the choices otherwise.
const SetUp &setup_named(std::string_view name);
// "cell, ray, bump, depth, pie or cone"
std::string setup_names();

std::string_view to_string(ModelKind kind);
// setup_named(name).kind
ModelKind parse_model(std::string_view name);
inline bool uses_lidar(ModelKind kind) { return setup(kind).reads_lidar(); }

// The probabilities a run marks with: the set-up's own, or the sensor model's.
MarkProbabilities probabilities_in_effect(const SetUp &setup, const mapping::SensorModelOptions &sensor);

// A lidar set-up's scan: gathers its marks into `update` (nothing applied). robot_cell is
// the cell the robot stands in (inside the grid).
void mark_scan(const ModelOptions &options, const mapping::OccupancyGrid &grid, const LidarScan &scan,
               mapping::Cell robot_cell, mapping::ScanUpdate &update);
// mark_scan, then update.apply(grid, model). Returns how many sub-cells were updated.
std::size_t integrate_scan(const ModelOptions &options, mapping::OccupancyGrid &grid, const LidarScan &scan,
                           mapping::Cell robot_cell, const mapping::SensorModel &model, mapping::ScanUpdate &update);

}  // namespace sensing
