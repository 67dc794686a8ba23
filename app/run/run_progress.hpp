#pragma once
// The progress line (app/run/progress_line.hpp) as a run's observer, for every kind of run:
// drawn on a terminal after each move into a cell (a run on the lattice: moves, visited of the
// reachable cells) or each control step (in metres: the reachable free cells observed), and
// cleared when the run ends, before its end is printed.

#include <optional>

#include "app/run/progress_line.hpp"
#include "app/run/run_observer.hpp"

namespace app {

class RunProgress final : public RunObserver {
 public:
  // The line on `fd` (a terminal: the caller decides, app/run/terminal.hpp).
  explicit RunProgress(int fd) : fd_(fd) {}

  void on_start(const RunStart &start) override;
  void on_step(const RunStep &step) override;
  void on_end(const RunEnd &) override { line_.reset(); }

 private:
  int fd_;
  std::optional<ProgressLine> line_;
  const MetresRunStart *metres_ = nullptr;  // a run in metres: its map and truth, scored when drawn
};

// Several observers told in turn, in the order added: the files first, then what draws.
class RunObservers final : public RunObserver {
 public:
  // Null is left out.
  void add(RunObserver *observer);
  bool empty() const { return observers_.empty(); }

  void on_start(const RunStart &start) override;
  // The first observer's that asks for the grid's change log (only the files do).
  std::vector<std::uint32_t> *grid_changes() override;
  void on_step(const RunStep &step) override;
  void on_end(const RunEnd &end) override;

 private:
  std::vector<RunObserver *> observers_;
};

}  // namespace app
