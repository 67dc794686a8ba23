#pragma once
// What a run on the cell lattice shows on the console as it goes, each an observer of the run
// (app/run/run_observer.hpp), told after the files and the progress line: the cells printed as
// the robot arrives in them (robot/progress_printer.hpp), the animation (app/run/terminal.hpp)
// and --step's prompt, which can end the run.

#include <istream>
#include <ostream>

#include "app/run/run_observer.hpp"
#include "app/run/terminal.hpp"
#include "robot/progress_printer.hpp"

namespace app {

// Each arrival in a cell printed: the cell's K x K matrix and the map around it.
class PrintedCells final : public RunObserver {
 public:
  explicit PrintedCells(robot::ProgressPrinter printer) : printer_(std::move(printer)) {}
  void on_start(const RunStart &) override {}
  void on_step(const RunStep &step) override {
    if (step.arrival != nullptr) printer_(*step.arrival);
  }
  void on_end(const RunEnd &) override {}

 private:
  robot::ProgressPrinter printer_;
};

// --animate: every control step and every arrival drawn at the simulator's true pose.
class Animation final : public RunObserver {
 public:
  Animation(std::ostream &out, const render::MapStyle &style, const AnimationOptions &options)
      : animator_(out, style, options) {}
  void on_start(const RunStart &) override {}
  void on_step(const RunStep &step) override;
  void on_end(const RunEnd &) override {}

 private:
  Animator animator_;
};

// --step: after each arrival in a cell, one line of `in` ("q", "quit" or "Q" ends the run,
// anything else goes on; at the end of the input the run goes on to its end), after the
// prompt on `prompt` when it is not null.
class StepPrompt final : public RunObserver {
 public:
  StepPrompt(std::istream &in, std::ostream *prompt) : in_(in), prompt_(prompt) {}
  void on_start(const RunStart &) override {}
  void on_step(const RunStep &step) override;
  void on_end(const RunEnd &) override {}
  // True once a line asked to end the run.
  bool quit() const { return quit_; }

 private:
  std::istream &in_;
  std::ostream *prompt_;
  bool quit_ = false;
  bool stepping_ = true;  // false once the input has ended
};

}  // namespace app
