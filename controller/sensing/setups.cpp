#include "sensing/setups.hpp"

#include "sensing/metric/map.hpp"

#include <array>
#include <cassert>
#include <string>

#include <fmt/format.h>

#include "common/error.hpp"
#include "sensing/cell_model.hpp"
#include "sensing/ray_model.hpp"

namespace sensing {
namespace {

constexpr int kMaxHitDepth = 8;

// The range models, each behind the one RangeMark signature.
void depth_mark(const mapping::OccupancyGrid &grid, const RangeModelOptions &, mapping::Point robot,
                std::span<const RangeReading> readings, LeveledUpdate &update) {
  mark_depth(grid, robot, readings, update);
}
void pie_mark(const mapping::OccupancyGrid &grid, const RangeModelOptions &options, mapping::Point,
              std::span<const RangeReading> readings, LeveledUpdate &update) {
  mark_pie(grid, options, readings, update);
}
void cone_mark(const mapping::OccupancyGrid &grid, const RangeModelOptions &, mapping::Point,
               std::span<const RangeReading> readings, LeveledUpdate &update) {
  mark_cone(grid, readings, update);
}

// The course's fixed numbers (sensing/range_models.hpp has their sources).
LeveledUpdate bump_update(const mapping::SensorModelOptions &) { return make_bump_update(); }
LeveledUpdate depth_update(const mapping::SensorModelOptions &) { return make_depth_update(); }
LeveledUpdate pie_update(const mapping::SensorModelOptions &) { return make_pie_update(); }

// The table: one row per set-up (the header draws it).
const std::array<SetUp, 6> kSetUps{{
    {ModelKind::cell, "cell", "the classroom sub-cell model (lidar)", "hambot", kProbabilities, std::nullopt,
     Arrival::resolve_and_confirm, LidarMark{&mark_cell_model}},
    {ModelKind::ray, "ray", "every lidar beam traced through the sub-cells it crosses", "hambot",
     kProbabilities | kHitDepth | kIgnoreNoReturn, std::nullopt, Arrival::resolve_and_confirm,
     LidarMark{&mark_ray_model}},
    {ModelKind::bump, "bump", "bumpers felt against each unknown side", "bumper-depth", 0,
     MarkProbabilities{kBumpFreeP, kBumpOccupiedP, std::nullopt}, Arrival::probe, BumpMark{&mark_bumps},
     &bump_update},
    {ModelKind::depth, "depth", "depth rays over the front 120 degrees", "bumper-depth", 0,
     MarkProbabilities{kDepthRayP, kDepthHitP, kDepthRobotP}, Arrival::look_around, RangeMark{&depth_mark},
     &depth_update, kGenericSensor},
    {ModelKind::pie, "pie", "the IR pie-slice update", "ir-ring", kPieBeta | kPieAlpha,
     MarkProbabilities{kPieFreeP, kPieOccupiedP, std::nullopt}, Arrival::resolve_and_confirm, RangeMark{&pie_mark},
     &pie_update, kInfraRedSensor, &mark_metric_pie},
    {ModelKind::cone, "cone", "the sonar/IR cone sweep", "ir-ring", kProbabilities, std::nullopt,
     Arrival::resolve_and_confirm, RangeMark{&cone_mark}, &make_cone_update,
     kInfraRedSensor | kSonarSensor, &mark_metric_cone},
}};

}  // namespace

std::string_view SetUp::devices() const {
  if (reads_lidar()) return "lidar";
  return reads_bumpers() ? "bumpers" : "range sensors";
}

std::string_view to_string(RangeSensorKind kind) {
  switch (kind) {
    case kGenericSensor: return "generic";
    case kInfraRedSensor: return "infra-red";
    case kSonarSensor: return "sonar";
  }
  return "?";
}

std::string SetUp::range_sensor_kind_names() const {
  std::string names;
  for (const RangeSensorKind sensor : {kGenericSensor, kInfraRedSensor, kSonarSensor}) {
    if ((range_sensor_kinds & sensor) == 0) continue;
    names += (names.empty() ? "" : " or ") + std::string(to_string(sensor));
  }
  return names;
}

std::string_view option_name(ModelOption option) {
  switch (option) {
    case kProbabilities: return "--p-free/--p-occ";
    case kHitDepth: return "--hit-depth";
    case kIgnoreNoReturn: return "--ignore-no-return";
    case kPieBeta: return "--pie-beta";
    case kPieAlpha: return "--pie-alpha";
  }
  return "?";
}

std::span<const SetUp> setups() { return kSetUps; }

const SetUp &setup(ModelKind kind) {
  for (const SetUp &s : kSetUps) {
    if (s.kind == kind) return s;
  }
  assert(false && "every ModelKind has a row");
  return kSetUps.front();
}

std::string setup_names() {
  std::string names;
  for (std::size_t i = 0; i < kSetUps.size(); ++i) {
    if (i > 0) names += i + 1 == kSetUps.size() ? " or " : ", ";
    names += kSetUps[i].name;
  }
  return names;
}

const SetUp &setup_named(std::string_view name) {
  for (const SetUp &s : kSetUps) {
    if (s.name == name) return s;
  }
  throw common::InputError(fmt::format("unknown --model '{}' (choose {})", name, setup_names()));
}

std::string_view to_string(ModelKind kind) { return setup(kind).name; }

ModelKind parse_model(std::string_view name) { return setup_named(name).kind; }

MarkProbabilities probabilities_in_effect(const SetUp &s, const mapping::SensorModelOptions &sensor) {
  return s.fixed.value_or(MarkProbabilities{sensor.p_free, sensor.p_occ, std::nullopt});
}

void validate(const ModelOptions &options) {
  if (!(options.wall_margin >= 0.0 && options.wall_margin < 0.5)) {
    throw common::InputError(fmt::format(
        "wall margin must be at least 0 and less than 0.5 cells (got {})", options.wall_margin));
  }
  if (options.hit_depth < 0 || options.hit_depth > kMaxHitDepth) {
    throw common::InputError(fmt::format("--hit-depth must be between 0 and {} (got {})",
                                         kMaxHitDepth, options.hit_depth));
  }
}

void mark_scan(const ModelOptions &options, const mapping::OccupancyGrid &grid, const LidarScan &scan,
               mapping::Cell robot_cell, mapping::ScanUpdate &update) {
  const SetUp &s = setup(options.kind);
  assert(s.reads_lidar());
  std::get<LidarMark>(s.mark)(options, grid, scan, robot_cell, update);
}

std::size_t integrate_scan(const ModelOptions &options, mapping::OccupancyGrid &grid, const LidarScan &scan,
                           mapping::Cell robot_cell, const mapping::SensorModel &model,
                           mapping::ScanUpdate &update) {
  mark_scan(options, grid, scan, robot_cell, update);
  return update.apply(grid, model);
}

}  // namespace sensing
