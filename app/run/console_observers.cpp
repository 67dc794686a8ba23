#include "app/run/console_observers.hpp"

#include <string>

#include <fmt/format.h>

namespace app {

void Animation::on_step(const RunStep &step) {
  if (step.arrival != nullptr) {
    const robot::MoveReport &a = *step.arrival;
    animator_.on_step(robot::StepReport{a.step, a.sim_time_s, a.cell, a.heading, robot::Action::rest, 0, a.grid,
                                        a.visits},
                      step.true_pose.x_m, step.true_pose.y_m);
  } else if (step.cell != nullptr) {
    animator_.on_step(*step.cell, step.true_pose.x_m, step.true_pose.y_m);
  }
}

void StepPrompt::on_step(const RunStep &step) {
  if (step.arrival == nullptr || quit_ || !stepping_) return;
  if (prompt_ != nullptr) {
    *prompt_ << fmt::format("-- cell ({},{}), step {}: Enter goes on, q quits -- ", step.arrival->cell.x,
                            step.arrival->cell.y, step.arrival->step)
             << std::flush;
  }
  std::string line;
  if (!std::getline(in_, line)) {
    stepping_ = false;
    return;
  }
  if (line == "q" || line == "quit" || line == "Q") quit_ = true;
}

}  // namespace app
