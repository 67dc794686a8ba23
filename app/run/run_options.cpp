#include "app/run/run_options.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "app/run/model_rules.hpp"
#include "app/run/profile_json.hpp"
#include "common/error.hpp"
#include "mapping/occupancy_grid.hpp"

namespace app {
namespace {

void require_above_zero(const char *option, double value) {
  if (!(value > 0.0 && value <= 1e6)) {
    throw common::InputError(fmt::format("{} must be a number above 0 (got {})", option, value));
  }
}

constexpr int kMaxSnapshots = 100;

void validate(const OutputOptions &o) {
  if (o.unknown) validate_unknown(std::string_view(&*o.unknown, 1));
  require_above_zero("--fps", o.fps);
  require_above_zero("--speed", o.speed);
  if (o.snapshots != 0) validate_snapshots(o.snapshots);  // 0: none
}

void validate_run(const RunOptions &o) {
  validate_subcells(o.subcells);
  if (o.threshold && !std::isfinite(*o.threshold)) {
    throw common::InputError(fmt::format("--threshold must be a finite log-odds value (got {})", *o.threshold));
  }
  // Log-odds never leave the clamp: a threshold outside it marks no wall, or every sub-cell.
  if (o.threshold && o.sensor.clamp && (*o.threshold > o.sensor.clamp->max || *o.threshold < o.sensor.clamp->min)) {
    throw common::InputError(fmt::format("--threshold {} lies outside --clamp {} {}: the log-odds never pass it, so "
                                         "the map {}", *o.threshold, o.sensor.clamp->min, o.sensor.clamp->max,
                                         *o.threshold > o.sensor.clamp->max ? "would hold no wall"
                                                                             : "would be walls everywhere"));
  }
  const std::optional<double> &noise = o.simulation.noise;
  if (noise && !(*noise >= 0.0 && *noise <= 1.0)) {
    throw common::InputError(fmt::format("--noise must be a fraction of the max range from 0 to 1 (got {})", *noise));
  }
  if (o.time_limit_s && !(*o.time_limit_s > 0.0)) {
    throw common::InputError(fmt::format("--time-limit must be more than 0 simulated seconds (got {:g})", *o.time_limit_s));
  }
  if (o.max_steps && *o.max_steps < 1) {
    throw common::InputError(fmt::format("--max-steps must be at least 1 (got {})", *o.max_steps));
  }
}

bool animating(const RunOptions &o) { return o.output.animate; }
bool not_animating(const RunOptions &o) { return !o.output.animate; }
bool planning(const RunOptions &o) { return o.plan.to.has_value() || o.plan.only; }
bool writing_files(const RunOptions &o) { return !o.output.out_dir.empty(); }
bool localizing(const RunOptions &o) { return o.localize.on; }

// The run's own rules; the model's are the set-up table's (model_given_options below).
constexpr OptionUse<RunOptions> kOptionUses[] = {
    {"--fps", "without --animate", animating},
    {"--speed", "without --animate", animating},
    {"--quiet", "with --animate", not_animating},
    {"--dilate", "without --plan-to", planning},
    {"--snapshots", "without --out", writing_files},
    {"--no-trace", "without --out", writing_files},
    {"--trace-steps", "without --out", writing_files},
    {"--no-replay", "without --out", writing_files},
    {"--picture-format", "without --out", writing_files},
    {"--sensor", "without --localize", localizing},
    {"--motion", "without --localize", localizing},
    {"--localized", "without --localize", localizing},
};

// The sensing::ModelOption bits of the options given: option_name() is "--p-free/--p-occ"
// for the pair, one name for the others.
unsigned model_given_options(const GivenOptions &given) {
  unsigned bits = 0;
  for (const sensing::ModelOption option : sensing::kModelOptions) {
    const std::string_view names = sensing::option_name(option);
    const std::size_t slash = names.find('/');
    const bool first = given.given(names.substr(0, slash));
    const bool second = slash != std::string_view::npos && given.given(names.substr(slash + 1));
    if (first || second) bits |= option;
  }
  return bits;
}

// The faults and the noise act on the lidar's beams: on a robot without one, --dropout and
// --spikes do nothing, nor does a --noise other than 0 (which also makes the other sensors exact).
void check_lidar_options(const GivenOptions &given, const RunOptions &options, std::vector<std::string> &warnings) {
  const bool lidar_option = given.given("--dropout") || given.given("--spikes") ||
                            (given.given("--noise") && options.simulation.noise.value_or(0.0) > 0.0);
  if (!lidar_option) return;
  const maze::sim::RobotProfile &profile = robot_profile(options);
  if (!profile.lidars.empty()) return;
  for (const char *option : {"--dropout", "--spikes"}) {
    if (!given.given(option)) continue;
    warnings.push_back(fmt::format("warning: {} has no effect: the robot {} has no lidar", option, profile.name));
  }
  if (given.given("--noise") && options.simulation.noise.value_or(0.0) > 0.0) {
    warnings.push_back(fmt::format("warning: --noise {} has no effect: the robot {} has no lidar (--noise 0 "
                                   "makes its sensors exact)", *options.simulation.noise, profile.name));
  }
}

bool has_bumper(const RunOptions &options) {
  const maze::sim::RobotProfile &profile = robot_profile(options);
  return std::any_of(profile.bumpers.begin(), profile.bumpers.end(),
                     [&](const maze::sim::BumperSpec &b) { return b.name == options.simulation.stuck_bumper; });
}

sensing::RangeSensorKind range_sensor_kind(maze::sim::DistanceSensorType type) {
  switch (type) {
    case maze::sim::DistanceSensorType::generic: return sensing::kGenericSensor;
    case maze::sim::DistanceSensorType::infra_red: return sensing::kInfraRedSensor;
    case maze::sim::DistanceSensorType::sonar: return sensing::kSonarSensor;
  }
  return sensing::kGenericSensor;
}

// A range model on range sensors it is not made for maps wrongly on every shipped world
// (docs/models.md): a warning, not an error, since a profile of one's own may still be
// worth the try, and the run's verdict says how it went.
void check_range_sensor_kinds(const RunOptions &options, std::vector<std::string> &warnings) {
  const sensing::SetUp &setup = sensing::setup(options.model.kind);
  if (!setup.reads_ranges()) return;
  const maze::sim::RobotProfile &profile = robot_profile(options);
  std::string others;
  unsigned seen = 0;
  for (const maze::sim::DistanceSensorSpec &sensor : profile.distance_sensors) {
    const sensing::RangeSensorKind kind = range_sensor_kind(sensor.type);
    if ((setup.range_sensor_kinds & kind) != 0 || (seen & kind) != 0) continue;
    seen |= kind;
    others += (others.empty() ? "" : " and ") + std::string(sensing::to_string(kind));
  }
  if (others.empty()) return;
  warnings.push_back(fmt::format("warning: the {} model is made for {} range sensors, and the robot {} has {} "
                                 "ones: expect a wrong map",
                                 setup.name, setup.range_sensor_kind_names(), profile.name, others));
}

}  // namespace

void validate_subcells(int subcells) {
  // In the grid's own words; the grid's size is checked with the world's.
  mapping::GridGeometry one_cell;
  one_cell.width_cells = 1;
  one_cell.height_cells = 1;
  one_cell.subcells = subcells;
  mapping::validate(one_cell, mapping::kDefaultMaxGridBytes);
}

void validate_snapshots(long long snapshots) {
  if (snapshots < 1 || snapshots > kMaxSnapshots) {
    throw common::InputError(fmt::format("--snapshots must be from 1 to {} (got {})", kMaxSnapshots, snapshots));
  }
}

std::vector<PictureFormat> parse_picture_formats(const std::string &text) {
  std::vector<PictureFormat> formats;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    const std::string name = text.substr(begin, comma - begin);
    const std::optional<PictureFormat> format = picture_format_named(name);
    if (!format) throw common::InputError(fmt::format("--picture-format takes png, svg and pdf (got '{}')", name));
    if (std::find(formats.begin(), formats.end(), *format) != formats.end()) {
      throw common::InputError(fmt::format("--picture-format names {} twice", name));
    }
    formats.push_back(*format);
    begin = comma + 1;
  }
  return formats;
}

void validate_unknown(std::string_view text) {
  const bool printable = text.size() == 1 && static_cast<unsigned char>(text[0]) >= 0x20 &&
                         static_cast<unsigned char>(text[0]) <= 0x7e && text[0] != 'W';
  if (!printable) {
    throw common::InputError(
        fmt::format("--unknown must be one printable ASCII character other than W (got '{}')", text));
  }
}

void validate(const RunOptions &o) {
  mapping::validate(o.sensor);
  sensing::validate(o.model);
  sensing::validate(o.range_model);
  plan::validate(o.plan.wavefront);
  validate_run(o);
  o.simulation.validate();
  validate(o.output);
  loc::parse_sensor(o.localize.sensor);
  loc::validate_motion(o.localize.motion);
  loc::validate_localized(o.localize.localized);
  robot_profile(o);  // a bad profile file fails here, before any world is read
}

const maze::sim::RobotProfile &robot_profile(const RunOptions &options) {
  if (!options.resolved_profile || options.resolved_for != options.robot) {
    options.resolved_profile = std::make_shared<const maze::sim::RobotProfile>(resolve_robot(options.robot));
    options.resolved_for = options.robot;
  }
  return *options.resolved_profile;
}

std::string_view default_robot(sensing::ModelKind model) { return sensing::setup(model).default_robot; }

std::string no_effect_warning(std::string_view option, std::string_view without) {
  return fmt::format("warning: {} has no effect{}{}", option, without.starts_with(':') ? "" : " ", without);
}

std::vector<std::string> check_options_apply(const GivenOptions &given, const RunOptions &options) {
  std::vector<std::string> warnings;
  for (const OptionUse<RunOptions> &use : kOptionUses) {
    if (!given.given(use.option) || use.applies(options)) continue;
    // compare and batch plan no path: --dilate never applies there.
    const bool plans_nothing = std::string_view(use.option) == "--dilate" && given.command != "run";
    warnings.push_back(plans_nothing ? no_effect_warning(use.option, fmt::format(": {} plans no path", given.command))
                                     : no_effect_warning(use.option, use.without));
  }
  // The options the set-up's model does not read (app/run/model_rules.hpp).
  for (std::string &warning : check_model_options(sensing::setup(options.model.kind), model_given_options(given))) {
    warnings.push_back(std::move(warning));
  }
  check_lidar_options(given, options, warnings);
  check_range_sensor_kinds(options, warnings);
  // Only a bumper set-up reads the bumpers (sensing/setups.cpp): a stuck one changes nothing
  // else. (A bumper the robot lacks is the simulator's error, said alone.)
  const sensing::SetUp &setup = sensing::setup(options.model.kind);
  if (given.given("--stuck-bumper") && !setup.reads_bumpers() && has_bumper(options)) {
    warnings.push_back(fmt::format("warning: --stuck-bumper has no effect with the {} model (read by bump)", setup.name));
  }
  return warnings;
}

namespace {

bool waypoints(const RunOptions &o) { return o.strategy == explore::StrategyKind::waypoints; }
bool wavefront(const RunOptions &o) { return o.strategy == explore::StrategyKind::wavefront; }
bool frontier(const RunOptions &o) { return o.strategy == explore::StrategyKind::frontier; }

// The rules of a run in metres; the depth rays' read like the set-up table's (app/run/model_rules.hpp).
constexpr OptionUse<RunOptions> kMetresOptionUses[] = {
    {"--waypoints", "without --strategy waypoints", waypoints},
    {"--laps", "without --strategy waypoints", waypoints},
    {"--goal", "without --strategy wavefront", wavefront},
    {"--dilate", "without --strategy wavefront (frontier keeps the body's radius clear)", wavefront},
    {"--verbose", "without --strategy frontier (its frontier left and set aside are the details)", frontier},
};

}  // namespace

RunOptions metres_run_options() {
  RunOptions options;
  options.strategy = explore::StrategyKind::frontier;
  options.model.kind = sensing::ModelKind::ray;
  options.robot.clear();
  return options;
}

std::vector<std::string> check_metres_options_apply(const GivenOptions &given, const RunOptions &options) {
  std::vector<std::string> warnings;
  add_no_effect_warnings(given, std::span<const OptionUse<RunOptions>>(kMetresOptionUses), options, warnings);
  if (options.model.kind != sensing::ModelKind::depth) {
    for (const char *option : {"--depth-reading", "--depth-origin"}) {
      if (!given.given(option)) continue;
      warnings.push_back(fmt::format("warning: {} has no effect with the {} model (read by depth)", option,
                                     sensing::to_string(options.model.kind)));
    }
  }
  return warnings;
}

void validate_metres(const RunOptions &o) {
  if (o.metres.cells_x && o.metres.resolution_m) throw common::InputError("give --cells or --resolution, not both");
  if (o.threshold && !std::isfinite(*o.threshold)) {
    throw common::InputError(fmt::format("--threshold must be a finite log-odds value (got {})", *o.threshold));
  }
  if (o.model.kind == sensing::ModelKind::cell) {
    throw common::InputError("--model cell reads a maze's cell sides; in a room the lidar marks with --model ray");
  }
  if (!explore::explores_in(o.strategy, explore::StrategySpace::metres)) {
    throw common::InputError(fmt::format("--strategy must be {} in a room (got '{}')",
                                         explore::strategy_names(explore::StrategySpace::metres),
                                         explore::to_string(o.strategy)));
  }
}

}  // namespace app
