#pragma once
// The whole of a Webots controller process, minus `main`: read the controllerArgs
// (robot/controller_args.hpp), attach to the robot with a default-constructed webots::Robot
// (a real Webots, or the embedded simulator made current), run the CellController, and print
// to out what `maze_mapper run` prints as it goes (robot/progress_printer.hpp), then the
// final map and a summary without the truth (no coverage or wall accuracy):
//
//   end: done
//   steps: 5120
//   moves: 30
//   visited: 16
//   sim_time_s: 163.840
//
// Returns the exit status: 0 when the run ended done or at --max-steps, 1 when it made no
// progress or the simulation ended first or something else failed (one line `error: ...`
// on err), 2 for an unusable argument or a missing device (likewise).

#include <ostream>
#include <span>
#include <string>

namespace robot {

int console_main(std::span<const std::string> args, std::ostream &out, std::ostream &err);

}  // namespace robot
