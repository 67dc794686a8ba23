// The course of a room run (app/run/metric/coverage_clock.hpp).

#include "app/run/metric/coverage_clock.hpp"

#include <cmath>

namespace app {

CoverageClock::CoverageClock(const sensing::MetricMap &map, const maze::TruthRaster &truth, maze::sim::Pose start)
    : map_(map), truth_(truth), last_(start) {
  gather();
}

void CoverageClock::gather() {
  unobserved_.clear();
  for (std::size_t n = 0; n < map_.size() && n < truth_.reachable.size(); ++n) {
    if (truth_.reachable[n] != 0 && map_.unobserved_at(n)) unobserved_.push_back(n);
  }
  back_to_prior_ = map_.back_to_prior();
}

void CoverageClock::on_step(std::int64_t step, maze::sim::Pose pose) {
  path_length_m_ += std::hypot(pose.x_m - last_.x_m, pose.y_m - last_.y_m);
  last_ = pose;
  const std::size_t before = unobserved_.size();
  if (map_.back_to_prior() != back_to_prior_) {
    gather();
    if (unobserved_.size() != before) coverage_final_step_ = step;  // (fell, or rose and fell)
  }
  std::size_t kept = 0;
  for (const std::size_t n : unobserved_) {
    if (map_.unobserved_at(n)) unobserved_[kept++] = n;
  }
  unobserved_.resize(kept);
  if (kept != before) coverage_final_step_ = step;
}

}  // namespace app
