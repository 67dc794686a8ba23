#include "app/mms/mms_session.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <ostream>

#include <fmt/format.h>

#include "app/run/evaluation.hpp"
#include "app/mms/mms_mouse.hpp"
#include "app/mms/mms_outputs.hpp"
#include "app/mms/mms_report.hpp"
#include "app/report/files_recorder.hpp"
#include "app/report/outputs.hpp"
#include "app/report/truth_picture.hpp"
#include "app/run/console_observers.hpp"
#include "app/run/run_frame.hpp"
#include "app/run/profile_json.hpp"
#include "app/run/step_limit.hpp"
#include "app/run/terminal.hpp"
#include "common/atomic_file.hpp"
#include "common/deadline.hpp"
#include "common/error.hpp"
#include "common/interrupt.hpp"
#include "common/standard_streams.hpp"
#include "mapping/walls.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/simulation.hpp"
#include "maze/world/world.hpp"
#include "render/ascii_map.hpp"
#include "robot/command_controller.hpp"
#include "robot/progress_printer.hpp"

namespace app {
namespace {

using Clock = std::chrono::steady_clock;

// The maze mms runs in: a maze without goals gets its centre cells, mms's goal.
maze::Maze with_goals(const maze::Maze &truth) {
  maze::Maze m = truth;
  if (!m.goals().empty()) return m;
  for (int y = (m.height() - 1) / 2; y <= m.height() / 2; ++y) {
    for (int x = (m.width() - 1) / 2; x <= m.width() / 2; ++x) m.add_goal({x, y});
  }
  return m;
}

std::string quoted_line(std::string_view line) {
  constexpr std::size_t kShown = 60;
  std::string shown;
  for (const char c : line.substr(0, kShown)) shown += (c >= 32 && c < 127) ? c : '?';
  return fmt::format("\"{}{}\"", shown, line.size() > kShown ? "..." : "");
}

// The conversation itself, until something ends it.
void converse(const MmsOptions &options, MmsMouse &session, ChildProcess &child, const RunControls &controls,
              MmsReport &report) {
  const auto deadline = common::deadline_after<Clock>(Clock::now(), options.wall_limit_s);
  std::string line;
  for (;;) {
    const ChildProcess::Read r = child.read_line(line, deadline, options.max_line_bytes, controls.interrupted);
    if (r == ChildProcess::Read::closed) {
      report.exit = child.finish(Clock::now() + std::chrono::seconds(2));
      report.end = report.exit->ok() ? MmsEnd::exited : MmsEnd::failed;
      report.message = fmt::format("the algorithm ended ({}) after {} lines", describe(*report.exit), report.lines);
      return;
    }
    if (r == ChildProcess::Read::timeout) {
      report.end = MmsEnd::wall_limit;
      report.message = fmt::format("no end after {:g} s (--wall-limit), {} lines", options.wall_limit_s, report.lines);
      return;
    }
    if (r == ChildProcess::Read::interrupted) {
      report.end = MmsEnd::interrupted;
      report.message = "interrupted by " + common::interrupt_name();
      return;
    }
    ++report.lines;
    if (r == ChildProcess::Read::too_long) {
      report.end = MmsEnd::protocol_error;
      report.message = fmt::format("line {}: longer than {} bytes (--max-line)", report.lines, options.max_line_bytes);
      return;
    }
    if (options.transcript) common::print_stderr("mms {}> {}\n", report.lines, line);
    const ParsedLine parsed = parse_mms_line(line);
    if (!parsed.command) {
      if (options.ignore_invalid) {
        common::print_stderr("warning: line {} {}: {}; ignored (--ignore-invalid)\n", report.lines, quoted_line(line),
                             parsed.error);
        continue;
      }
      report.end = MmsEnd::protocol_error;
      report.message = fmt::format("line {} {}: {}", report.lines, quoted_line(line), parsed.error);
      return;
    }
    const MmsOutcome outcome = session.execute(*parsed.command);
    if (outcome.end) {
      report.end = *outcome.end;
      report.message = outcome.message.empty() ? std::string() : fmt::format("line {} {}: {}", report.lines,
                                                                             quoted_line(line), outcome.message);
      return;
    }
    if (outcome.answer) {
      if (options.transcript) common::print_stderr("mms {}< {}\n", report.lines, *outcome.answer);
      child.write(*outcome.answer + "\n");
    }
    if (session.until_reached()) {
      report.end = MmsEnd::reached;
      report.message = fmt::format("the {} was reached (--until) after {} lines",
                                   options.until == MmsUntil::goal ? "goal" : "start, after the goal", report.lines);
      return;
    }
  }
}

robot::EndReason reason_of(const MmsReport &report, robot::Motion motion) {
  if (report.end == MmsEnd::interrupted) return robot::EndReason::stopped;
  if (report.end == MmsEnd::robot) {
    switch (motion) {
      case robot::Motion::max_steps: return robot::EndReason::max_steps;
      case robot::Motion::no_progress: return robot::EndReason::no_progress;
      case robot::Motion::ended: return robot::EndReason::simulation_ended;
      case robot::Motion::stopped: return robot::EndReason::stopped;
      case robot::Motion::ok: break;
    }
  }
  return robot::EndReason::done;
}

}  // namespace

void validate(const MmsOptions &options) {
  if (options.command.empty()) throw common::InputError("mms needs the algorithm's command after --: mms WORLD -- python3 algo.py");
  if (!(options.wall_limit_s > 0.0)) {
    throw common::InputError(fmt::format("--wall-limit must be more than 0 seconds (got {:g})", options.wall_limit_s));
  }
  if (options.max_line_bytes < 64) {
    throw common::InputError(fmt::format("--max-line must be at least 64 bytes (got {})", options.max_line_bytes));
  }
}

std::string_view to_string(MmsEnd end) {
  switch (end) {
    case MmsEnd::exited: return "exited";
    case MmsEnd::reached: return "reached";
    case MmsEnd::failed: return "failed";
    case MmsEnd::wall_limit: return "wall limit";
    case MmsEnd::protocol_error: return "protocol error";
    case MmsEnd::robot: return "robot stopped";
    case MmsEnd::interrupted: return "interrupted";
  }
  return "?";
}

namespace {

// The conversation on a started robot; the robot's ending, if it had one.
robot::EndReason talk(const MmsOptions &mms, MmsMouse &mouse, robot::CommandController &controller, ChildProcess &child,
                      const RunControls &controls, robot::Motion started, MmsReport &report) {
  robot::Motion motion = started;
  if (motion == robot::Motion::ok) {
    converse(mms, mouse, child, controls, report);
    motion = mouse.robot_motion();
  } else {
    report.end = MmsEnd::robot;
  }
  if (!report.exit) report.exit = child.kill();
  if (motion == robot::Motion::stopped) {
    report.end = MmsEnd::interrupted;
    report.message = "interrupted by " + common::interrupt_name();
  }
  robot::EndReason reason = reason_of(report, motion);
  if (report.end == MmsEnd::robot && motion != robot::Motion::ok) {
    std::string why;
    reason = controller.ended(motion, why);
    if (report.message.empty()) {
      report.message = fmt::format("the robot stopped: {}{}", robot::to_string(reason), why.empty() ? "" : fmt::format(" ({})", why));
    }
  }
  return reason;
}

}  // namespace

MmsRun run_mms(const RunOptions &options, const MmsOptions &mms, const maze::Maze &given, std::ostream &out,
               const RunControls &controls) {
  validate(mms);
  const auto started = Clock::now();
  const maze::Maze truth = with_goals(given);
  const maze::sim::RobotProfile &profile = robot_profile(options);
  const robot::ControllerOptions controller_opts = controller_options(options, truth, profile);
  check_fit(options, truth, profile, controller_opts);
  const std::string &out_dir = options.output.out_dir;
  std::optional<FilesRecorder> recorder;  // the files every kind of run writes, and marks.txt
  if (!out_dir.empty()) recorder.emplace(program_inputs(mms), mms_own_names());
  RunFrame frame(maze::world_of(truth), profile, options.simulation, recorder ? &*recorder : nullptr,
                 controls.progress_fd);
  webots::embedded::Simulation &simulation = frame.simulation();
  const mapping::SensorModel model(options.sensor);
  const render::MapStyle style = map_style(options.output, model, controller_opts, controls.terminal_fd);
  const CellRunStart cell_start{truth, controller_opts, style.initial_log_odds};
  frame.start(RunStart{options, simulation.robot(), &cell_start, nullptr});
  robot::CommandController controller(simulation.robot(), controller_opts);
  MmsRun run;
  MmsReport &report = run.mms;
  report.marks = MmsMarks(truth.width(), truth.height());
  // What the robot tells as it goes: the frame's observers, then the cells printed; the stop
  // signal is polled before each control step.
  RunObservers told;
  told.add(frame.observer());
  std::optional<PrintedCells> printed;
  if (!options.output.quiet) told.add(&printed.emplace(robot::ProgressPrinter(out, style, truth.width() * truth.height())));
  robot::RunHooks hooks = observed_hooks(told.empty() ? nullptr : &told, simulation);
  hooks.stop_requested = controls.interrupted;

  MmsMouse mouse(truth, mms, controller, controller_opts, report);
  ChildProcess child(mms.command);  // before the robot moves: a command that cannot start prints nothing
  const robot::Motion motion = controller.start(hooks);
  const robot::EndReason reason = talk(mms, mouse, controller, child, controls, motion, report);
  const robot::RunResult result = controller.finish(reason, report.message);
  run.summary = robot_summary(options, truth, result, style);
  run.summary.explore_time_s = result.sim_time_s;
  run.summary.interrupted = report.end == MmsEnd::interrupted;
  name_step_limit(options, run.summary);
  run.summary.wall_time_ms = std::chrono::duration<double, std::milli>(Clock::now() - started).count();

  const Report mms_summary = mms_report(options, mms, run);
  if (recorder) recorder->add_own_files(mms_summary, mms_own_files(run));
  const CellRunEnd cell{truth, run.summary, result, model, learned_sides(result, style)};
  frame.end(RunEnd{options, &cell, nullptr}, out, [&] {
    if (report.end == MmsEnd::interrupted) {
      out << "(interrupted: the final map is not printed)\n\n";
    } else {
      out << render::render_map(result.grid, result.visits, style) << '\n';
      out << "the algorithm's marks (setWall, setColor, setText):\n" << render_marks(report.marks, style.color) << '\n';
    }
    out << format_summary(mms_summary);
  });
  frame.close(out);
  return run;
}

MmsRun run_mms_world(const RunOptions &options, const MmsOptions &mms, std::ostream &out, const RunControls &controls) {
  // mms's maze: the algorithm starts in (0,0) facing north and seeks the centre (it counts
  // its own position from there), unless --start or --goal say otherwise.
  maze::WorldOverrides overrides = options.world_overrides;
  if (!overrides.start) overrides.start = maze::Cell{0, 0};
  if (!overrides.goals) overrides.centre_goals = true;
  const maze::World world = maze::load_world(options.world, overrides);
  for (const std::string &warning : world.warnings) common::print_stderr("{}\n", warning);
  return run_mms(options, mms, world.maze(), out, controls);
}

std::string command_line(const std::vector<std::string> &command) {
  std::string text;
  for (const std::string &a : command) {
    if (!text.empty()) text += ' ';
    text += a.find_first_of(" \t'\"") == std::string::npos && !a.empty() ? a : fmt::format("'{}'", a);
  }
  return text;
}

int exit_status(const MmsRun &run) {
  if (run.mms.end == MmsEnd::interrupted) return common::interrupted_exit_status();
  const bool ended_as_asked = run.mms.end == MmsEnd::exited || run.mms.end == MmsEnd::reached;
  return ended_as_asked && run.summary.reached_goal ? 0 : 1;
}

}  // namespace app
