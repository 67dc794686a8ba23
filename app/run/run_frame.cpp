#include "app/run/run_frame.hpp"

#include "common/atomic_file.hpp"
#include "common/interrupt.hpp"

namespace app {

RunFrame::RunFrame(const maze::World &world, const maze::sim::RobotProfile &profile,
                   const maze::sim::SimulationOptions &simulation, RunObserver *files, int progress_fd)
    : simulation_(world, profile, simulation) {
  observers_.add(files);
  if (progress_fd >= 0) observers_.add(&progress_.emplace(progress_fd));
}

void RunFrame::end(const RunEnd &end, std::ostream &out, const std::function<void()> &print_end) {
  const bool stopped_by_signal = common::interrupted();
  if (stopped_by_signal) {
    if (progress_) progress_->on_end(end);
    print_end();
    out << std::flush;
  }
  try {
    observers_.on_end(end);
  } catch (const common::NoSpaceError &) {
    no_space_ = std::current_exception();
  }
  if (!stopped_by_signal) print_end();
}

void RunFrame::close(std::ostream &out, std::exception_ptr *keep) {
  if (!no_space_) return;
  if (keep != nullptr) {
    *keep = no_space_;
    return;
  }
  out << std::flush;
  std::rethrow_exception(no_space_);
}

}  // namespace app
