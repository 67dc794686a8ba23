// The room controller's words and options (robot/room_controller.hpp).

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "common/error.hpp"
#include "robot/room_controller.hpp"

namespace robot {
namespace {

using mapping::Point;
constexpr int kMaxRoomDilate = 8;

}  // namespace

std::string_view to_string(RoomStrategy s) {
  switch (s) {
    case RoomStrategy::waypoints: return "waypoints";
    case RoomStrategy::wavefront: return "wavefront";
    case RoomStrategy::frontier: return "frontier";
    case RoomStrategy::wander: return "wander";
  }
  return "?";
}

RoomStrategy parse_room_strategy(std::string_view name) {
  for (const RoomStrategy s : {RoomStrategy::waypoints, RoomStrategy::wavefront, RoomStrategy::frontier,
                               RoomStrategy::wander}) {
    if (to_string(s) == name) return s;
  }
  throw common::InputError(
      fmt::format("--strategy must be waypoints, wavefront, frontier or wander in a room (got '{}')", name));
}

std::string_view to_string(RoomEnding e) {
  switch (e) {
    case RoomEnding::done: return "done";
    case RoomEnding::goal_reached: return "goal reached";
    case RoomEnding::arrived: return "arrived";
    case RoomEnding::blocked: return "blocked";
    case RoomEnding::unreachable: return "unreachable";
    case RoomEnding::incomplete: return "incomplete";
    case RoomEnding::time_up: return "time up";
    case RoomEnding::no_progress: return "no progress";
    case RoomEnding::max_steps: return "max steps";
    case RoomEnding::simulation_ended: return "simulation ended";
    case RoomEnding::stopped: return "stopped";
  }
  return "?";
}

void validate(const RoomOptions &o) {
  common::require_input(o.strategy != RoomStrategy::waypoints || !o.waypoints.empty(),
                        "--strategy waypoints needs --waypoints X,Y;X,Y...");
  common::require_input(o.strategy != RoomStrategy::wavefront || o.goal.has_value(),
                        "--strategy wavefront needs --goal X,Y (the world gives none)");
  common::require_input(o.strategy != RoomStrategy::wander || o.time_limit_s > 0.0, "--strategy wander needs --time-limit S");
  common::require_input(o.laps >= 0, fmt::format("--laps must be a whole number >= 0 (got {})", o.laps));
  common::require_input(o.laps > 0 || o.time_limit_s > 0.0, "--laps 0 (round and round) needs --time-limit S");
  common::require_input(o.dilate >= 0 && o.dilate <= kMaxRoomDilate,
                        fmt::format("--dilate must be 0 to {} cells (got {})", kMaxRoomDilate, o.dilate));
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
