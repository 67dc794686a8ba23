// The room controller's words and options (robot/metric/controller.hpp).

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "common/error.hpp"
#include "robot/metric/controller.hpp"

namespace robot {
namespace {

using mapping::Point;
constexpr int kMaxMetricDilate = 8;

}  // namespace

std::string_view to_string(MetricEnding e) {
  switch (e) {
    case MetricEnding::done: return "done";
    case MetricEnding::goal_reached: return "goal reached";
    case MetricEnding::arrived: return "arrived";
    case MetricEnding::blocked: return "blocked";
    case MetricEnding::unreachable: return "unreachable";
    case MetricEnding::incomplete: return "incomplete";
    case MetricEnding::time_up: return "time limit";
    case MetricEnding::no_progress: return "no progress";
    case MetricEnding::max_steps: return "max steps";
    case MetricEnding::simulation_ended: return "simulation ended";
    case MetricEnding::stopped: return "stopped";
  }
  return "?";
}

void validate(const MetricOptions &o) {
  common::require_input(explore::explores_in(o.strategy, explore::StrategySpace::metres),
                        fmt::format("--strategy must be {} in a room (got '{}')",
                                    explore::strategy_names(explore::StrategySpace::metres), explore::to_string(o.strategy)));
  common::require_input(o.strategy != explore::StrategyKind::waypoints || !o.waypoints.empty(),
                        "--strategy waypoints needs --waypoints X,Y;X,Y...");
  common::require_input(o.strategy != explore::StrategyKind::wavefront || o.goal.has_value(),
                        "--strategy wavefront needs --goal X,Y (the world gives none)");
  common::require_input(o.strategy != explore::StrategyKind::wander || o.time_limit_s > 0.0, "--strategy wander needs --time-limit S");
  common::require_input(o.laps >= 0, fmt::format("--laps must be a whole number >= 0 (got {})", o.laps));
  common::require_input(o.laps > 0 || o.time_limit_s > 0.0, "--laps 0 (round and round) needs --time-limit S");
  common::require_input(o.dilate >= 0 && o.dilate <= kMaxMetricDilate,
                        fmt::format("--dilate must be 0 to {} cells (got {})", kMaxMetricDilate, o.dilate));
  common::require_input(o.free_below_p > 0.0 && o.free_below_p <= 1.0, "the free threshold must be in (0, 1]");
  common::require_input(o.time_limit_s >= 0.0,  // NaN refused; inf is no limit
                        fmt::format("--time-limit must be more than 0 simulated seconds (got {})", o.time_limit_s));
  for (const Point &p : o.waypoints) {
    common::require_input(std::isfinite(p.x_m) && std::isfinite(p.y_m), "--waypoints must be finite numbers");
  }
  common::require_input(o.stop_distance_m > 0.0 && o.back_off_m > 0.0 && o.view_m > 0.0,
                        "room distances must be > 0 m");
}

}  // namespace robot
