#include "app/report/outputs.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <system_error>

#include "app/report/output_dir.hpp"
#include "app/report/truth_picture.hpp"
#include "app/run/option_fields.hpp"
#include "app/run/run_report.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/fixed_decimal.hpp"
#include "common/standard_streams.hpp"
#include "mapping/walls.hpp"
#include "sensing/setups.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;

std::string fixed(double v, int decimals) { return fmt::format("{:.{}f}", v, decimals); }

// The first missing ancestor of dir (dir itself when only it is missing), to remove on failure.
}  // namespace

unsigned char pgm_pixel(float log_odds, float initial_log_odds) {
  if (!mapping::observed(log_odds, initial_log_odds)) return 205;
  return log_odds > 0.0f ? 0 : 254;
}

std::string pgm_file(const mapping::OccupancyGrid &grid, float initial_log_odds) {
  const mapping::GridGeometry &g = grid.geometry();
  const int w = g.width_subcells();
  const int h = g.height_subcells();
  std::string out = fmt::format("P5\n# maze_mapper occupancy grid, one pixel a sub-cell\n{} {}\n255\n", w, h);
  out.reserve(out.size() + static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (int row = 0; row < h; ++row) {
    for (int x = 0; x < w; ++x) {
      const float v = grid.at(mapping::SubCell{x, h - 1 - row});
      out += static_cast<char>(pgm_pixel(v, initial_log_odds));
    }
  }
  return out;
}

std::string map_yaml(const mapping::GridGeometry &geometry, const std::string &image_file) {
  return fmt::format(
      "image: {}\n"
      "resolution: {}\n"
      "origin: [{}, {}, 0.0]\n"
      "negate: 0\n"
      "occupied_thresh: 0.65\n"
      "free_thresh: 0.196\n"
      "mode: trinary\n",
      image_file, fixed(geometry.subcell_size_m(), 6), fixed(geometry.origin.x_m, 6),
      fixed(geometry.origin.y_m, 6));
}

MapTones map_tones(const RunOptions &options, const mapping::SensorModel &model) {
  const sensing::MarkProbabilities p = sensing::probabilities_in_effect(sensing::setup(options.model.kind), options.sensor);
  MapTones tones;
  tones.initial_log_odds = static_cast<float>(model.prior_log_odds());
  if (options.threshold) tones.threshold = static_cast<float>(*options.threshold);
  tones.occupied_increment = model.increment_for(p.p_occ);
  tones.free_increment = model.increment_for(p.p_free);
  return tones;
}

std::string map_caption(const RunOptions &options) {
  return fmt::format("{}, model {}, K {}", fs::path(options.world).filename().string(),
                     sensing::to_string(options.model.kind), options.subcells);
}

std::string png_file(const mapping::OccupancyGrid &grid, const MapTones &tones, const MapMarks &marks,
                     const std::string &caption, PictureFormat format, const std::optional<PageFrame> &page) {
  return map_picture(grid, tones, marks, caption, format, page).encode();
}

namespace {

TruthInput truth_input(const RunOptions &options, const RunFiles &files, const std::vector<bool> &visited) {
  return {files.truth, &visited, files.learned, options.subcells, fmt::format("truth: {}", map_caption(options))};
}

}  // namespace

std::string truth_png_file(const RunOptions &options, const RunFiles &files, PictureFormat format,
                           const std::optional<PageFrame> &page) {
  const std::vector<bool> visited = visited_cells(*files.visits);
  return truth_picture(truth_input(options, files, visited), format, page).encode();
}

PageFrame run_page(const RunOptions &options, const RunFiles &files, std::int64_t steps) {
  const mapping::GridGeometry &g = files.grid->geometry();
  const MapTones tones = map_tones(options, *files.model);
  const std::vector<bool> visited = visited_cells(*files.visits);
  const MapMarks marks{*files.path, files.goals, {}, files.landmarks};
  std::vector<Figure> figures{map_figure(g, tones, marks, map_caption(options)),
                              truth_figure(truth_input(options, files, visited))};
  if (options.output.snapshots > 0) {  // the longest snapshot caption
    figures.push_back(map_figure(g, tones, marks, fmt::format("{}, step {}/{}", map_caption(options), steps, steps)));
  }
  return shared_page(figures);
}

namespace {

using Json = nlohmann::ordered_json;

// Every option in effect, one object a concern as RunOptions holds them
// (app/run/option_fields.hpp), with what the run settled: the steps in effect and the
// sensor model's probabilities as its set-up marks with them (pie, bump, depth use the
// course's own numbers: "probabilities" says which; depth adds the robot's own cells').
Json options_json(const RunOptions &o, const RunSummary &s) {
  const sensing::SetUp &setup = sensing::setup(o.model.kind);
  const sensing::MarkProbabilities p = sensing::probabilities_in_effect(setup, o.sensor);
  RunOptions in_effect = o;
  in_effect.max_steps = s.max_steps;
  in_effect.sensor.p_free = p.p_free;
  in_effect.sensor.p_occ = p.p_occ;
  Json j = echo_fields(in_effect);
  Json sensor;
  sensor["probabilities"] = setup.fixed ? "the model's own (course numbers)" : "--p-free, --p-occ";
  const std::string_view p_occ = option_field<mapping::SensorModelOptions>("--p-occ").key;
  for (const auto &item : j["sensor"].items()) {
    sensor[item.key()] = item.value();
    if (item.key() == p_occ && p.p_robot) sensor["p_robot"] = *p.p_robot;
  }
  j["sensor"] = sensor;
  return j;
}

}  // namespace

std::string summary_json(const RunOptions &o, const RunSummary &s, const Report &report) {
  Json j = report_json(report);
  j["options"] = options_json(o, s);
  return j.dump(2) + "\n";
}

std::string summary_json(const RunOptions &o, const RunSummary &s) { return summary_json(o, s, run_report(o, s)); }

bool trace_every_step(const RunOptions &options) {
  return options.output.trace_steps || !sensing::setup(options.model.kind).reads_lidar();
}

std::string_view pose_trace_columns() { return "step,time_s,true_x_m,true_y_m,true_yaw_rad"; }

std::string trace_header(const std::string &sensor_columns) {
  return std::string(pose_trace_columns()) + ",cell_x,cell_y,action,subcells_updated" + sensor_columns + "\n";
}

void append_pose_trace_values(std::string &csv, std::int64_t step, double time_s, double x_m, double y_m,
                              double yaw_rad) {
  // As "{},{:.3f},{:.4f},{:.4f},{:.4f}" (the same bytes; common/fixed_decimal.hpp).
  common::append_int(csv, step);
  csv += ',';
  common::append_fixed(csv, time_s, 3);
  for (const double v : {x_m, y_m, yaw_rad}) {
    csv += ',';
    common::append_fixed(csv, v, 4);
  }
}

void append_trace_row(std::string &csv, const robot::StepReport &step, double x_m, double y_m,
                      double yaw_rad, const std::string &sensor_values) {
  append_pose_trace_values(csv, step.step, step.sim_time_s, x_m, y_m, yaw_rad);
  csv += ',';
  common::append_int(csv, step.cell.x);
  csv += ',';
  common::append_int(csv, step.cell.y);
  csv += ',';
  csv += robot::to_string(step.action);
  csv += ',';
  common::append_int(csv, step.subcells_updated);
  csv += sensor_values;
  csv += '\n';
}

namespace {

void write_snapshots(OutputDir &out, const RunOptions &options, const RunSummary &summary, const RunFiles &files,
                     const PageFrame &page) {
  const MapTones tones = map_tones(options, *files.model);
  const int count = options.output.snapshots;
  const int digits = std::max(2, static_cast<int>(std::to_string(count).size()));
  const std::vector<std::int64_t> steps = snapshot_steps(summary.steps, count);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const mapping::OccupancyGrid grid = files.history->grid_at(steps[i]);
    const std::vector<mapping::Cell> path = files.history->path_at(steps[i]);
    const MapMarks marks{path, files.goals, {}, files.landmarks};
    const std::string caption = fmt::format("{}, step {}/{}", map_caption(options), steps[i], summary.steps);
    for (const PictureFormat format : options.output.picture_formats) {
      const std::string name = fmt::format("snapshots/{:0{}}.{}", i + 1, digits, to_string(format));
      out.write(name, png_file(grid, tones, marks, caption, format, page));
    }
  }
}

std::size_t subcells_of(const mapping::GridGeometry &g) {
  return static_cast<std::size_t>(g.width_subcells()) * static_cast<std::size_t>(g.height_subcells());
}

bool replay_fits(const mapping::GridGeometry &g) { return subcells_of(g) <= kReplayMaxSubcells; }

void write_replay(OutputDir &out, const RunOptions &options, const RunSummary &summary, const RunFiles &files) {
  if (!options.output.replay || files.history == nullptr || !replay_fits(files.grid->geometry())) return;
  const std::optional<Replay> replay = replay_file(options, summary, files);
  if (!replay) {
    common::print_stderr("warning: replay.html not written: even the final map alone is over {} MiB\n",
                         kReplayMaxBytes >> 20);
    return;
  }
  out.write("replay.html", replay->html);
}

// --plan-to / plan: plan.png (the learned map with the planned path) and plan.csv (its
// sub-cells in order, with their centres in metres).
void write_plan(OutputDir &out, const RunOptions &options, const PlanSummary &plan, const RunFiles &files,
                const PageFrame &page) {
  std::string csv = "index,subcell_x,subcell_y,x_m,y_m\n";
  for (std::size_t i = 0; i < plan.path.size(); ++i) {
    const mapping::Point p = files.grid->centre_of(plan.path[i]);
    fmt::format_to(std::back_inserter(csv), "{},{},{},{:.4f},{:.4f}\n", i, plan.path[i].x, plan.path[i].y, p.x_m, p.y_m);
  }
  MapMarks marks{{}, files.goals, plan.path, files.landmarks};
  const std::string caption = fmt::format("{}, plan to ({},{})", map_caption(options), plan.to.x, plan.to.y);
  for (const PictureFormat format : options.output.picture_formats) {
    out.write(fmt::format("plan.{}", to_string(format)),
              png_file(*files.grid, map_tones(options, *files.model), marks, caption, format, page));
  }
  out.write("plan.csv", csv);
}

}  // namespace

std::vector<NamedInput> run_inputs(const RunOptions &options) {
  return {{"the world", options.world}, {"--robot", options.robot}};
}

bool keeps_history(const RunOptions &options, const mapping::GridGeometry &geometry) {
  if (options.output.replay && !replay_fits(geometry)) {
    common::print_stderr("warning: replay.html not written: the grid has {} sub-cells, a replay at most {} (--no-replay "
                         "leaves it out without this warning)\n", subcells_of(geometry), kReplayMaxSubcells);
  }
  return options.output.snapshots > 0 || (options.output.replay && replay_fits(geometry));
}

std::optional<Replay> replay_file(const RunOptions &options, const RunSummary &summary, const RunFiles &files) {
  ReplayInput input;
  add_history(input, *files.history, summary.steps);
  input.tones = map_tones(options, *files.model);
  add_goal_cells(input, files.goals);
  input.landmarks = files.landmarks;
  input.title = options.world;
  input.caption = map_caption(options);
  input.steps = summary.steps;
  input.reachable_cells = summary.score.reachable_cells;
  // The belief of a maze small enough to keep it at every cell (live_localization.hpp).
  if (summary.localization && !summary.localization->updates.empty() &&
      !summary.localization->updates.front().belief.empty()) {
    for (const LocalizationUpdate &u : summary.localization->updates) {
      std::vector<int> &permille = input.belief_permille.emplace_back();
      for (const double p : u.belief) permille.push_back(static_cast<int>(std::lround(1000.0 * p)));
    }
  }
  input.summary = replay_summary(files.report ? *files.report : run_report(options, summary));
  return replay_html(input);
}

void write_outputs(OutputDir &out, const RunOptions &options, const RunSummary &summary, const RunFiles &files) {
  // What matters most first: after a stop signal the files have a bounded time (output_dir.hpp).
  out.write("summary.json", summary_json(options, summary, files.report ? *files.report : run_report(options, summary)));
  if (files.trace != nullptr) out.commit("trace.csv", *files.trace);
  const auto initial = static_cast<float>(files.model->prior_log_odds());
  out.write("map.pgm", pgm_file(*files.grid, initial));
  out.write("map.yaml", map_yaml(files.grid->geometry(), "map.pgm"));
  const MapTones tones = map_tones(options, *files.model);
  const PageFrame page = run_page(options, files, summary.steps);
  for (const PictureFormat format : options.output.picture_formats) {
    out.write(fmt::format("map.{}", to_string(format)),
              png_file(*files.grid, tones, MapMarks{*files.path, files.goals, {}, files.landmarks}, map_caption(options),
                       format, page));
    out.write(fmt::format("truth.{}", to_string(format)), truth_png_file(options, files, format, page));
  }
  if (options.output.snapshots > 0 && files.history != nullptr) write_snapshots(out, options, summary, files, page);
  write_replay(out, options, summary, files);
  if (summary.plan && summary.plan->found) write_plan(out, options, *summary.plan, files, page);
}

}  // namespace app
