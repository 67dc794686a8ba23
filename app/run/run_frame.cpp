#include "app/run/run_frame.hpp"

#include "common/atomic_file.hpp"

namespace app {

RunFrame::RunFrame(const maze::World &world, const maze::sim::RobotProfile &profile,
                   const maze::sim::SimulationOptions &simulation, RunObserver *files, int progress_fd)
    : simulation_(world, profile, simulation) {
  observers_.add(files);
  if (progress_fd >= 0) observers_.add(&progress_.emplace(progress_fd));
}

void RunFrame::end(const RunEnd &end) {
  try {
    observers_.on_end(end);
  } catch (const common::NoSpaceError &) {
    no_space_ = std::current_exception();
  }
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
