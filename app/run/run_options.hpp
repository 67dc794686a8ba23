#pragma once
// The options of a run, one struct per concern. The command line fills them in
// (app/cli/run_cli.hpp), validate() checks them once, and from there they travel by const
// reference: controller_options() and run_maze() hand each concern on whole (the sensor
// model, the mapping options, the range models, the simulation and its faults), and
// summary.json echoes them whole (app/report/outputs.hpp).

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/picture/drawing.hpp"
#include "app/run/localization.hpp"
#include "explore/strategies.hpp"
#include "mapping/grid_types.hpp"
#include "sensing/setups.hpp"
#include "sensing/range_models.hpp"
#include "mapping/sensor_model.hpp"
#include "maze/sim/simulation.hpp"
#include "maze/world/world.hpp"
#include "plan/cell/wavefront.hpp"
#include "robot/metric/controller.hpp"
#include "sensing/bump_depth_marks.hpp"

namespace app {

// What the run shows and writes: the terminal (map style, progress, animation, --step) and
// --out DIR.
struct OutputOptions {
  bool ascii = false;                   // --ascii: heading arrows ^ > v <
  std::optional<char> unknown;          // --unknown CHAR for never-observed sub-cells
  bool quiet = false;                   // --quiet: final map and summary only
  bool color = false;                   // ANSI colours (a terminal, no --no-color)
  bool animate = false;                 // --animate: the map redrawn in place
  double fps = 30.0;                    // --fps, --animate's frames per second at most
  double speed = 10.0;                  // --speed: simulated seconds per wall-clock second
  bool step = false;                    // --step: wait for Enter (or q) after each cell
  std::string out_dir;                  // --out DIR: map.pgm, map.yaml, map.png, truth.png, summary.json, trace.csv, replay.html
  bool trace = true;                    // trace.csv with --out (--no-trace: not written)
  bool trace_steps = false;             // --trace-steps: a row every control step (see trace_every_step)
  int snapshots = 0;                    // --snapshots N: N pictures through the run in DIR/snapshots/
  bool replay = true;                   // replay.html with --out (--no-replay: not written)
  // --picture-format: map, truth, plan and the snapshots in each of these (default PNG)
  std::vector<PictureFormat> picture_formats{PictureFormat::png};
  // --narrow (1) or --wide (2): terminal columns a sub-cell; none: 2 when standard output is
  // a terminal wide enough for the map so drawn, else 1 (pipes and files: the classroom look).
  std::optional<int> subcell_columns;
};

// Planning on the learned grid after exploring.
struct PlanOptions {
  // A wavefront path from `from` (default: where the robot ended) to `to` (run --plan-to;
  // `plan` sets both ends, --from and --to).
  std::optional<mapping::Cell> from;
  std::optional<mapping::Cell> to;
  plan::WavefrontOptions wavefront;     // --dilate N sub-cells
  bool only = false;                    // `plan`: print only the planned map and the summary
  bool speed_run = false;               // --speed-run: the micromouse speed run, start to goal (robot/options.hpp)
};

// What a run in metres adds (the room command, batch's room rows; app/run/metric/run.hpp):
// the metric map's grid, the metric strategies' own options, the start as a pose in metres,
// where the depth rays leave from, and the maps printed at simulated times and control
// steps. The strategy, the model, the robot, the limits, the seed, the sensor model and what
// the run prints and writes are the run's own fields, as for every kind of run.
struct MetresOptions {
  // --waypoints, --laps, --goal, --dilate (cells) and the controller's constants; its
  // strategy, time limit and seed are set from the run's when the run starts.
  robot::MetricOptions controller;
  std::optional<int> cells_x, cells_y;        // --cells X,Y
  std::optional<double> resolution_m;         // --resolution M (default 0.1)
  std::optional<mapping::Point> start;        // --start X,Y (default: the world's start)
  std::optional<double> start_yaw_deg;
  // --model depth: how the depth rays report (range along the ray, or axial depth along the
  // heading) and where they leave from (robot frame, m; none: the rim, the range from the centre).
  sensing::DepthReading depth_reading = sensing::DepthReading::range;
  std::optional<mapping::Point> depth_origin;
  std::vector<double> snapshots_at_s;         // --snapshots-at: the map printed at these simulated seconds
  std::vector<std::int64_t> snapshot_steps;   // --snapshot-steps: and at these control steps
  bool verbose = false;  // --verbose: frontier's details (the frontier left and set aside) after the end line
};

// run --localize: the localization lab's grid Bayes filter follows the robot, knowing the
// maze's walls and not its start (app/run/live_localization.hpp).
struct LocalizationOptions {
  bool on = false;                          // --localize
  std::string sensor;                       // --sensor P1,P2,P3,P4; empty: the lab's 0.8,0.2,0.4,0.6
  double motion = loc::kLabMotion;          // --motion: P(a move succeeds)
  double localized = loc::kLabLocalized;    // --localized: the share one cell must hold
};

struct RunOptions {
  std::string world;                    // the path as the user gave it
  maze::WorldOverrides world_overrides; // --cell-size, --start, --goal
  int subcells = 3;                     // --subcells K
  sensing::ModelOptions model;        // --model, --hit-depth, --ignore-no-return
  mapping::SensorModelOptions sensor;   // --p-free, --p-occ, --prior, --log-base, --clamp
  sensing::RangeModelOptions range_model;  // --pie-beta, --pie-alpha
  std::optional<double> threshold;      // --threshold L: occupied when log-odds >= L
  explore::StrategyKind strategy = explore::StrategyKind::dfs;
  std::string robot = "hambot";         // --robot: a built-in profile's name or a FILE.json
  // --max-steps: control steps before the run stops; none: max_steps_for(maze), which no
  // complete exploration reaches (dfs and frontier take about 200 steps a cell).
  std::optional<std::int64_t> max_steps;
  // --time-limit: simulated seconds before the run stops (every kind of run takes it); none:
  // no limit but the steps'. Any positive number, inf included: the steps it allows saturate.
  std::optional<double> time_limit_s;
  // --seed, --noise (lidar noise as a fraction of max range; none: the robot's) and the
  // faults --dropout, --spikes, --stuck-bumper, --wheel-slip.
  maze::sim::SimulationOptions simulation;
  PlanOptions plan;
  OutputOptions output;
  MetresOptions metres;                 // a run in metres only
  LocalizationOptions localize;         // run only

  // robot_profile()'s memo: the profile read for `resolved_for`, shared by copies.
  mutable std::shared_ptr<const maze::sim::RobotProfile> resolved_profile;
  mutable std::string resolved_for;
};

// The profile `options.robot` names, read once: a FILE.json is read and checked by the first
// call, and later calls on these options (or copies of them) reuse it while `robot` is
// unchanged, so one run never sees two versions of a file being edited. Throws
// common::InputError for an unknown name or a bad file. Not safe to call on one object from
// two threads at once; copies are independent (the command line's validate() resolves before a
// batch copies the options into its workers).
const maze::sim::RobotProfile &robot_profile(const RunOptions &options);

// Throws common::InputError naming the first unusable option; each concern's own validate
// (sensor model, mapping, range models, wavefront, simulation), then the run's: --subcells,
// --threshold finite, --noise from 0 to 1, --max-steps >= 1, --unknown one printable
// character but W, --fps and --speed above 0, --snapshots from 0 to 100, and the robot (a profile file is read and
// checked). What needs the world (cells inside it, the grid's size, the robot's sensors)
// is checked when the run starts.
void validate(const RunOptions &options);

// --subcells K alone: odd, 3 to 9 (common::InputError otherwise). validate() checks it too.
void validate_subcells(int subcells);

// --snapshots N typed: throws common::InputError unless 1 <= N <= 100 (0, none, is the default).
void validate_snapshots(long long snapshots);

// --picture-format LIST: the formats of "png,svg"; throws common::InputError on an unknown or
// repeated one.
std::vector<PictureFormat> parse_picture_formats(const std::string &text);

// --unknown CHAR: throws common::InputError unless text is one printable ASCII character
// other than W.
void validate_unknown(std::string_view text);

// The robot a model runs on when --robot is not given: its set-up's (sensing/setups.hpp).
std::string_view default_robot(sensing::ModelKind model);

// Which command the options were given to ("run", "plan", "compare", "batch", "room") and
// whether the user typed an option (by its long name, e.g. "--fps").
struct GivenOptions {
  std::string_view command;
  std::function<bool(std::string_view option)> given;
};

// One rule of a command's options: `option` does nothing unless applies(options); `without`
// says what it needs ("without --animate"). Every command's table of them warns alike.
template <typename Options>
struct OptionUse {
  const char *option;
  const char *without;
  bool (*applies)(const Options &);
};

// "warning: OPTION has no effect WITHOUT": the one spelling of an option that does nothing.
std::string no_effect_warning(std::string_view option, std::string_view without);

// One no_effect_warning a rule whose option was given and does not apply, in the table's order.
template <typename Options>
void add_no_effect_warnings(const GivenOptions &given, std::span<const OptionUse<Options>> uses,
                            const Options &options, std::vector<std::string> &warnings) {
  for (const OptionUse<Options> &use : uses) {
    if (given.given(use.option) && !use.applies(options)) warnings.push_back(no_effect_warning(use.option, use.without));
  }
}

// The one place that tells options given that do nothing for what was asked: one
// "warning: --fps has no effect without --animate" line each, the run's own rules (the
// table in run_options.cpp) first, then the model's (app/run/model_rules.hpp: "--hit-depth has
// no effect with the cell model"). The run goes on, but for --p-free/--p-occ with a set-up
// that marks with the course's fixed numbers: common::InputError.
std::vector<std::string> check_options_apply(const GivenOptions &given, const RunOptions &options);

// The options of a run in metres before any is given: the frontier strategy, the ray model,
// the set-up's robot (robot empty), the rest the run's defaults.
RunOptions metres_run_options();

// The warnings of a run in metres: its strategy's own options with another strategy (--goal
// without wavefront, ...), the depth rays' with another model; one "warning: ..." line each.
std::vector<std::string> check_metres_options_apply(const GivenOptions &given, const RunOptions &options);

// A run in metres' own checks, before validate(): --cells with --resolution, a threshold not
// finite, the cell model (a maze's cell sides), a strategy without a variant in metres
// (common::InputError).
void validate_metres(const RunOptions &options);

}  // namespace app
