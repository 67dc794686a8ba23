#include "app/run/run_progress.hpp"

#include "app/run/evaluation.hpp"
#include "app/run/metric/evaluation.hpp"

namespace app {
namespace {

// The reachable free cells of the truth the map has observed, and how many there are.
MetricRunSummary observed_of(const MetresRunStart &metres) {
  MetricRunSummary counted;
  score_metric_map(metres.map, metres.truth, metres.threshold, counted);
  return counted;
}

}  // namespace

void RunProgress::on_start(const RunStart &start) {
  if (start.cell != nullptr) line_.emplace(fd_, count_reachable_cells(start.cell->truth));
  if (start.metres != nullptr) {
    metres_ = start.metres;
    line_.emplace(fd_, static_cast<int>(observed_of(*metres_).reachable_free));
  }
}

void RunProgress::on_step(const RunStep &step) {
  if (!line_) return;
  if (step.arrival != nullptr) line_->update(step.arrival->moves, step.arrival->visits->count(), step.time_s);
  if (step.metres != nullptr) {
    line_->update_metres(step.step, [this] { return observed_of(*metres_).reachable_free_observed; }, step.time_s);
  }
}

void RunObservers::add(RunObserver *observer) {
  if (observer != nullptr) observers_.push_back(observer);
}

void RunObservers::on_start(const RunStart &start) {
  for (RunObserver *o : observers_) o->on_start(start);
}

std::vector<std::uint32_t> *RunObservers::grid_changes() {
  for (RunObserver *o : observers_) {
    if (std::vector<std::uint32_t> *log = o->grid_changes()) return log;
  }
  return nullptr;
}

void RunObservers::on_step(const RunStep &step) {
  for (RunObserver *o : observers_) o->on_step(step);
}

void RunObservers::on_end(const RunEnd &end) {
  for (RunObserver *o : observers_) o->on_end(end);
}

}  // namespace app
