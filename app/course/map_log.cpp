#include "app/course/map_log.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "app/picture/plain_grid_picture.hpp"
#include "app/report/output_dir.hpp"
#include "app/report/outputs.hpp"
#include "app/run/option_values.hpp"
#include "common/atomic_file.hpp"
#include "common/csv.hpp"
#include "common/error.hpp"
#include "common/input_file.hpp"
#include "common/parse_number.hpp"
#include "common/standard_streams.hpp"

namespace app::course {
namespace {

inline constexpr Rgb kThresholdWall{0, 0, 0};
inline constexpr Rgb kThresholdOpen{255, 255, 255};

// An option of the other sensor is refused, not ignored.
void check_sensor_options(const MapLogInput &input, sensing::BumpDepthSensor sensor) {
  if (sensor == sensing::BumpDepthSensor::bump && input.depth_options_given) {
    throw common::InputError(
        "--depth-angles, --depth-max, --depth-reading and --depth-origin apply to depth logs only (this log is mapped "
        "with its bumps)");
  }
  if (sensor == sensing::BumpDepthSensor::depth && input.bump_options_given) {
    throw common::InputError("--bump-radius applies to bump logs only (this log is mapped with its depth rays)");
  }
}

// The fields of one line of the log (common/csv.hpp), blanks around each removed.
std::vector<common::CsvField> split_fields(const std::string &file, int number, std::string_view line) {
  std::optional<std::vector<common::CsvField>> fields = common::csv_fields(line);
  if (!fields) throw common::InputError({file, number, 1}, "a quoted field is not closed on its line");
  for (common::CsvField &f : *fields) f.text = std::string(common::trim_blanks(f.text));
  return std::move(*fields);
}

// run --out's trace.csv names for the log's columns (app/report/trace_sensors.hpp): the time, the
// pose the robot reads (GPS, IMU) and depth rays in metres; "" for a name it shares.
std::string trace_name(const std::string &name) {
  if (name == "t") return "time_s";
  if (name == "x") return "gps_x_m";
  if (name == "y") return "gps_y_m";
  if (name == "theta") return "imu_yaw_rad";
  if (name.starts_with("depth_")) return name + "_m";
  return "";
}

// The log's columns: where each needed name is in the header, under the log's name or else
// under trace.csv's.
struct Columns {
  std::vector<std::string> names;
  std::optional<std::size_t> position(const std::string &name) const {
    for (std::size_t n = 0; n < names.size(); ++n) {
      if (names[n] == name) return n;
    }
    return std::nullopt;
  }
  std::optional<std::size_t> find(const std::string &name) const {
    const std::optional<std::size_t> own = position(name);
    const std::string alias = trace_name(name);
    return own || alias.empty() ? own : position(alias);
  }
};

std::vector<std::string> sensor_columns(sensing::BumpDepthSensor sensor) {
  if (sensor == sensing::BumpDepthSensor::bump) return {"bump_right", "bump_left", "bump_front"};
  std::vector<std::string> names;
  for (int n = 1; n <= sensing::kDepthRays; ++n) names.push_back(fmt::format("depth_{}", n));
  return names;
}

sensing::BumpDepthSensor pick_sensor(const MapLogInput &input, const Columns &columns) {
  if (input.sensor == "bump") return sensing::BumpDepthSensor::bump;
  if (input.sensor == "depth") return sensing::BumpDepthSensor::depth;
  if (!input.sensor.empty()) throw common::InputError("--sensor must be bump or depth (got " + input.sensor + ")");
  const bool bump = columns.find("bump_front").has_value();
  const bool depth = columns.find("depth_1").has_value();
  if (bump && depth) throw common::InputError("the log has bump and depth columns: choose one with --sensor bump|depth");
  return depth ? sensing::BumpDepthSensor::depth : sensing::BumpDepthSensor::bump;
}

double number_at(const std::string &file, int line, const common::CsvField &f, const std::string &name) {
  const std::optional<double> value = common::parse_number<double>(f.text);
  if (!value) {
    throw common::InputError({file, line, f.column}, fmt::format("{} must be a finite number (got '{}')", name, f.text));
  }
  return *value;
}

struct Log {
  sensing::BumpDepthSensor sensor = sensing::BumpDepthSensor::bump;
  std::vector<sensing::PoseStep> steps;
};

sensing::PoseStep parse_step(const std::string &file, int line, const std::vector<common::CsvField> &fields, const Columns &c,
                             sensing::BumpDepthSensor sensor) {
  const auto value = [&](const std::string &name) {
    const std::size_t at = *c.find(name);
    return number_at(file, line, fields[at], c.names[at]);  // named as the header names it
  };
  sensing::PoseStep s;
  s.t = value("t"), s.x_m = value("x"), s.y_m = value("y"), s.theta_rad = value("theta");
  if (sensor == sensing::BumpDepthSensor::bump) {
    bool *flags[] = {&s.bump_right, &s.bump_left, &s.bump_front};
    const auto names = sensor_columns(sensor);
    for (std::size_t n = 0; n < 3; ++n) {
      const double v = value(names[n]);
      if (v != 0.0 && v != 1.0) {
        throw common::InputError({file, line, fields[*c.find(names[n])].column},
                                 fmt::format("{} must be 0 or 1 (got '{}')", names[n], fields[*c.find(names[n])].text));
      }
      *flags[n] = v == 1.0;
    }
  } else {
    const auto names = sensor_columns(sensor);
    for (std::size_t n = 0; n < names.size(); ++n) s.depth_m[n] = value(names[n]);
  }
  return s;
}

// The log's text (within common::kCsvLimits: /dev/zero or an endless line fails at once).
std::string log_text(const std::string &path) {
  try {
    return common::read_text(path, "log (CSV)", common::kCsvLimits);
  } catch (const common::InputError &e) {
    if (!e.where().file.empty()) throw;  // not a log
    throw common::InputError(fmt::format("cannot read {}", path));
  }
}

// The next line of `text` from `offset` (without its "\n"); false at the end.
bool next_line(std::string_view text, std::size_t &offset, std::string_view &line) {
  if (offset >= text.size()) return false;
  const std::size_t end = std::min(text.find('\n', offset), text.size());
  line = text.substr(offset, end - offset);
  offset = end + 1;
  return true;
}

Log read_log(const MapLogInput &input) {
  const std::string text = log_text(input.log_path);
  std::size_t offset = 0;
  std::string_view line;
  if (!next_line(text, offset, line)) throw common::InputError({input.log_path, 0, 0}, "the log is empty; expected a header line");
  Columns columns;
  for (const common::CsvField &f : split_fields(input.log_path, 1, line)) columns.names.push_back(f.text);
  Log log;
  log.sensor = pick_sensor(input, columns);
  std::vector<std::string> needed{"t", "x", "y", "theta"};
  for (const auto &name : sensor_columns(log.sensor)) needed.push_back(name);
  for (const auto &name : needed) {
    if (!columns.find(name)) {
      const std::string alias = trace_name(name);
      throw common::InputError({input.log_path, 1, 1},
                               alias.empty() ? fmt::format("missing column '{}'", name)
                                             : fmt::format("missing column '{}' (or trace.csv's '{}')", name, alias));
    }
  }
  for (int number = 2; next_line(text, offset, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto fields = split_fields(input.log_path, number, line);
    if (fields.size() != columns.names.size()) {
      throw common::InputError({input.log_path, number, 1},
                               fmt::format("expected {} fields like the header, got {}", columns.names.size(), fields.size()));
    }
    log.steps.push_back(parse_step(input.log_path, number, fields, columns, log.sensor));
  }
  if (log.steps.empty()) throw common::InputError({input.log_path, 2, 1}, "no time steps after the header");
  return log;
}

int whole(double v, const std::string &option) {
  if (v != std::floor(v) || v < 1 || v > 1e6) throw common::InputError(fmt::format("{} must be whole numbers >= 1 (got {})", option, v));
  return static_cast<int>(v);
}

sensing::BumpDepthOptions map_log_options(const MapLogInput &input) {
  sensing::BumpDepthOptions o = input.options;
  const auto cells = parse_number_list(input.cells, "--cells", 2);
  o.cells_x = whole(cells[0], "--cells"), o.cells_y = whole(cells[1], "--cells");
  if (input.boundary.empty()) throw common::InputError("map-log needs --boundary XS,XE,YS,YE (m)");
  const auto b = parse_number_list(input.boundary, "--boundary", 4);
  o.x_start_m = b[0], o.x_end_m = b[1], o.y_start_m = b[2], o.y_end_m = b[3];
  if (input.base != "e" && input.base != "10") throw common::InputError("--log-base must be e or 10 (got " + input.base + ")");
  o.base = input.base == "e" ? mapping::LogBase::e : mapping::LogBase::ten;
  if (!input.depth_angles.empty()) {
    const auto angles = parse_number_list(input.depth_angles, "--depth-angles", sensing::kDepthRays);
    std::copy(angles.begin(), angles.end(), o.depth_angles_deg.begin());
  }
  if (input.depth_reading != "range" && input.depth_reading != "axial") {
    throw common::InputError("--depth-reading must be range or axial (got " + input.depth_reading + ")");
  }
  o.depth_reading = input.depth_reading == "axial" ? sensing::DepthReading::axial : sensing::DepthReading::range;
  if (!input.depth_origin.empty()) {
    const auto origin = parse_number_list(input.depth_origin, "--depth-origin", 2);
    o.depth_origin_x_m = origin[0], o.depth_origin_y_m = origin[1];
  }
  sensing::validate(o);
  return o;
}

// The steps (1-based) after which a snapshot is taken: fractions of the log, rounded.
std::vector<std::size_t> snapshot_steps(const MapLogInput &input, std::size_t steps) {
  if (!input.snapshots.empty() && input.out_dir.empty()) throw common::InputError("--snapshots-at needs --out DIR");
  const auto fractions = input.snapshots.empty() ? std::vector<double>{1.0 / 3, 2.0 / 3, 1.0}
                                                 : parse_number_list(input.snapshots, "--snapshots-at");
  std::vector<std::size_t> out;
  for (const double f : fractions) {
    if (!(f > 0.0 && f <= 1.0)) throw common::InputError(fmt::format("--snapshots-at are fractions in (0, 1] (got {})", f));
    out.push_back(std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(f * static_cast<double>(steps)))));
  }
  return out;
}

std::string grid_csv(const sensing::LogOddsGrid &g) {
  std::string out;
  for (int j = g.cells_y - 1; j >= 0; --j) {
    for (int i = 0; i < g.cells_x; ++i) out += fmt::format("{}{:.4f}", i == 0 ? "" : ",", g.at(i, j));
    out += "\n";
  }
  return out;
}

std::string grid_matrix(const sensing::LogOddsGrid &g) {
  std::string out;
  for (int j = g.cells_y - 1; j >= 0; --j) {
    for (int i = 0; i < g.cells_x; ++i) out += fmt::format("{}{:+.3f}", i == 0 ? "" : " ", g.at(i, j));
    out += "\n";
  }
  return out;
}

std::string thresholded(const sensing::LogOddsGrid &g, double threshold) {
  std::string out;
  for (int j = g.cells_y - 1; j >= 0; --j) {
    for (int i = 0; i < g.cells_x; ++i) out += g.at(i, j) >= threshold ? 'W' : ' ';
    out += "\n";
  }
  return out;
}

PlainGrid plain_grid(const sensing::BumpDepthOptions &o) {
  PlainGrid p;
  p.cells_x = o.cells_x, p.cells_y = o.cells_y;
  p.x0_m = o.x_start_m, p.y0_m = o.y_start_m;
  p.cell_w_m = (o.x_end_m - o.x_start_m) / o.cells_x;
  p.cell_h_m = (o.y_end_m - o.y_start_m) / o.cells_y;
  return p;
}

// The log-odds picture: map.png's tones, graded by one occupied (0.99999) and one ray (0.4)
// update.
std::string log_odds_png(const sensing::BumpDepthOptions &o, const sensing::LogOddsGrid &g, const std::string &caption) {
  const double l0 = mapping::log_odds(o.prior, o.base);
  const double occupied = mapping::log_odds(sensing::kBumpDepthOccupiedP, o.base) - l0;
  const double ray = mapping::log_odds(sensing::kBumpDepthRayP, o.base) - l0;
  PlainGrid p = plain_grid(o);
  for (int j = 0; j < g.cells_y; ++j) {
    for (int i = 0; i < g.cells_x; ++i) p.tones.push_back(log_odds_tone(g.at(i, j), l0, occupied, ray));
  }
  Figure legend;
  legend.lines = {caption};
  legend.bar = map_tone_bar(log_odds_tones(l0, occupied, ray), "never updated");
  return plain_grid_picture(p, legend).encode();
}

// The thresholded map: black where log-odds >= the threshold (the printed W), else white.
std::string thresholded_png(const sensing::BumpDepthOptions &o, const sensing::LogOddsGrid &g, double threshold,
                            const std::string &caption) {
  PlainGrid p = plain_grid(o);
  for (int j = 0; j < g.cells_y; ++j) {
    for (int i = 0; i < g.cells_x; ++i) p.tones.push_back(g.at(i, j) >= threshold ? kThresholdWall : kThresholdOpen);
  }
  Figure legend;
  legend.lines = {caption};
  legend.items = {{Swatch::box, kThresholdWall, fmt::format("W: log-odds at least {:g}", threshold)},
                  {Swatch::box, kThresholdOpen, "below"}};
  return plain_grid_picture(p, legend).encode();
}

std::string caption(const MapLogInput &input, const sensing::BumpDepthOptions &o, std::size_t step, std::size_t steps) {
  return fmt::format("map-log {}, {} x {} cells, step {}/{}", std::filesystem::path(input.log_path).filename().string(),
                     o.cells_x, o.cells_y, step, steps);
}

// The names --out may write: the final files and each snapshot's.
std::vector<std::string> map_log_output_names(const std::vector<std::size_t> &snapshots) {
  std::vector<std::string> names{"logodds.csv", "logodds.png", "thresholded.txt", "thresholded.png"};
  for (const std::size_t at : snapshots) {
    names.push_back(fmt::format("logodds_step{}.csv", at));
    names.push_back(fmt::format("logodds_step{}.png", at));
  }
  return names;
}

// --out: a snapshot's grid and picture after step `at`.
void write_snapshot(OutputDir &out, const MapLogInput &input, const sensing::BumpDepthOptions &o,
                    const sensing::LogOddsGrid &grid, std::size_t at, std::size_t steps) {
  out.write(fmt::format("logodds_step{}.csv", at), grid_csv(grid));
  out.write(fmt::format("logodds_step{}.png", at), log_odds_png(o, grid, caption(input, o, at, steps)));
}

// --out: the final grid, its picture and the thresholded map.
void write_final(OutputDir &out, const MapLogInput &input, const sensing::BumpDepthOptions &o,
                 const sensing::LogOddsGrid &grid, std::size_t steps) {
  const std::string text = caption(input, o, steps, steps);
  out.write("logodds.csv", grid_csv(grid));
  out.write("logodds.png", log_odds_png(o, grid, text));
  out.write("thresholded.txt", thresholded(grid, input.threshold));
  out.write("thresholded.png", thresholded_png(o, grid, input.threshold, text));
}

std::string map_log_header(const MapLogInput &input, const sensing::BumpDepthOptions &o, const Log &log) {
  const double l0 = mapping::log_odds(o.prior, o.base);
  const auto l = [&](double p) { return mapping::log_odds(p, o.base); };
  const char *sensor = log.sensor == sensing::BumpDepthSensor::bump ? "bump" : "depth";
  std::string out = fmt::format("map-log {}: {} steps, sensor {}, {} x {} cells over x {:g} .. {:g} m, y {:g} .. {:g} m\n",
                                input.log_path, log.steps.size(), sensor, o.cells_x, o.cells_y, o.x_start_m, o.x_end_m,
                                o.y_start_m, o.y_end_m);
  out += fmt::format("log base {}, prior {:g} (l0 = {:+.3f}): occupied l({:g}) = {:+.3f}, free l({:g}) = {:+.3f}, "
                     "ray l({:g}) = {:+.3f}\n",
                     mapping::to_string(o.base), o.prior, l0, sensing::kBumpDepthOccupiedP,
                     l(sensing::kBumpDepthOccupiedP), sensing::kBumpDepthFreeP, l(sensing::kBumpDepthFreeP),
                     sensing::kBumpDepthRayP, l(sensing::kBumpDepthRayP));
  return out;
}

// A pose off the grid marks nothing there, which the map alone would not tell.
void warn_outside_boundary(const sensing::BumpDepthOptions &o, const Log &log) {
  std::size_t outside = 0;
  for (const sensing::PoseStep &step : log.steps) {
    const bool in = step.x_m >= o.x_start_m && step.x_m <= o.x_end_m && step.y_m >= o.y_start_m && step.y_m <= o.y_end_m;
    if (!in) ++outside;
  }
  if (outside == 0) return;
  common::print_stderr("warning: {} of {} poses lie outside --boundary {:g},{:g},{:g},{:g}; what they sense off the grid is not mapped\n",
                       outside, log.steps.size(), o.x_start_m, o.x_end_m, o.y_start_m, o.y_end_m);
}

}  // namespace

sensing::BumpDepthOptions homework_options() {
  sensing::BumpDepthOptions o;
  o.cells_x = 25;
  o.cells_y = 25;
  o.prior = 0.5;
  o.base = mapping::LogBase::ten;
  o.bump_radius_m = 0.16;
  o.depth_angles_deg = {28.5, 21.375, 14.25, 7.125, 0.0, -7.125, -14.25, -21.375, -28.5};
  o.depth_max_m = 10.0;
  return o;
}

std::string run_map_log(const MapLogInput &input) {
  if (!std::isfinite(input.threshold)) {
    throw common::InputError(fmt::format("--threshold must be a finite log-odds value (got {})", input.threshold));
  }
  const sensing::BumpDepthOptions o = map_log_options(input);
  const Log log = read_log(input);
  check_sensor_options(input, log.sensor);
  const auto snapshots = snapshot_steps(input, log.steps.size());
  warn_outside_boundary(o, log);
  // Only map-log's own names: a run's directory it writes into keeps the run's files.
  std::optional<OutputDir> out_dir;
  if (!input.out_dir.empty()) {
    out_dir.emplace(input.out_dir, std::vector<NamedInput>{{"the log", input.log_path}},
                    OwnNamesOnly{map_log_output_names(snapshots)});
  }
  sensing::LogOddsGrid grid = sensing::make_log_odds_grid(o);
  for (std::size_t n = 0; n < log.steps.size(); ++n) {
    sensing::apply_bump_depth_marks(o, log.sensor, log.steps[n], grid);
    for (const std::size_t at : snapshots) {
      if (at == n + 1 && out_dir) write_snapshot(*out_dir, input, o, grid, at, log.steps.size());
    }
  }
  if (out_dir) {
    write_final(*out_dir, input, o, grid, log.steps.size());
    out_dir->finish();
  }
  std::string out = map_log_header(input, o, log) + "\nfinal log-odds, north row first:\n" + grid_matrix(grid);
  out += fmt::format("\nthresholded: W where log-odds >= {:g}\n", input.threshold) + thresholded(grid, input.threshold);
  return out;
}

}  // namespace app::course
