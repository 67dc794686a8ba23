#pragma once
// The frame every kind of run is composed in: a maze run (app/run/run.hpp), a room run
// (app/run/metric/run.hpp) and an mms program's run (app/mms/mms_session.hpp). The frame owns
// what they share: the simulation, built from the world alone; the observers, told the start,
// each step and the end in one order (the files first, then the progress line); and a full
// disk met while the files are written, which is said after the run's summary (the user still
// gets the summary). What a kind adds is its driver: the cell controller, the metric
// controller, an mms program's commands or a Python controller's own loop
// (python/src/simulator_bindings.cpp), whose steps it tells the frame.

#include <exception>
#include <functional>
#include <optional>
#include <ostream>

#include "app/run/run_observer.hpp"
#include "app/run/run_progress.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/simulation.hpp"
#include "maze/world/world.hpp"

namespace app {

class RunFrame {
 public:
  // The simulation of `profile` in `world`; `files` (null: none) is told first, then the
  // progress line on `progress_fd` (-1: none; a terminal, app/run/terminal.hpp).
  RunFrame(const maze::World &world, const maze::sim::RobotProfile &profile,
           const maze::sim::SimulationOptions &simulation, RunObserver *files, int progress_fd);

  webots::embedded::Simulation &simulation() { return simulation_; }
  // The observers in their order, or null when there is none (a driver then reports nothing).
  RunObserver *observer() { return observers_.empty() ? nullptr : &observers_; }

  // One more observer, told after those before it (a Python controller's files, given once
  // the runner has checked --out).
  void add(RunObserver *observer) { observers_.add(observer); }
  void start(const RunStart &start) { observers_.on_start(start); }
  void step(const RunStep &step) { observers_.on_step(step); }
  // Tells the end and prints the run's end on `out` (`print_end`): the files first (a
  // long map prints after them), but for a run a stop signal ended the printed end first
  // (flushed, once the progress line is cleared): its files then have a bounded time
  // (app/report/output_dir.hpp), which the summary must not wait on. A full disk
  // (common::NoSpaceError) met by the files is kept for close().
  void end(const RunEnd &end, std::ostream &out, const std::function<void()> &print_end);
  // Once the summary is on `out`: a full disk kept by end() is handed to `keep` when it is not
  // null, else thrown (after `out` is flushed).
  void close(std::ostream &out, std::exception_ptr *keep = nullptr);

 private:
  webots::embedded::Simulation simulation_;
  RunObservers observers_;
  std::optional<RunProgress> progress_;
  std::exception_ptr no_space_;
};

}  // namespace app
