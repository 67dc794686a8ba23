#include "robot/console_main.hpp"

#include <exception>

#include <fmt/format.h>

#include <webots/Robot.hpp>

#include "common/error.hpp"
#include "mapping/sensor_model.hpp"
#include "robot/controller_args.hpp"
#include "robot/progress_printer.hpp"

namespace robot {

namespace {

std::string summary(const RunResult &r) {
  const std::string end = r.message.empty() ? std::string(to_string(r.reason))
                                            : fmt::format("{} ({})", to_string(r.reason), r.message);
  return fmt::format("end: {}\nsteps: {}\nmoves: {}\nvisited: {}\nsim_time_s: {:.3f}\n", end, r.steps, r.moves,
                     r.visited, r.sim_time_s);
}

int exit_status(EndReason reason) {
  return reason == EndReason::done || reason == EndReason::max_steps ? 0 : 1;
}

int run(const ControllerOptions &options, std::ostream &out) {
  webots::Robot robot;
  CellController controller(robot, options);
  render::MapStyle style;
  style.initial_log_odds = static_cast<float>(mapping::SensorModel(options.sensor).prior_log_odds());
  style.threshold = options.occupied_threshold;
  ProgressPrinter printer(out, style, options.geometry.width_cells * options.geometry.height_cells);
  const RunResult result = controller.run([&printer](const MoveReport &report) { printer(report); });
  out << render::render_map(result.grid, result.visits, style) << '\n' << summary(result) << std::flush;
  return exit_status(result.reason);
}

}  // namespace

int console_main(std::span<const std::string> args, std::ostream &out, std::ostream &err) {
  try {
    return run(parse_controller_args(args), out);
  } catch (const common::InputError &e) {
    err << e.diagnostic() << '\n';
    return 2;
  } catch (const std::exception &e) {
    err << "error: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace robot
