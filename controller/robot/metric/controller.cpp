#include "robot/metric/controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include <webots/Robot.hpp>

#include "common/angles.hpp"
#include "common/cell_clearance.hpp"
#include "common/error.hpp"
#include "common/random.hpp"
#include "plan/metric/wavefront.hpp"

namespace robot {
namespace {

using mapping::Point;
using sensing::MetricCell;

// A planned leg (on the grown map) stops only when a return ahead is this close to the body.
constexpr double kTouchMargin_m = 0.03;
// A wavefront ending: this many legs in a row stopped by a touch without touching a new cell.
constexpr int kMaxBareStops = 3;

}  // namespace

MetricController::MetricController(webots::Robot &robot, const ControllerOptions &options, const MetricOptions &metric,
                                   sensing::MetricMap &map, MetricStepHook on_step, StopPoll stop_requested)
    : robot_(robot),
      options_(options),
      metric_(metric),
      map_(map),
      on_step_(std::move(on_step)),
      loop_(robot, options.motion, stop_requested, metric.time_limit_s),
      chassis_(robot, options.devices),
      drive_(chassis_, options.motion, loop_.time_step_ms(), [this](Action a) { return step(a); }),
      senses_(robot, options, map),
      position_(metric.start) {
  chassis_.enable(loop_.time_step_ms());
  senses_.enable(loop_.time_step_ms());
  body_observes_ = senses_.nothing_seen_marks_nothing();
}

double MetricController::time_s() const { return loop_.time_s(); }

void MetricController::update_pose() {
  const WheelAngles now = chassis_.wheel_angles();
  if (const std::optional<Point> gps = chassis_.gps()) {
    position_ = *gps;
  } else {
    const double d = options_.motion.wheel_radius_m *
                     ((now.left_rad - last_wheels_.left_rad) + (now.right_rad - last_wheels_.right_rad)) / 2.0;
    position_.x_m += d * std::cos(drive_.yaw_rad());
    position_.y_m += d * std::sin(drive_.yaw_rad());
  }
  last_wheels_ = now;
}

Motion MetricController::step(Action) {
  if (const Motion m = loop_.step(); m != Motion::ok) return m;
  update_pose();
  senses_.scan(position_, drive_.yaw_rad(), robot_.getTime());
  trajectory_.push_back(position_);
  mark_under_body();
  if (on_step_) on_step_(*this);
  return Motion::ok;
}

bool MetricController::seen_occupied(std::size_t flat) const {
  // Where the body has touched (a frontier sweep leg, a wavefront leg) or frontier's body has
  // been, its own observation stands over the echoes'.
  if (flat < contact_.size() && contact_[flat]) return true;
  if (body_observes_ && metric_.strategy == explore::StrategyKind::frontier && flat < under_body_.size() && under_body_[flat]) {
    return false;
  }
  return map_.probability_at(flat) >= metric_.free_below_p - 1e-9;
}

void MetricController::cover(std::size_t flat) {
  if (under_body_[flat]) return;
  under_body_[flat] = true;
  if (body_observes_) map_.observe_by_body(flat);
}

void MetricController::mark_under_body() {
  if (under_body_.size() != map_.size()) under_body_.assign(map_.size(), false);
  const double r = metric_.body_radius_m;
  const auto lo = map_.cell_at({position_.x_m - r, position_.y_m - r});
  const auto hi = map_.cell_at({position_.x_m + r, position_.y_m + r});
  const MetricCell here = robot_cell();
  const MetricCell a = lo.value_or(here);
  const MetricCell b = hi.value_or(here);
  for (int j = std::min(a.j, here.j); j <= std::max(b.j, here.j); ++j) {
    for (int i = std::min(a.i, here.i); i <= std::max(b.i, here.i); ++i) {
      const Point c = map_.centre_of({i, j});
      if (map_.contains({i, j}) && std::hypot(c.x_m - position_.x_m, c.y_m - position_.y_m) <= r) {
        cover(map_.index({i, j}));
      }
    }
  }
  cover(map_.index(here));
  // The cells the robot's centre has driven through (within a quarter cell of their centre):
  // the body has been there, so the way back through them is clear whatever the map says
  // of their neighbours since.
  if (driven_.size() != map_.size()) driven_.assign(map_.size(), false);
  const Point c = map_.centre_of(here);
  if (std::hypot(c.x_m - position_.x_m, c.y_m - position_.y_m) <= map_.cell_m() / 4) driven_[map_.index(here)] = true;
}

bool MetricController::blocked_ahead() const {
  return senses_.bumped() || senses_.clearance_ahead_m() < metric_.stop_distance_m;
}

bool MetricController::touching_ahead() const {
  return senses_.bumped() || senses_.clearance_ahead_m() < metric_.body_radius_m + kTouchMargin_m;
}

MetricCell MetricController::robot_cell() const {
  const auto c = map_.cell_at(position_);
  if (c) return *c;
  const auto clampi = [](double v, int n) { return std::clamp(static_cast<int>(std::floor(v)), 0, n - 1); };
  const auto &b = map_.spec().boundary;
  return {clampi((position_.x_m - b.x_start_m) / map_.cell_m(), map_.cells_x()),
          clampi((position_.y_m - b.y_start_m) / map_.cell_m(), map_.cells_y())};
}

Motion MetricController::go_to(Point p, StopWhen when, bool *stopped, const std::function<bool()> *done) {
  *stopped = false;
  const double ex = p.x_m - position_.x_m;
  const double ey = p.y_m - position_.y_m;
  const double distance = std::hypot(ex, ey);
  if (distance < options_.motion.position_tolerance_m) return Motion::ok;
  const double yaw = std::atan2(ey, ex);
  if (const Motion m = drive_.turn_to_yaw(yaw); m != Motion::ok) return m;
  const std::function<void()> none;
  bool hit = false;
  const std::function<bool()> stop = [&] {
    if (done != nullptr && (*done)()) return true;
    if (when == StopWhen::never) return false;
    hit = when == StopWhen::obstacle_ahead ? blocked_ahead() : touching_ahead();
    return hit;
  };
  const Motion m = drive_.drive_along(p, yaw, distance, "the point", none, stop);
  *stopped = hit;
  return m;
}

Motion MetricController::look_around() {
  const double start = drive_.yaw_rad();
  for (int quarter = 1; quarter <= 4; ++quarter) {
    if (const Motion m = drive_.turn_to_yaw(common::wrap_angle_rad(start + quarter * std::numbers::pi / 2));
        m != Motion::ok) {
      return m;
    }
  }
  return Motion::ok;
}

std::vector<bool> MetricController::grown_obstacles(const std::vector<bool> &occupied) const {
  const plan::FlatGrid g{map_.cells_x(), map_.cells_y()};
  if (metric_.strategy != explore::StrategyKind::frontier) return plan::dilated(g, occupied, metric_.dilate);
  const std::vector<std::uint8_t> near = common::cells_without_clearance(
      g.cells_x, g.cells_y, map_.cell_m(), metric_.body_radius_m, [&occupied](std::size_t n) { return occupied[n]; });
  std::vector<bool> grown(map_.size(), false);
  for (std::size_t n = 0; n < map_.size(); ++n) {
    grown[n] = occupied[n] || (near[n] != 0 && !(n < driven_.size() && driven_[n]));
  }
  return grown;
}

std::vector<bool> MetricController::obstacles(bool unknown_blocked) const {
  std::vector<bool> out(map_.size(), false);
  for (std::size_t n = 0; n < map_.size(); ++n) {
    out[n] = seen_occupied(n);
  }
  std::vector<bool> grown = grown_obstacles(out);
  if (unknown_blocked) {
    for (std::size_t n = 0; n < map_.size(); ++n) {
      grown[n] = grown[n] || (map_.unobserved_at(n) && !(n < under_body_.size() && under_body_[n]));
    }
  }
  grown[map_.index(robot_cell())] = false;  // where the robot stands
  return grown;
}

MetricEnding MetricController::finish(Motion m) {
  switch (m) {
    case Motion::ok: return MetricEnding::done;
    case Motion::max_steps: message_ = "the step limit was reached"; return MetricEnding::max_steps;
    case Motion::no_progress: message_ = drive_.failure(); return MetricEnding::no_progress;
    case Motion::ended: message_ = "the simulation ended"; return MetricEnding::simulation_ended;
    case Motion::stopped:
      if (loop_.time_up()) {
        message_ = fmt::format("{:g} s of simulated time", metric_.time_limit_s);
        return MetricEnding::time_up;
      }
      message_ = "stopped";
      return MetricEnding::stopped;
  }
  return MetricEnding::stopped;
}

MetricEnding MetricController::run() {
  update_pose();
  if (const Motion m = step(Action::start); m != Motion::ok) return finish(m);
  switch (metric_.strategy) {
    case explore::StrategyKind::waypoints: return run_waypoints();
    case explore::StrategyKind::wavefront: return run_wavefront();
    case explore::StrategyKind::frontier: return run_frontier();
    case explore::StrategyKind::wander: return run_wander();
    case explore::StrategyKind::dfs:
    case explore::StrategyKind::left_wall:
    case explore::StrategyKind::right_wall:
    case explore::StrategyKind::floodfill: break;  // no variant in metres: validate() refuses them
  }
  return MetricEnding::stopped;
}

MetricEnding MetricController::run_waypoints() {
  const std::size_t count = metric_.waypoints.size();
  for (int lap = 1; metric_.laps == 0 || lap <= metric_.laps; ++lap) {
    const std::int64_t lap_began = loop_.steps();
    for (std::size_t n = 0; n < count; ++n) {
      const Point p = metric_.waypoints[n];
      bool stopped = false;
      if (const Motion m = go_to(p, StopWhen::obstacle_ahead, &stopped); m != Motion::ok) return finish(m);
      if (stopped) {
        const std::string leg = lap == 1 ? fmt::format("leg {}", n + 1) : fmt::format("lap {} leg {}", lap, n + 1);
        message_ = fmt::format("{} to ({:g}, {:g}) stopped at ({:.2f}, {:.2f}): {}", leg, p.x_m, p.y_m,
                               position_.x_m, position_.y_m,
                               senses_.bumped() ? std::string("a bumper is pressed")
                                                : fmt::format("a return {:.2f} m ahead", senses_.clearance_ahead_m()));
        return MetricEnding::blocked;
      }
    }
    // A lap with every point where the robot stands takes no step: it rests there a step,
    // scanning, so that time goes on to the limit.
    if (loop_.steps() == lap_began) {
      if (const Motion m = drive_.come_to_rest(); m != Motion::ok) return finish(m);
    }
  }
  message_ = metric_.laps == 1 ? fmt::format("reached all {} waypoints", count)
                             : fmt::format("reached all {} waypoints {} times", count, metric_.laps);
  return MetricEnding::arrived;
}

MetricEnding MetricController::run_wavefront() {
  const auto goal_cell = map_.cell_at(*metric_.goal);
  if (!goal_cell) {
    message_ = fmt::format("the goal ({:g}, {:g}) is outside the map", metric_.goal->x_m, metric_.goal->y_m);
    return MetricEnding::unreachable;
  }
  const std::size_t goal = map_.index(*goal_cell);
  const plan::FlatGrid g{map_.cells_x(), map_.cells_y()};
  int bare_stops = 0;  // legs stopped by a touch since the last one that touched a new cell
  for (;;) {
    const std::size_t here = map_.index(robot_cell());
    if (here == goal) {
      bool stopped = false;
      if (const Motion m = go_to(*metric_.goal, StopWhen::never, &stopped); m != Motion::ok) return finish(m);
      message_ = fmt::format("reached the goal ({:g}, {:g}) in {} steps", metric_.goal->x_m, metric_.goal->y_m, loop_.steps());
      return MetricEnding::goal_reached;
    }
    std::vector<bool> blocked = obstacles(false);
    // The growth keeps the way clear of the body; like the robot's own cell, the goal's is an
    // end of the way: blocked only when the map says it is itself an obstacle (or it was touched).
    blocked[goal] = seen_occupied(goal);
    wave_ = plan::wave_from(g, blocked, goal);
    const auto path = plan::descend(g, wave_, here);
    if (!path) {
      path_.clear();
      message_ = fmt::format("no path to the goal ({:g}, {:g}) on the map with obstacles grown by {} cell{}",
                             metric_.goal->x_m, metric_.goal->y_m, metric_.dilate, metric_.dilate == 1 ? "" : "s");
      return MetricEnding::unreachable;
    }
    path_ = *path;
    // The closest point of the path ahead: its next cell.
    bool stopped = false;
    Motion m = go_to(map_.centre_of(map_.cell_of_index(path_[1])), StopWhen::touching, &stopped);
    if (m == Motion::no_progress) {
      stopped = true;  // wedged on what the map had not shown: as a touch
      m = Motion::ok;
    }
    if (m != Motion::ok) return finish(m);
    // A leg that ends in its cell has done its part, touching or not.
    if (!stopped || map_.index(robot_cell()) == path_[1]) continue;
    // A touch the map did not show short of the cell: the cell just ahead is occupied for
    // planning; back off and plan again. Stops that touch no new cell cannot change the plan.
    bare_stops = mark_contact() ? 0 : bare_stops + 1;
    if (bare_stops >= kMaxBareStops) {
      message_ = fmt::format("no progress to the goal ({:g}, {:g}): stopped by a touch {} times at ({:.2f}, {:.2f}) "
                             "and learned nothing new",
                             metric_.goal->x_m, metric_.goal->y_m, bare_stops, position_.x_m, position_.y_m);
      return MetricEnding::no_progress;
    }
    if (const Motion b = back_off(); b != Motion::ok && b != Motion::no_progress) return finish(b);
  }
}

MetricEnding MetricController::run_wander() {
  common::Rng rng(metric_.seed);
  const std::function<void()> none;
  const std::function<bool()> never = [] { return false; };
  for (;;) {
    const double yaw = drive_.yaw_rad();
    const double far = 1000.0;
    const Point ahead{position_.x_m + far * std::cos(yaw), position_.y_m + far * std::sin(yaw)};
    const std::function<bool()> stop = [this] { return blocked_ahead(); };
    if (const Motion m = drive_.drive_along(ahead, yaw, far, "ahead", none, stop); m != Motion::ok) {
      if (m == Motion::no_progress) {
        // pushing against something the sensors did not stop: back off and turn as after a bump
      } else {
        return finish(m);
      }
    }
    const Point back{position_.x_m - metric_.back_off_m * std::cos(yaw), position_.y_m - metric_.back_off_m * std::sin(yaw)};
    if (const Motion m = drive_.drive_along(back, yaw, -metric_.back_off_m, "backing off", none, never);
        m != Motion::ok && m != Motion::no_progress) {
      return finish(m);
    }
    const double turn = rng.uniform(std::numbers::pi / 2, std::numbers::pi) * (rng.uniform01() < 0.5 ? -1.0 : 1.0);
    if (const Motion m = drive_.turn_to_yaw(common::wrap_angle_rad(drive_.yaw_rad() + turn)); m != Motion::ok) {
      return finish(m);
    }
  }
}

}  // namespace robot
