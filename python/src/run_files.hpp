#pragma once
// The files of a Python controller's run (python3 -m maze_mapper.run --out DIR), written by the
// program's own writers (app/report/): the directory prepared and checked against the run's
// inputs as `run --out` does, trace.csv a row every control step as the run goes, and at the end
// summary.json (the runner's report, the same Report renderer as every run's), and where the
// world is a maze truth.png, replay.html and, when the controller kept a grid, map.png.

#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "common/atomic_file.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/world/world.hpp"

namespace maze_mapper_python {

// trace.csv as the run goes: app/report/outputs.hpp's pose columns, a row after every control
// step (its last basic step and simulated time, the true pose). Keeps the positions for the
// pictures (x, y: 16 bytes a step).
class PoseTrace {
 public:
  // Opens DIR/trace.csv's temporary and writes the header.
  explicit PoseTrace(const std::string &dir);

  void record(std::int64_t step, double time_s, const maze::sim::Pose &pose);
  // Renames the temporary over trace.csv.
  void commit() { file_.commit(); }

  struct Visit {
    std::int64_t step;
    double x_m;
    double y_m;
    double yaw_rad;
  };
  const std::vector<Visit> &visits() const { return visits_; }

 private:
  common::OutputFile file_;
  std::string row_;  // one row (reused)
  std::vector<Visit> visits_;
};

// A report entry as the runner builds it: key, printed value (none: summary.json only), and
// the JSON value as JSON text.
using EntryTuple = std::tuple<std::string, std::optional<std::string>, std::string>;

// "key: value" lines of the entries (app/run/report.hpp's format_summary).
std::string format_entries(const std::vector<EntryTuple> &entries);

class RunFiles {
 public:
  // Prepares DIR (app/report/output_dir.hpp: created when missing, a dangling link refused
  // and left as it is) and refuses it when a file the run may write there is one of
  // `inputs` ((what, path) pairs, "the world", "the controller"). Throws common::InputError.
  RunFiles(std::string dir, const std::vector<std::pair<std::string, std::string>> &inputs);

  // The trace the simulation writes a row to after every control step (opened on first use).
  PoseTrace &trace();

  // Writes every file and removes what an earlier run left in DIR that this one did not
  // write; names them on stderr ("wrote DIR/: ..."). `world`: the world read (null: the
  // course's empty floor); `grid`: the grid the controller kept (an OccupancyGrid or an array;
  // None: none), `initial_log_odds` its never-observed value. A maze's pictures mark the cells
  // the robot's centre passed through as visited; an arena's truth.png draws its solids,
  // landmarks and the path. Throws common::InputError when the kept grid's cells are not the
  // maze's.
  void finish(const std::vector<EntryTuple> &entries, const maze::World *world, const py::object &grid,
              std::optional<float> initial_log_odds);

  // The names the run may write in DIR.
  static const std::vector<std::string> &names();

 private:
  std::string dir_;
  std::optional<PoseTrace> trace_;
};

}  // namespace maze_mapper_python
