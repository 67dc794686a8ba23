#include "app/run/option_fields.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/parse_number.hpp"
#include "maze/sim/profile.hpp"

namespace app {
namespace {

using Json = nlohmann::ordered_json;

// The field at the end of a path of members: member<&A::b, &B::c>(a) is a.b.c.
template <auto First, auto... Rest, typename Object>
constexpr auto &member(Object &object) {
  if constexpr (sizeof...(Rest) == 0) {
    return object.*First;
  } else {
    return member<Rest...>(object.*First);
  }
}

template <typename T>
Json json_value(const T &value) {
  return Json(value);
}

template <typename T>
Json json_value(const std::optional<T> &value) {
  return value ? Json(*value) : Json(nullptr);
}

// A plain field at Path in Concern.
template <typename Concern, auto... Path>
OptionField<Concern> plain(std::string_view key, std::string_view flag, std::string (*help)(const Concern &),
                           std::string_view controller_arg = "") {
  return {key,
          flag,
          controller_arg,
          help,
          [](Concern &c) -> FieldRef { return &member<Path...>(c); },
          nullptr,
          "",
          [](const Concern &c) { return json_value(member<Path...>(c)); }};
}

// A field whose option is registered by its own code (see the header), or that no option sets
// alone: its key and its echo.
template <typename Concern>
OptionField<Concern> own(std::string_view key, std::string_view flag, Json (*echo)(const Concern &),
                         std::string_view controller_arg = "") {
  return {key, flag, controller_arg, nullptr, nullptr, nullptr, "", echo};
}

Json cell_json(maze::Cell c) { return Json::array({c.x, c.y}); }
Json cell_json(mapping::Cell c) { return Json::array({c.x, c.y}); }

// A point in metres, [x, y], each rounded to the micrometre as the echo prints it.
Json metres_json(const std::array<double, 2> &point) {
  Json j = Json::array();
  for (const double v : point) j.push_back(std::round(v * 1e6) / 1e6);
  return j;
}

template <typename Cell>
Json cell_or_null(const std::optional<Cell> &c) {
  return c ? cell_json(*c) : Json(nullptr);
}

// The value of `flag` as the type its help names. The command line checks values first
// (check_values_ourselves, in the same words); a table's parse is also reached without that
// check (parse_run_options, a fuzz target), so it refuses a wrong value itself rather than
// trusting it.
long long whole_number_of(std::string_view flag, const std::string &text) {
  const std::optional<long long> n = common::parse_number<long long>(text);
  if (!n) {
    throw common::InputError(
        fmt::format("{} needs a whole number (got '{}'{})", flag, text, common::range_note<long long>(text)));
  }
  return *n;
}

double real_number_of(std::string_view flag, const std::string &text) {
  const std::optional<double> x = common::parse_real(text);
  if (!x) {
    throw common::InputError(
        fmt::format("{} needs a number (got '{}'{})", flag, text, common::range_note<double>(text)));
  }
  return *x;
}

void set_unknown(OutputOptions &o, const std::string &text) {
  validate_unknown(text);
  o.unknown = text[0];
}

void set_snapshots(OutputOptions &o, const std::string &text) {
  const long long n = whole_number_of("--snapshots", text);
  validate_snapshots(n);
  o.snapshots = static_cast<int>(n);
}

Json picture_formats_json(const OutputOptions &o) {
  Json formats = Json::array();
  for (const PictureFormat f : o.picture_formats) formats.push_back(std::string(to_string(f)));
  return formats;
}

}  // namespace

template <>
std::span<const OptionField<RunOptions>> option_fields() {
  using O = RunOptions;
  static const std::vector<OptionField<O>> fields{
      own<O>("world", "WORLD", [](const O &o) { return Json(o.world); }),
      own<O>("world_overrides", "", [](const O &o) { return echo_fields(o.world_overrides); }),
      plain<O, &O::subcells>(
          "subcells", "--subcells",
          [](const O &d) { return fmt::format("K: sub-cells per cell side, odd, 3 to 9 (default {})", d.subcells); },
          "subcells"),
      {"strategy", "--strategy", "strategy",
       [](const O &d) {
         return fmt::format("exploration: dfs, frontier, left-wall, right-wall or floodfill (default {})",
                            explore::to_string(d.strategy));
       },
       nullptr, [](O &o, const std::string &name) { o.strategy = explore::parse_strategy(name); }, "",
       [](const O &o) { return Json(std::string(explore::to_string(o.strategy))); }},
      plain<O, &O::robot>("robot", "--robot",
                          [](const O &) {
                            return fmt::format("NAME or FILE.json: robot profile, one of {} (default {})",
                                               robot_names(), default_robots());
                          }),
      plain<O, &O::threshold>(
          "threshold", "--threshold",
          [](const O &) {
            return std::string(
                "L: a sub-cell is occupied when its log-odds >= L, for the map and the walls "
                "(default none: when above 0; a run in metres: at or above 0, -0.5 for bump and depth)");
          },
          "threshold"),
      // The echo shows the steps in effect (the maze's default when not given): the run's
      // summary carries them, and outputs.cpp sets them here before echoing.
      own<O>(
          "max_steps", "--max-steps", [](const O &o) { return json_value(o.max_steps); }, "max-steps"),
      plain<O, &O::time_limit_s>("time_limit_s", "--time-limit",
                                 [](const O &) {
                                   return std::string("S: stop after S simulated seconds (default none; wander needs it)");
                                 }),
      own<O>("model", "", [](const O &o) { return echo_fields(o.model); }),
      own<O>("sensor", "", [](const O &o) { return echo_fields(o.sensor); }),
      own<O>("range_model", "", [](const O &o) { return echo_fields(o.range_model); }),
      own<O>("simulation", "", [](const O &o) { return echo_fields(o.simulation); }),
      own<O>("plan", "", [](const O &o) { return echo_fields(o.plan); }),
      own<O>("output", "", [](const O &o) { return echo_fields(o.output); }),
      own<O>("localize", "", [](const O &o) { return echo_fields(o.localize); }),
  };
  return fields;
}

template <>
std::span<const OptionField<maze::WorldOverrides>> option_fields() {
  using W = maze::WorldOverrides;
  static const std::vector<OptionField<W>> fields{
      {"cell_size_m", "--cell-size", "cell-size",
       [](const W &) {
         return std::string("M: cell side of a text or num world, metres (default 1; an XML world has its own)");
       },
       nullptr,
       [](W &w, const std::string &text) {
         const double m = real_number_of("--cell-size", text);  // nan and inf read: refused below
         if (!(m > maze::kMinCellSize_m && m <= maze::kMaxCellSize_m)) {
           throw common::InputError(
               fmt::format("--cell-size must be more than {} m (four walls of {} m) and at most {} m (got {})",
                           maze::kMinCellSize_m, maze::kDefaultWallThickness_m, maze::kMaxCellSize_m, m));
         }
         w.cell_size_m = m;
       },
       "FLOAT", [](const W &w) { return json_value(w.cell_size_m); }},
      own<W>(
          "start", "--start",
          [](const W &w) {
            if (!w.start) return Json(nullptr);
            Json start = cell_json(*w.start);
            start.push_back(std::string(maze::to_string(w.start_heading)));
            return start;
          },
          "start"),
      own<W>("start_m", "--start", [](const W &w) { return w.start_m ? metres_json(*w.start_m) : Json(nullptr); }),
      own<W>("start_position", "--start", [](const W &w) { return json_value(w.start_position); }),  // pos:N
      own<W>("random_start", "--start", [](const W &w) { return Json(w.random_start); }),            // random
      own<W>(
          "goals", "--goal",
          [](const W &w) {
            if (!w.goals) return Json(nullptr);
            Json goals = Json::array();
            for (const maze::Cell g : *w.goals) goals.push_back(cell_json(g));
            return goals;
          },
          "goal"),
      own<W>("centre_goals", "--goal", [](const W &w) { return Json(w.centre_goals); }),  // --goal centre
  };
  return fields;
}

template <>
std::span<const OptionField<sensing::ModelOptions>> option_fields() {
  using M = sensing::ModelOptions;
  static const std::vector<OptionField<M>> fields{
      {"kind", "--model", "model",
       [](const M &) {  // one line for every kind of run, whatever default the command holds
         return fmt::format("mapping model: {} (default {}; a run in metres: {})", models_by_device(),
                            sensing::to_string(M{}.kind), sensing::to_string(metres_run_options().model.kind));
       },
       nullptr, [](M &m, const std::string &name) { m.kind = sensing::parse_model(name); }, "",
       [](const M &m) { return Json(std::string(sensing::to_string(m.kind))); }},
      own<M>("wall_margin", "", [](const M &m) { return Json(m.wall_margin); }),
      plain<M, &M::hit_depth>(
          "hit_depth", "--hit-depth",
          [](const M &d) {
            return fmt::format("ray model: sub-cells behind a hit also occupied (default {})", d.hit_depth);
          },
          "hit-depth"),
      plain<M, &M::ignore_no_return>(
          "ignore_no_return", "--ignore-no-return",
          [](const M &) {
            return std::string(
                "ray model: a beam with no return frees nothing (default off: it frees up to max range)");
          },
          "ignore-no-return"),
  };
  return fields;
}

template <>
std::span<const OptionField<mapping::SensorModelOptions>> option_fields() {
  using S = mapping::SensorModelOptions;
  static const std::vector<OptionField<S>> fields{
      plain<S, &S::p_free>(
          "p_free", "--p-free",
          [](const S &d) { return fmt::format("inverse model where a beam passed (default {})", d.p_free); }, "p-free"),
      plain<S, &S::p_occ>(
          "p_occ", "--p-occ",
          [](const S &d) { return fmt::format("inverse model where a beam ended (default {})", d.p_occ); }, "p-occ"),
      plain<S, &S::prior>(
          "prior", "--prior",
          [](const S &d) { return fmt::format("belief before any measurement (default {})", d.prior); }, "prior"),
      {"log_base", "--log-base", "log-base",
       [](const S &d) { return fmt::format("base of the log-odds: e or 10 (default {})", mapping::to_string(d.base)); },
       nullptr,
       [](S &s, const std::string &base) {
         if (base == "e") {
           s.base = mapping::LogBase::e;
         } else if (base == "10") {
           s.base = mapping::LogBase::ten;
         } else {
           throw common::InputError("--log-base must be e or 10 (got " + base + ")");
         }
       },
       "", [](const S &s) { return Json(std::string(mapping::to_string(s.base))); }},
      own<S>(
          "clamp", "--clamp",
          [](const S &s) {
            return s.clamp ? Json::array({s.clamp->min, s.clamp->max}) : Json(nullptr);
          },
          "clamp"),
  };
  return fields;
}

template <>
std::span<const OptionField<sensing::RangeModelOptions>> option_fields() {
  using R = sensing::RangeModelOptions;
  static const std::vector<OptionField<R>> fields{
      {"pie_half_angle_rad", "--pie-beta", "pie-beta-rad",
       [](const R &d) {
         return fmt::format("pie model: slice half-angle, degrees (default {:g})",
                            d.pie_half_angle_rad * 180.0 / std::numbers::pi);
       },
       nullptr,
       [](R &r, const std::string &text) {
         r.pie_half_angle_rad = real_number_of("--pie-beta", text) * std::numbers::pi / 180.0;
       },
       "FLOAT", [](const R &r) { return Json(r.pie_half_angle_rad); }},
      plain<R, &R::pie_contact_m>(
          "pie_contact_m", "--pie-alpha",
          [](const R &d) { return fmt::format("pie model: contact slice length, m (default {})", d.pie_contact_m); },
          "pie-alpha"),
      own<R>(
          "pie_usable_fraction", "", [](const R &r) { return Json(r.pie_usable_fraction); }, "pie-usable"),
  };
  return fields;
}

template <>
std::span<const OptionField<maze::sim::SimulationOptions>> option_fields() {
  using S = maze::sim::SimulationOptions;
  static const std::vector<OptionField<S>> fields{
      own<S>("seed", "--seed", [](const S &s) { return Json(s.seed); }),
      plain<S, &S::noise>(
          "noise", "--noise",
          [](const S &) {
            return std::string(
                "lidar noise, standard deviation as a fraction of max range; 0 makes "
                "every sensor exact (default the robot's)");
          },
          "lidar-noise"),
      plain<S, &S::dropout>(
          "dropout", "--dropout",
          [](const S &) { return std::string("fault: fraction of lidar beams that read +infinity (default 0)"); }),
      plain<S, &S::spikes>(
          "spikes", "--spikes",
          [](const S &) { return std::string("fault: fraction of lidar beams that read a random range (default 0)"); }),
      {"stuck_bumper", "--stuck-bumper", "",
       [](const S &) { return std::string("fault: NAME, a bumper that always reads pressed (default none)"); },
       [](S &s) -> FieldRef { return &s.stuck_bumper; }, nullptr, "",
       [](const S &s) { return s.stuck_bumper.empty() ? Json(nullptr) : Json(s.stuck_bumper); }},
      plain<S, &S::wheel_slip>(
          "wheel_slip", "--wheel-slip",
          [](const S &) {
            return std::string(
                "fault: fraction of wheel turning that does not move the robot; the encoders count it all "
                "(default 0)");
          }),
  };
  return fields;
}

template <>
std::span<const OptionField<PlanOptions>> option_fields() {
  using P = PlanOptions;
  static const std::vector<OptionField<P>> fields{
      own<P>("from", "--from", [](const P &p) { return cell_or_null(p.from); }),
      own<P>("to", "--to", [](const P &p) { return cell_or_null(p.to); }),  // run: --plan-to
      plain<P, &P::wavefront, &plan::WavefrontOptions::dilate>(
          "dilate", "--dilate",
          [](const P &d) {
            return fmt::format("N: planning: grow obstacles by N sub-cells (default {})", d.wavefront.dilate);
          }),
      plain<P, &P::speed_run>(
          "speed_run", "--speed-run",
          [](const P &) {
            return std::string(
                "after the search, drive the known shortest path from the start to the goal, returning to "
                "the start first (a micromouse speed run; with floodfill the path is searched until "
                "proven)");
          },
          "speed-run"),
  };
  return fields;
}

template <>
std::span<const OptionField<OutputOptions>> option_fields() {
  using O = OutputOptions;
  static const std::vector<OptionField<O>> fields{
      own<O>("out", "--out", [](const O &o) { return Json(o.out_dir); }),
      plain<O, &O::ascii>("ascii", "--ascii",
                          [](const O &) { return std::string("heading arrows as ^ > v < instead of ↑ → ↓ ←"); }),
      {"unknown", "--unknown", "",
       [](const O &) { return std::string("CHAR: drawn for never-observed sub-cells (default blank)"); }, nullptr,
       set_unknown, "", [](const O &o) { return o.unknown ? Json(std::string(1, *o.unknown)) : Json(nullptr); }},
      plain<O, &O::quiet>("quiet", "--quiet",
                          [](const O &) {
                            return std::string(
                                "print only the final map and the summary (mms: and the marks; a run in metres: the "
                                "summary alone)");
                          }),
      own<O>("color", "--color", [](const O &o) { return Json(o.color); }),
      plain<O, &O::animate>("animate", "--animate",
                            [](const O &) {
                              return std::string(
                                  "redraw the map in place as the robot moves (standard output must be a terminal)");
                            }),
      plain<O, &O::fps>(
          "fps", "--fps",
          [](const O &d) { return fmt::format("--animate: frames per second, at most (default {:g})", d.fps); }),
      plain<O, &O::speed>("speed", "--speed",
                          [](const O &d) {
                            return fmt::format("--animate: simulated seconds per wall-clock second (default {:g})",
                                               d.speed);
                          }),
      plain<O, &O::step>("step", "--step",
                         [](const O &) { return std::string("stop after each cell: Enter goes on, q quits"); }),
      plain<O, &O::trace>("trace", "--no-trace",
                          [](const O &) { return std::string("with --out, do not write trace.csv"); }),
      // 0 is "none" inside (the default), not a value to type: --snapshots 0 wrote none, silently.
      {"snapshots", "--snapshots", "",
       [](const O &) {
         return std::string(
             "N: with --out, N pictures of the map at equal fractions of the run's steps in DIR/snapshots/ (3: after "
             "1/3, 2/3 and at the end)");
       },
       nullptr, set_snapshots, "INT", [](const O &o) { return Json(o.snapshots); }},
      plain<O, &O::replay>(
          "replay", "--no-replay",
          [](const O &) {
            return std::string(
                "with --out, do not write replay.html (the run in a browser: slider, play, the map at each move)");
          }),
      own<O>("subcell_columns", "--wide", [](const O &o) { return json_value(o.subcell_columns); }),  // and --narrow
      plain<O, &O::trace_steps>(
          "trace_steps", "--trace-steps",
          [](const O &) {
            return std::string(
                "with --out, trace.csv a row every control step (default for cell and ray: a row when the "
                "action or cell changes or a scan updates the map)");
          }),
      {"picture_formats", "--picture-format", "",
       [](const O &) {
         return std::string(
             "LIST: with --out, map, truth, plan and the snapshots as png, svg and/or pdf, comma-separated (default "
             "png; svg and pdf print at any size)");
       },
       nullptr, [](O &o, const std::string &text) { o.picture_formats = parse_picture_formats(text); }, "",
       picture_formats_json},
  };
  return fields;
}

}  // namespace app
