#pragma once
// trace.csv of a Python controller's run (python3 -m maze_mapper.run --out), as the run goes.

#include <cstdint>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "maze/sim/sensors.hpp"

namespace maze_mapper_python {

// trace.csv as the run goes: app/report/outputs.hpp's pose columns, a row after every control
// step (its last basic step and simulated time, the true pose). Keeps the poses for the
// pictures and the replay (40 bytes a step).
class PoseTrace {
 public:
  // Opens DIR/trace.csv's temporary and writes the header.
  explicit PoseTrace(const std::string &dir);

  // False when `step` is the last row's (a step that passed no time): no row.
  bool record(std::int64_t step, double time_s, const maze::sim::Pose &pose);
  // A supervisor set the robot down since the last row (a teleport, simulationReset): the next
  // row's pose is `placed`, not driven to.
  void mark_placed() { placed_next_ = true; }
  // trace.csv's temporary, for the output folder to commit (app::OutputDir::commit).
  common::OutputFile &file() { return file_; }

  struct Visit {
    std::int64_t step;
    double time_s;
    double x_m;
    double y_m;
    double yaw_rad;
    bool placed;  // set down by a supervisor: the pictures draw no path to it
  };
  const std::vector<Visit> &visits() const { return visits_; }

 private:
  common::OutputFile file_;
  std::string row_;  // one row (reused)
  std::vector<Visit> visits_;
  bool placed_next_ = false;
};

// The visit the run starts from: the last one a supervisor set the robot down on before it
// first moved (the course's random start), else the first; 0 for none.
std::size_t start_visit(const std::vector<PoseTrace::Visit> &visits);

}  // namespace maze_mapper_python
