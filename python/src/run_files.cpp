#include "run_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <span>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "app/picture/map_picture.hpp"
#include "app/picture/plain_grid_picture.hpp"
#include "app/report/grid_history.hpp"
#include "app/report/output_dir.hpp"
#include "app/report/outputs.hpp"
#include "app/report/replay.hpp"
#include "app/report/truth_picture.hpp"
#include "app/run/evaluation.hpp"
#include "app/run/option_fields.hpp"
#include "app/run/report.hpp"
#include "app/run/report_keys.hpp"
#include "common/error.hpp"
#include "common/standard_streams.hpp"
#include "mapping/walls.hpp"
#include "maze/world/truth_raster.hpp"

namespace maze_mapper_python {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

app::Report report_of(const std::vector<EntryTuple> &entries) {
  app::Report report;
  for (const auto &[key, text, json] : entries) {
    if (text) report.both(key, *text, Json::parse(json));
    else report.json_only(key, Json::parse(json));
  }
  return report;
}

// The compass point nearest a yaw (0 east, counter-clockwise).
mapping::Heading heading_of(double yaw_rad) {
  const long quarter = std::lround(yaw_rad / (std::numbers::pi / 2.0));
  constexpr mapping::Heading kByQuarter[] = {mapping::Heading::east, mapping::Heading::north, mapping::Heading::west,
                                            mapping::Heading::south};
  return kByQuarter[((quarter % 4) + 4) % 4];
}

// What the pictures of a maze run show: the controller's grid, and the cells the robot's
// centre passed through, in order, with the step and heading of each arrival.
struct MazeRun {
  mapping::OccupancyGrid grid;
  float initial_log_odds = 0.0F;
  std::vector<mapping::Cell> path;
  std::vector<app::GridHistory::Arrival> arrivals;
};

mapping::GridGeometry maze_geometry(const maze::Maze &truth, int subcells) {
  return {truth.width(), truth.height(), subcells, truth.cell_size_m(), {truth.origin_x_m(), truth.origin_y_m()}};
}

// The controller's kept grid on the maze's cells; throws common::InputError when its cells
// are not the maze's.
mapping::OccupancyGrid kept_grid(const py::object &grid, const maze::Maze &truth, float initial_log_odds) {
  const mapping::OccupancyGrid own =
      py::isinstance<PyGrid>(grid) ? grid.cast<const PyGrid &>().grid : grid_from_array(grid, initial_log_odds);
  if (own.width() != truth.width() || own.height() != truth.height()) {
    throw common::InputError(fmt::format("the kept grid is {}x{} cells, the world {}x{}", own.width(), own.height(),
                                         truth.width(), truth.height()));
  }
  mapping::OccupancyGrid placed(maze_geometry(truth, own.k()), initial_log_odds);
  for (std::size_t i = 0; i < own.size(); ++i) placed.at_index(i) = own.at_index(i);
  return placed;
}

mapping::Cell cell_of(const maze::Maze &truth, const PoseTrace::Visit &v) {
  return {static_cast<int>(std::floor((v.x_m - truth.origin_x_m()) / truth.cell_size_m())),
          static_cast<int>(std::floor((v.y_m - truth.origin_y_m()) / truth.cell_size_m()))};
}

// The maze as the run started on it: its start where a supervisor set the robot down before it
// first moved (the course's random start, start_visit), else the file's.
maze::Maze started_maze(const maze::Maze &truth, const std::vector<PoseTrace::Visit> &visits) {
  maze::Maze started = truth;
  if (visits.empty()) return started;
  const PoseTrace::Visit &v = visits[start_visit(visits)];
  const mapping::Cell c = cell_of(truth, v);
  if (c.x >= 0 && c.y >= 0 && c.x < truth.width() && c.y < truth.height()) started.set_start({c.x, c.y}, heading_of(v.yaw_rad));
  return started;
}

// The kept grid (not None), and the cells the robot's centre passed through from the start
// (start_visit) on.
MazeRun maze_run(const maze::Maze &truth, const py::object &grid, std::optional<float> initial_log_odds,
                 const std::vector<PoseTrace::Visit> &visits) {
  const float l0 = initial_log_odds.value_or(
      py::isinstance<PyGrid>(grid) ? grid.cast<const PyGrid &>().initial_log_odds() : 0.0F);
  MazeRun run{kept_grid(grid, truth, l0), l0, {}, {}};
  for (std::size_t k = start_visit(visits); k < visits.size(); ++k) {
    const PoseTrace::Visit &v = visits[k];
    const mapping::Cell c = cell_of(truth, v);
    if (!run.grid.contains(c) || (!run.path.empty() && run.path.back() == c)) continue;
    run.path.push_back(c);
    run.arrivals.push_back({v.step, c, heading_of(v.yaw_rad)});
  }
  return run;
}

std::vector<bool> visited_of(const maze::Maze &truth, const std::vector<mapping::Cell> &path) {
  std::vector<bool> visited(static_cast<std::size_t>(truth.width()) * static_cast<std::size_t>(truth.height()));
  for (const mapping::Cell c : path) visited[static_cast<std::size_t>(c.y * truth.width() + c.x)] = true;
  return visited;
}

// map.png's tones for a grid whose never-observed value is initial_log_odds (the classroom
// model's increments).
app::MapTones tones_of(const MazeRun &run) {
  app::MapTones tones;
  tones.initial_log_odds = run.initial_log_odds;
  return tones;
}

std::string grid_caption(const MazeRun &run) { return fmt::format("the controller's grid, K {}", run.grid.k()); }

std::vector<mapping::Cell> goals_of(const maze::Maze &truth) {
  std::vector<mapping::Cell> goals;
  for (const maze::Cell g : truth.goals()) goals.push_back({g.x, g.y});
  return goals;
}

std::string truth_file(const maze::Maze &truth, const MazeRun &run) {
  const std::vector<bool> visited = visited_of(truth, run.path);
  const auto learned = [&run](maze::Cell c, maze::Side s) {
    return mapping::side_state(run.grid, run.initial_log_odds, {c.x, c.y}, s);
  };
  const app::TruthInput input{&truth, &visited, learned, run.grid.k(), fmt::format("truth: {}", grid_caption(run))};
  return app::truth_picture(input).encode();
}

std::optional<app::Replay> replay_page(const maze::Maze &truth, const std::string &title, const MazeRun &run,
                                       const app::Report &report, std::int64_t steps) {
  app::GridHistory history(run.grid.geometry(), run.initial_log_odds);
  for (const auto &a : run.arrivals) history.arrived(a.step, a.cell, a.heading);
  history.record(steps, run.grid);
  app::ReplayInput input;
  app::add_history(input, history, steps);
  app::add_goal_cells(input, goals_of(truth));
  input.tones = tones_of(run);
  input.landmarks = app::landmark_marks(truth);
  input.title = title;
  input.caption = grid_caption(run);
  input.steps = steps;
  const std::vector<bool> reachable = truth.reachable_from_start();
  input.reachable_cells = static_cast<std::size_t>(std::count(reachable.begin(), reachable.end(), true));
  input.summary = app::replay_summary(report);
  return app::replay_html(input);
}

// map.png and truth.png of a maze run.
void write_maze_pictures(app::OutputDir &out, const maze::Maze &truth, const MazeRun &run) {
  const app::MapMarks marks{std::span<const mapping::Cell>(run.path), goals_of(truth), {}, app::landmark_marks(truth)};
  out.write("map.png", app::png_file(run.grid, tones_of(run), marks, grid_caption(run)));
  out.write("truth.png", truth_file(truth, run));
}

// replay.html of a maze run, or a warning when even its final map is too large.
void write_maze_replay(app::OutputDir &out, const maze::Maze &truth, const std::string &title, const MazeRun &run,
                       const app::Report &report, std::int64_t steps) {
  if (const std::optional<app::Replay> replay = replay_page(truth, title, run, report, steps)) {
    out.write("replay.html", replay->html);
  } else {
    common::print_stderr("warning: replay.html not written: even the final map alone is over {} MiB\n",
               app::kReplayMaxBytes >> 20);
  }
}

}  // namespace

void RunFiles::write_metres_pictures(const std::vector<PoseTrace::Visit> &visits, const MetresRunMarks &marks) {
  if (kept_map() != nullptr) out_.write("map.png", kept_map_png(*kept_map(), visits, marks));
  out_.write("truth.png", world_truth_png(*marks.world, visits, marks.body_radius_m));
}

void RunFiles::write_metres_replay(const std::vector<PoseTrace::Visit> &visits, const MetresRunMarks &marks) {
  if (visits.empty()) {
    common::print_stderr("note: replay.html not written: the controller took no step\n");
    return;
  }
  const PoseTrace::Visit &last = visits.back();
  replay_.finish({last.step, {last.x_m, last.y_m}, last.yaw_rad, last.placed}, last.time_s);
  if (const std::optional<app::Replay> replay = app::replay_html(metres_replay_input(replay_, kept_map(), visits, marks))) {
    out_.write("replay.html", replay->html);
  } else {
    common::print_stderr("warning: replay.html not written: even the final map alone is over {} MiB\n",
               app::kReplayMaxBytes >> 20);
  }
}

PoseTrace::PoseTrace(const std::string &dir) : file_((fs::path(dir) / "trace.csv").string()) {
  file_.write(std::string(app::pose_trace_columns()) + "\n");
}

bool PoseTrace::record(std::int64_t step, double time_s, const maze::sim::Pose &pose) {
  if (!visits_.empty() && visits_.back().step == step) return false;  // a step that passed no time
  row_.clear();
  app::append_pose_trace_values(row_, step, time_s, pose.x_m, pose.y_m, pose.yaw_rad);
  row_ += '\n';
  file_.write(row_);
  visits_.push_back({step, time_s, pose.x_m, pose.y_m, pose.yaw_rad, placed_next_});
  placed_next_ = false;
  return true;
}

std::size_t start_visit(const std::vector<PoseTrace::Visit> &visits) {
  constexpr double kMoved_m = 1e-3;
  std::size_t start = 0;
  for (std::size_t k = 1; k < visits.size(); ++k) {
    if (visits[k].placed) start = k;
    else if (std::hypot(visits[k].x_m - visits[k - 1].x_m, visits[k].y_m - visits[k - 1].y_m) > kMoved_m) break;
  }
  return start;
}

std::string format_entries(const std::vector<EntryTuple> &entries) { return app::format_summary(report_of(entries)); }

namespace {

std::vector<app::NamedInput> named_inputs(const std::vector<std::pair<std::string, std::string>> &inputs) {
  std::vector<app::NamedInput> named;
  for (const auto &[what, path] : inputs) named.push_back({what, path});
  return named;
}

}  // namespace

RunFiles::RunFiles(std::string dir, const std::vector<std::pair<std::string, std::string>> &inputs)
    : out_(std::move(dir), named_inputs(inputs), kControllerFiles) {}

void RunFiles::keep_text(const std::string &name, std::string text) {
  if (std::find(kControllerFiles.begin(), kControllerFiles.end(), name) == kControllerFiles.end()) {
    throw py::value_error(fmt::format("{} is not a file of the controller's (controller.log, controller_lines.csv)", name));
  }
  std::erase_if(texts_, [&](const auto &kept) { return kept.first == name; });
  texts_.emplace_back(name, std::move(text));
}

PoseTrace &RunFiles::trace() {
  if (!trace_) trace_.emplace(out_.path());
  return *trace_;
}

template <typename Record>
void RunFiles::recording(Record record) {
  if (failed_) return;
  try {
    record();
  } catch (const common::RuntimeFailure &) {  // common::NoSpaceError
    failed_ = std::current_exception();
    trace_.reset();
  } catch (const common::InputError &) {  // "cannot write DIR/trace.csv: Permission denied"
    failed_ = std::current_exception();
    trace_.reset();
  }
}

void RunFiles::on_step(const app::RunStep &step) {
  recording([&] {
    if (!trace().record(step.step, step.time_s, step.true_pose)) return;
    const PoseTrace::Visit &v = trace_->visits().back();
    replay_.on_step({v.step, {v.x_m, v.y_m}, v.yaw_rad, v.placed}, v.time_s);
  });
}

void RunFiles::mark_placed() {
  recording([&] { trace().mark_placed(); });
}

void RunFiles::keep_map(py::object kept) {
  kept_map_ = &kept.cast<const KeptMap &>();
  replay_.keep(kept_map_->view());
  kept_ = std::move(kept);
}

void RunFiles::finish(const std::vector<EntryTuple> &entries, const maze::World *world, const py::object &grid,
                      std::optional<float> initial_log_odds) {
  if (failed_) std::rethrow_exception(failed_);
  // A maze whose controller kept its 4D grid is drawn on its cells; any other run in metres.
  const maze::World *maze = world != nullptr && world->on_lattice() && !grid.is_none() ? world : nullptr;
  const bool metres = world != nullptr && maze == nullptr;
  const app::Report report = report_of(entries);
  const std::vector<PoseTrace::Visit> none;
  const std::vector<PoseTrace::Visit> &visits = trace_ ? trace_->visits() : none;
  // What matters most first, as `run --out` writes (after a stop signal the files have a
  // bounded time: app/report/output_dir.hpp): summary.json, trace.csv, the pictures, replay.html.
  out_.write("summary.json", app::report_json(report).dump(2) + "\n");
  if (trace_) out_.commit("trace.csv", trace_->file());
  const std::optional<maze::Maze> started =
      maze != nullptr ? std::optional<maze::Maze>(started_maze(maze->maze(), visits)) : std::nullopt;
  const std::optional<MazeRun> run =
      started ? std::optional<MazeRun>(maze_run(*started, grid, initial_log_odds, visits)) : std::nullopt;
  const MetresRunMarks marks{world, body_radius_m_, app::replay_summary(report)};
  if (run) write_maze_pictures(out_, *started, *run);
  if (metres) write_metres_pictures(visits, marks);
  if (run) write_maze_replay(out_, *started, maze->file, *run, report, visits.empty() ? 0 : visits.back().step);
  if (metres) write_metres_replay(visits, marks);
  for (const auto &[name, text] : texts_) out_.write(name, text);
  out_.finish();
}

void bind_run_files(py::module_ &m) {
  py::module_ keys = m.def_submodule("report_key", "The summary keys every report spells the same (summary.json, batch "
                                                     "columns, the grader's table).");
  keys.attr("reachable") = std::string(app::report_key::reachable);
  keys.attr("coverage") = std::string(app::report_key::coverage);
  keys.attr("wall_accuracy") = std::string(app::report_key::wall_accuracy);
  keys.attr("cell_accuracy") = std::string(app::report_key::cell_accuracy);
  m.def("option_help", [](const std::string &flag) { return app::option_help(flag); }, py::arg("flag"),
        "The help line of a run's option (\"--robot\", \"--seed\", ...): the same words as maze_mapper run, room and "
        "mms; the runner's --help shows them.");
  m.def("format_entries", &format_entries, py::arg("entries"),
        "The summary block of report entries (key, printed value or None, JSON text), as every run prints it.");
  py::class_<RunFiles>(m, "RunFiles",
                       "The files of a Python controller's run (--out DIR): trace.csv as it goes, the rest at its end.")
      .def(py::init<std::string, const std::vector<std::pair<std::string, std::string>> &>(), py::arg("dir"),
           py::arg("inputs"))
      .def(
          "finish",
          [](RunFiles &files, const std::vector<EntryTuple> &entries, const py::object &world, const py::object &grid,
             std::optional<float> initial_log_odds) {
            files.finish(entries, py::isinstance<maze::World>(world) ? &world.cast<const maze::World &>() : nullptr,
                         grid, initial_log_odds);
          },
          py::arg("entries"), py::arg("world"), py::arg("grid"), py::arg("initial_log_odds"))
      .def("keep_text", &RunFiles::keep_text, py::arg("name"), py::arg("text"),
           "A file of the controller's own (controller.log, controller_lines.csv), written at finish().")
      .def("keep_map", &RunFiles::keep_map, py::arg("kept"),
           "The controller's metric map (a KeptMap) from now on: map.png and the replay's map of a run drawn in metres.");
}

}  // namespace maze_mapper_python
