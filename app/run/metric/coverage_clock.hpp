#pragma once
// What a room run's summary says of its course, whatever the strategy: the length of the path
// the robot drove (its true centre, step to step) and the control step at which the observed
// share of the reachable free area reached its final value (the step the last reachable free
// cell the run observed was first observed; 0 when none was).
//
// A cell whose evidence cancels out to l(prior) again is unobserved again (MetricMap::
// back_to_prior), and coverage falls: the step is the last at which it rose.
//
// Cost: each step, one look at the reachable free cells still unobserved (the list shrinks as
// they are observed); after a step that left a cell at l(prior) again, one look at every
// reachable free cell. (The bump and depth set-ups' homework update, base 10, is not counted
// there: its increments never cancel out exactly.)

#include <cstddef>
#include <cstdint>
#include <vector>

#include "maze/sim/sensors.hpp"
#include "maze/world/truth_raster.hpp"
#include "sensing/metric/map.hpp"

namespace app {

class CoverageClock {
 public:
  // The map and the truth on its grid (truth.reachable); the robot's pose at the start.
  CoverageClock(const sensing::MetricMap &map, const maze::TruthRaster &truth, maze::sim::Pose start);
  // After control step `step`, the robot at `pose`.
  void on_step(std::int64_t step, maze::sim::Pose pose);
  double path_length_m() const { return path_length_m_; }
  std::int64_t coverage_final_step() const { return coverage_final_step_; }

 private:
  const sensing::MetricMap &map_;
  const maze::TruthRaster &truth_;
  std::vector<std::size_t> unobserved_;  // reachable free cells not yet observed
  std::size_t back_to_prior_ = 0;        // the map's count when unobserved_ was last gathered
  void gather();
  maze::sim::Pose last_;
  double path_length_m_ = 0.0;
  std::int64_t coverage_final_step_ = 0;
};

}  // namespace app
