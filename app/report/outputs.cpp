#include "app/report/outputs.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/run/run_report.hpp"
#include "app/report/truth_picture.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/fixed_decimal.hpp"
#include "mapping/walls.hpp"
#include "sensing/setups.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail_out(const std::string &dir, const std::string &reason) {
  throw common::InputError(fmt::format("--out {}: {}", dir, reason));
}

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
  return fmt::format("model {}, K {}", sensing::to_string(options.model.kind), options.subcells);
}

std::string png_file(const mapping::OccupancyGrid &grid, const MapTones &tones, const MapMarks &marks,
                     const std::string &caption, PictureFormat format) {
  return map_picture(grid, tones, marks, caption, format).encode();
}

std::string truth_png_file(const RunOptions &options, const RunFiles &files, PictureFormat format) {
  const std::vector<bool> visited = visited_cells(*files.visits);
  const TruthInput input{files.truth, &visited, files.learned, options.subcells,
                         fmt::format("truth: {}", map_caption(options))};
  return truth_picture(input, format).encode();
}

namespace {

using Json = nlohmann::ordered_json;

template <typename T>
Json or_null(const std::optional<T> &value) {
  return value ? Json(*value) : Json(nullptr);
}

Json cell_json(mapping::Cell c) { return Json::array({c.x, c.y}); }

// --cell-size, --start (X,Y, pos:N or random), --goal as given (null when not).
Json world_overrides_json(const maze::WorldOverrides &w) {
  const auto cell = [](maze::Cell c) { return Json::array({c.x, c.y}); };
  Json j;
  j["cell_size_m"] = or_null(w.cell_size_m);
  j["start"] = nullptr;
  if (w.start) {
    j["start"] = cell(*w.start);
    j["start"].push_back(std::string(maze::to_string(w.start_heading)));
  }
  j["start_position"] = or_null(w.start_position);  // --start pos:N
  j["random_start"] = w.random_start;               // --start random (by the seed)
  j["goals"] = nullptr;
  if (w.goals) {
    j["goals"] = Json::array();
    for (const maze::Cell g : *w.goals) j["goals"].push_back(cell(g));
  }
  return j;
}

// The sensor model as the run used it: p_free and p_occ are the set-up's own numbers where it
// marks with the course's (pie, bump, depth: "probabilities" says so), else --p-free/--p-occ.
Json sensor_json(const mapping::SensorModelOptions &s, const sensing::SetUp &setup) {
  const sensing::MarkProbabilities p = sensing::probabilities_in_effect(setup, s);
  Json j;
  j["probabilities"] = setup.fixed ? "the model's own (course numbers)" : "--p-free, --p-occ";
  j["p_free"] = p.p_free;
  j["p_occ"] = p.p_occ;
  if (p.p_robot) j["p_robot"] = *p.p_robot;
  j["prior"] = s.prior;
  j["log_base"] = std::string(mapping::to_string(s.base));
  j["clamp"] = s.clamp ? Json::array({s.clamp->min, s.clamp->max}) : Json(nullptr);
  return j;
}

Json model_json(const sensing::ModelOptions &m) {
  Json j;
  j["kind"] = std::string(sensing::to_string(m.kind));
  j["wall_margin"] = m.wall_margin;
  j["hit_depth"] = m.hit_depth;
  j["ignore_no_return"] = m.ignore_no_return;
  return j;
}

Json range_model_json(const sensing::RangeModelOptions &r) {
  Json j;
  j["pie_half_angle_rad"] = r.pie_half_angle_rad;
  j["pie_contact_m"] = r.pie_contact_m;
  j["pie_usable_fraction"] = r.pie_usable_fraction;
  return j;
}

// --seed, --noise (null: the robot's own) and the faults.
Json simulation_json(const maze::sim::SimulationOptions &s) {
  Json j;
  j["seed"] = s.seed;
  j["noise"] = or_null(s.noise);
  j["dropout"] = s.dropout;
  j["spikes"] = s.spikes;
  j["stuck_bumper"] = s.stuck_bumper.empty() ? Json(nullptr) : Json(s.stuck_bumper);
  j["wheel_slip"] = s.wheel_slip;
  return j;
}

Json plan_options_json(const PlanOptions &p) {
  Json j;
  j["from"] = p.from ? cell_json(*p.from) : Json(nullptr);
  j["to"] = p.to ? cell_json(*p.to) : Json(nullptr);
  j["dilate"] = p.wavefront.dilate;
  j["speed_run"] = p.speed_run;
  return j;
}

Json output_json(const OutputOptions &o) {
  Json j;
  j["out"] = o.out_dir;
  j["ascii"] = o.ascii;
  j["unknown"] = o.unknown ? Json(std::string(1, *o.unknown)) : Json(nullptr);
  j["quiet"] = o.quiet;
  j["color"] = o.color;
  j["animate"] = o.animate;
  j["fps"] = o.fps;
  j["speed"] = o.speed;
  j["step"] = o.step;
  j["trace"] = o.trace;
  j["snapshots"] = o.snapshots;
  j["replay"] = o.replay;
  j["subcell_columns"] = or_null(o.subcell_columns);
  return j;
}

// Every option in effect, one object a concern as RunOptions holds them.
Json options_json(const RunOptions &o, const RunSummary &s) {
  Json j;
  j["world"] = o.world;
  j["world_overrides"] = world_overrides_json(o.world_overrides);
  j["subcells"] = o.subcells;
  j["strategy"] = std::string(explore::to_string(o.strategy));
  j["robot"] = o.robot;
  j["threshold"] = or_null(o.threshold);
  j["max_steps"] = s.max_steps;
  j["model"] = model_json(o.model);
  j["sensor"] = sensor_json(o.sensor, sensing::setup(o.model.kind));
  j["range_model"] = range_model_json(o.range_model);
  j["simulation"] = simulation_json(o.simulation);
  j["plan"] = plan_options_json(o.plan);
  j["output"] = output_json(o.output);
  return j;
}

}  // namespace

std::string summary_json(const RunOptions &o, const RunSummary &s) {
  Json j = report_json(RunReport(o, s));
  j["options"] = options_json(o, s);
  return j.dump(2) + "\n";
}

bool trace_every_step(const RunOptions &options) {
  return options.output.trace_steps || !sensing::setup(options.model.kind).reads_lidar();
}

std::string trace_header(const std::string &sensor_columns) {
  return "step,time_s,true_x_m,true_y_m,true_yaw_rad,cell_x,cell_y,action,subcells_updated" + sensor_columns + "\n";
}

void append_trace_row(std::string &csv, const robot::StepReport &step, double x_m, double y_m,
                      double yaw_rad, const std::string &sensor_values) {
  // As "{},{:.3f},{:.4f},{:.4f},{:.4f},{},{},{},{}{}\n" (the same bytes; common/fixed_decimal.hpp).
  common::append_int(csv, step.step);
  csv += ',';
  common::append_fixed(csv, step.sim_time_s, 3);
  for (const double v : {x_m, y_m, yaw_rad}) {
    csv += ',';
    common::append_fixed(csv, v, 4);
  }
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

void write_snapshots(const fs::path &dir, const RunOptions &options, const RunSummary &summary, const RunFiles &files,
                     std::vector<std::string> &written) {
  std::error_code ec;
  fs::create_directory(dir, ec);
  if (ec) fail_out(options.output.out_dir, fmt::format("cannot create snapshots/: {}", ec.message()));
  const MapTones tones = map_tones(options, *files.model);
  const int count = options.output.snapshots;
  const int digits = std::max(2, static_cast<int>(std::to_string(count).size()));
  const std::vector<std::int64_t> steps = snapshot_steps(summary.steps, count);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const mapping::OccupancyGrid grid = files.history->grid_at(steps[i]);
    const MapMarks marks{files.history->path_at(steps[i]), files.goals, {}, files.landmarks};
    const std::string caption = fmt::format("{}, step {}/{}", map_caption(options), steps[i], summary.steps);
    for (const PictureFormat format : options.output.picture_formats) {
      const std::string name = fmt::format("{:0{}}.{}", i + 1, digits, to_string(format));
      common::write_file_atomically((dir / name).string(), png_file(grid, tones, marks, caption, format));
      written.push_back("snapshots/" + name);
    }
  }
}

std::size_t subcells_of(const mapping::GridGeometry &g) {
  return static_cast<std::size_t>(g.width_subcells()) * static_cast<std::size_t>(g.height_subcells());
}

bool replay_fits(const mapping::GridGeometry &g) { return subcells_of(g) <= kReplayMaxSubcells; }

void write_replay(const fs::path &dir, const RunOptions &options, const RunSummary &summary, const RunFiles &files,
                  std::vector<std::string> &written) {
  if (!options.output.replay || files.history == nullptr || !replay_fits(files.grid->geometry())) return;
  const std::optional<Replay> replay = replay_file(options, summary, files);
  if (!replay) {
    fmt::print(stderr, "warning: replay.html not written: even the final map alone is over {} MiB\n",
               kReplayMaxBytes >> 20);
    return;
  }
  common::write_file_atomically((dir / "replay.html").string(), replay->html);
  written.push_back("replay.html");
}

// --plan-to / plan: plan.png (the learned map with the planned path) and plan.csv (its
// sub-cells in order, with their centres in metres).
void write_plan(const fs::path &dir, const RunOptions &options, const PlanSummary &plan, const RunFiles &files,
                std::vector<std::string> &written) {
  std::string csv = "index,subcell_x,subcell_y,x_m,y_m\n";
  for (std::size_t i = 0; i < plan.path.size(); ++i) {
    const mapping::Point p = files.grid->centre_of(plan.path[i]);
    fmt::format_to(std::back_inserter(csv), "{},{},{},{:.4f},{:.4f}\n", i, plan.path[i].x, plan.path[i].y, p.x_m, p.y_m);
  }
  MapMarks marks{{}, files.goals, plan.path, files.landmarks};
  const std::string caption = fmt::format("{}, plan to ({},{})", map_caption(options), plan.to.x, plan.to.y);
  for (const PictureFormat format : options.output.picture_formats) {
    const std::string name = fmt::format("plan.{}", to_string(format));
    common::write_file_atomically((dir / name).string(),
                                  png_file(*files.grid, map_tones(options, *files.model), marks, caption, format));
    written.push_back(name);
  }
  common::write_file_atomically((dir / "plan.csv").string(), csv);
  written.emplace_back("plan.csv");
}

}  // namespace

std::string wrote_line(const std::string &dir, const std::vector<std::string> &written, std::size_t first_snapshot,
                       std::size_t snapshot_files) {
  std::vector<std::string> names(written.begin(), written.begin() + static_cast<std::ptrdiff_t>(first_snapshot));
  if (snapshot_files > 0) {
    names.push_back(fmt::format("snapshots/ ({} files, {} to {})", snapshot_files,
                                written[first_snapshot].substr(10), written[first_snapshot + snapshot_files - 1].substr(10)));
  }
  names.insert(names.end(), written.begin() + static_cast<std::ptrdiff_t>(first_snapshot + snapshot_files), written.end());
  std::string line = "wrote " + (fs::path(dir) / "").string() + ":";
  for (std::size_t i = 0; i < names.size(); ++i) line += (i == 0 ? " " : ", ") + names[i];
  return line;
}

bool keeps_history(const RunOptions &options, const mapping::GridGeometry &geometry) {
  if (options.output.replay && !replay_fits(geometry)) {
    fmt::print(stderr, "warning: replay.html not written: the grid has {} sub-cells, a replay at most {} (--no-replay "
               "leaves it out without this warning)\n", subcells_of(geometry), kReplayMaxSubcells);
  }
  return options.output.snapshots > 0 || (options.output.replay && replay_fits(geometry));
}

std::optional<Replay> replay_file(const RunOptions &options, const RunSummary &summary, const RunFiles &files) {
  ReplayInput input;
  input.history = files.history;
  input.tones = map_tones(options, *files.model);
  input.goals = files.goals;
  input.landmarks = files.landmarks;
  input.title = options.world;
  input.caption = map_caption(options);
  input.steps = summary.steps;
  input.reachable_cells = summary.score.reachable_cells;
  input.summary = summary_pairs(RunReport(options, summary));
  return replay_html(input);
}

void write_outputs(const std::string &dir, const RunOptions &options, const RunSummary &summary,
                   const RunFiles &files) {
  const fs::path d(dir);
  std::vector<std::string> written{"map.pgm", "map.yaml"};
  const auto initial = static_cast<float>(files.model->prior_log_odds());
  common::write_file_atomically((d / "map.pgm").string(), pgm_file(*files.grid, initial));
  common::write_file_atomically((d / "map.yaml").string(), map_yaml(files.grid->geometry(), "map.pgm"));
  const MapTones tones = map_tones(options, *files.model);
  for (const PictureFormat format : options.output.picture_formats) {
    const std::string map = fmt::format("map.{}", to_string(format));
    const std::string truth = fmt::format("truth.{}", to_string(format));
    common::write_file_atomically(
        (d / map).string(),
        png_file(*files.grid, tones, MapMarks{*files.path, files.goals, {}, files.landmarks}, map_caption(options), format));
    common::write_file_atomically((d / truth).string(), truth_png_file(options, files, format));
    written.push_back(map);
    written.push_back(truth);
  }
  common::write_file_atomically((d / "summary.json").string(), summary_json(options, summary));
  written.emplace_back("summary.json");
  if (files.trace != nullptr) {
    files.trace->commit();
    written.emplace_back("trace.csv");
  }
  const std::size_t before_snapshots = written.size();
  if (options.output.snapshots > 0 && files.history != nullptr) {
    write_snapshots(d / "snapshots", options, summary, files, written);
  }
  const std::size_t snapshot_files = written.size() - before_snapshots;
  write_replay(d, options, summary, files, written);
  if (summary.plan && summary.plan->found) write_plan(d, options, *summary.plan, files, written);
  remove_stale_outputs(dir, written);
  fmt::print(stderr, "{}\n", wrote_line(dir, written, before_snapshots, snapshot_files));
}

}  // namespace app
