#pragma once
// The files of a Python controller's run (python3 -m maze_mapper.run --out DIR), written by the
// one writer of every run's files (app/report/output_dir.hpp's OutputDir): the directory
// prepared and checked against the run's inputs as `run --out` does, each file atomic, an
// earlier run's files removed, one `wrote` line; trace.csv a row every control step as the run
// goes, and at the end summary.json (the runner's report, the same Report renderer as every
// run's), truth.png and replay.html, and map.png of the map the controller kept. A maze whose
// controller kept its 4D grid is drawn as `run --out` draws one (its truth.png scores the
// grid's walls); any other run in metres (python/src/metres_files.hpp): the world, the path,
// and the metric map kept (maze_mapper.keep_map), if any.

#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "metres_files.hpp"
#include "bindings.hpp"
#include "kept_map.hpp"
#include "pose_trace.hpp"
#include "app/report/output_dir.hpp"
#include "app/run/run_observer.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/world/world.hpp"

namespace maze_mapper_python {

// A report entry as the runner builds it: key, printed value (none: summary.json only), and
// the JSON value as JSON text.
using EntryTuple = std::tuple<std::string, std::optional<std::string>, std::string>;

// "key: value" lines of the entries (app/run/report.hpp's format_summary).
std::string format_entries(const std::vector<EntryTuple> &entries);

// The files observe the run's steps, as every kind of run's do (app/run/run_frame.hpp); a
// Python run's start is its first step, and its end finish(), which brings the runner's
// report.
// The names a Python run writes beyond every run's (app::run_output_names): the controller's
// standard output and error as printed (controller.log) and, a row a line of it, the step it
// was printed at and the robot's true pose then (controller_lines.csv).
inline const std::vector<std::string> kControllerFiles = {"controller.log", "controller_lines.csv"};

class RunFiles final : public app::RunObserver {
 public:
  // Prepares DIR (app::OutputDir: created when missing, a dangling link refused and left as
  // it is) and refuses it when a file the run may write there is one of `inputs` ((what,
  // path) pairs, "the world", "the controller"). Throws common::InputError.
  RunFiles(std::string dir, const std::vector<std::pair<std::string, std::string>> &inputs);

  void on_start(const app::RunStart &) override {}
  // After every control step: its row of trace.csv (opened on first use) and, when due, a
  // frame of the replay in metres. A write that fails (a full disk) is kept for finish(), never
  // raised into the controller's step: the run goes on, unrecorded from then on.
  void on_step(const app::RunStep &step) override;
  void on_end(const app::RunEnd &) override {}
  // A supervisor set the robot down (a teleport, simulationReset): no path is drawn to its
  // next pose.
  void mark_placed();
  // The metric map the controller keeps from now on (a KeptMap: maze_mapper.keep_map).
  void keep_map(py::object kept);
  // A file of the controller's own (one of kControllerFiles: what it printed), written by
  // finish() after the run's core files; a name given twice keeps the last text.
  void keep_text(const std::string &name, std::string text);
  // The robot's body radius, for the replay's robot and goal marks.
  void set_body_radius(double radius_m) { body_radius_m_ = radius_m; }

  // Writes every file and removes what an earlier run left in DIR that this one did not
  // write; names them on stderr ("wrote DIR/: ..."). `world`: the world read (null: no
  // pictures); `grid`: the 4D grid the controller kept on a maze (an OccupancyGrid or an
  // array; None: none), `initial_log_odds` its never-observed value. A maze's grid pictures
  // mark the cells the robot's centre passed through as visited; else truth.png draws the
  // world's solids, landmarks and the path, map.png the kept metric map (keep_map) and
  // replay.html both.
  // Throws common::InputError when the kept grid's cells are not the maze's, or the kept
  // map's array changed shape; a write kept from the run (common::NoSpaceError for a full disk)
  // is thrown first, and then no file is written.
  void finish(const std::vector<EntryTuple> &entries, const maze::World *world, const py::object &grid,
              std::optional<float> initial_log_odds);

 private:
  PoseTrace &trace();
  // Runs `record` (a trace write); a failure is kept in failed_ and the trace dropped.
  template <typename Record>
  void recording(Record record);
  // truth.png, map.png (a kept metric map) and replay.html of a run drawn in metres.
  void write_metres_pictures(const std::vector<PoseTrace::Visit> &visits, const MetresRunMarks &marks);
  void write_metres_replay(const std::vector<PoseTrace::Visit> &visits, const MetresRunMarks &marks);
  const KeptMap *kept_map() const { return kept_map_; }

  app::OutputDir out_;
  std::optional<PoseTrace> trace_;
  py::object kept_ = py::none();  // a KeptMap
  const KeptMap *kept_map_ = nullptr;  // kept_'s (cast once: the steps read it)
  app::MapFrames replay_{app::PathPoses::every_step};
  std::vector<std::pair<std::string, std::string>> texts_;  // keep_text's, in order
  double body_radius_m_ = 0.0;
  std::exception_ptr failed_;  // the first write that failed during the run
};

}  // namespace maze_mapper_python
