// The metric controller's frontier strategy (robot/metric/controller.hpp): each round finds
// the frontier and its target (explore/metric/frontier.hpp), drives the path there and turns a
// full turn scanning; the body sweep's legs and probes are explore/metric/sweep.hpp's.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>

#include <fmt/format.h>

#include "explore/metric/frontier.hpp"
#include "explore/metric/sweep.hpp"
#include "plan/metric/wavefront.hpp"
#include "robot/metric/controller.hpp"

namespace robot {
namespace {

using mapping::Point;

std::size_t count_of(const std::vector<bool> &flags) {
  return static_cast<std::size_t>(std::count(flags.begin(), flags.end(), true));
}

std::string cells_text(std::size_t n) { return fmt::format("{} frontier cell{}", n, n == 1 ? "" : "s"); }

}  // namespace

Motion MetricController::drive_path_corners(bool *stopped, const std::function<bool()> *done) {
  *stopped = false;
  // Drive the path's corners: cells where the direction changes, and the last.
  for (std::size_t k = 1; k < path_.size(); ++k) {
    const bool last = k + 1 == path_.size();
    if (!last) {
      const long d1 = static_cast<long>(path_[k]) - static_cast<long>(path_[k - 1]);
      const long d2 = static_cast<long>(path_[k + 1]) - static_cast<long>(path_[k]);
      if (d1 == d2) continue;
    }
    if (const Motion m = go_to(map_.centre_of(map_.cell_of_index(path_[k])), StopWhen::touching, stopped, done);
        m != Motion::ok) {
      return m;
    }
    if (*stopped || (done != nullptr && (*done)())) return Motion::ok;
    // The map grew while driving: stop when the rest of the path is now blocked.
    bool now_blocked = false;
    const std::vector<bool> fresh = obstacles(false);
    for (std::size_t r = k; r < path_.size(); ++r) now_blocked = now_blocked || fresh[path_[r]];
    if (now_blocked) return Motion::ok;
  }
  return Motion::ok;
}

Motion MetricController::back_off() {
  const double yaw = drive_.yaw_rad();
  const Point back{position_.x_m - metric_.back_off_m * std::cos(yaw), position_.y_m - metric_.back_off_m * std::sin(yaw)};
  const std::function<void()> none;
  const std::function<bool()> never = [] { return false; };
  return drive_.drive_along(back, yaw, -metric_.back_off_m, "backing off", none, never);
}

Motion MetricController::visit_frontier(const explore::FrontierTarget &t, const std::vector<bool> &blocked) {
  const plan::FlatGrid g{map_.cells_x(), map_.cells_y()};
  const std::size_t here = map_.index(robot_cell());
  // The path there: down a wave from the target.
  wave_ = plan::wave_from(g, blocked, t.target);
  const auto path = plan::descend(g, wave_, here);
  path_ = path ? *path : std::vector<std::size_t>{here};
  bool stopped = false;
  // The drive ends once the aim is no frontier cell: seen on the way, or no cell seen clear
  // beside it any more; there is nothing left to look at there.
  const bool lidar = sensing::uses_lidar(options_.model.kind);
  const std::function<bool()> aim_resolved = [&] { return !explore::is_frontier_cell(map_, t.aim, lidar); };
  Motion driven = drive_path_corners(&stopped, &aim_resolved);
  if (driven == Motion::no_progress) {
    // Wedged on something the map had not shown (a corner between the beams): stopped, as
    // by a touch; the visit counts against its frontier cell like any other.
    stopped = true;
    driven = Motion::ok;
  }
  if (driven != Motion::ok) return driven;
  if (stopped) {
    // Back off a little before planning again (from a wedge it may not get far).
    if (const Motion m = back_off(); m != Motion::ok && m != Motion::no_progress) return m;
  }
  if (aim_resolved()) return Motion::ok;
  if (map_.index(robot_cell()) == t.target || !stopped) return look_around();
  return Motion::ok;
}

std::optional<explore::SweepLeg> MetricController::next_sweep_leg(const std::vector<std::int32_t> &steps,
                                                                  const std::vector<bool> &swept, bool probe_only) {
  const explore::BodyView view = body_view();
  std::optional<explore::SweepLeg> leg;
  if (!probe_only) leg = explore::sweep_leg(view, obstacles(false), steps, swept);
  if (!leg && (leg = explore::probe_leg(view, steps, swept))) ++probe_legs_;
  if (leg) ++sweep_legs_;
  return leg;
}

std::optional<explore::FrontierTarget> MetricController::next_frontier_target(
    const std::vector<bool> &frontier, int view_cells, const explore::FrontierVisits &visits,
    const std::vector<std::int32_t> &steps, const explore::MapProgress &progress,
    const std::vector<std::int32_t> &gain) const {
  // The frontier cells not set aside first; then, when none has a target, those set aside
  // before the map last progressed.
  for (const bool retrying : {false, true}) {
    std::vector<bool> aims(map_.size(), false);
    bool any = false;
    for (std::size_t n = 0; n < map_.size(); ++n) {
      aims[n] = frontier[n] && (retrying ? visits.retry(n, progress) : !visits.aside(n));
      any = any || aims[n];
    }
    if (!any) continue;
    if (auto t = explore::frontier_target(map_, metric_.free_below_p, aims, view_cells, visits, steps, &gain)) return t;
  }
  return std::nullopt;
}

explore::MapProgress MetricController::progress_now(const explore::MapProgress &before) const {
  return explore::progress_of(map_, map_.size() - count_of(obstacles(true)), before);
}

std::string MetricController::frontier_left_message(std::size_t unreachable, std::size_t aside) const {
  if (aside == 0) {
    return fmt::format("{} out of reach of the free space reached, the map no longer changing", cells_text(unreachable));
  }
  if (unreachable == 0) {
    return fmt::format("{} left unobserved by {} visits each, the map no longer changing", cells_text(aside),
                       explore::kMaxFrontierAttempts);
  }
  return fmt::format("{} out of reach of the free space reached and {} left unobserved by {} visits each, the map "
                     "no longer changing",
                     cells_text(unreachable), cells_text(aside), explore::kMaxFrontierAttempts);
}

MetricEnding MetricController::run_frontier() {
  const plan::FlatGrid g{map_.cells_x(), map_.cells_y()};
  explore::FrontierVisits visits(map_.size());
  const int view_cells = std::max(1, static_cast<int>(std::floor(metric_.view_m / map_.cell_m())));
  const bool lidar = sensing::uses_lidar(options_.model.kind);
  const auto min_cells = static_cast<std::size_t>(std::max(1.0, std::round(metric_.min_frontier_m / map_.cell_m())));
  if (const Motion m = look_around(); m != Motion::ok) return finish(m);
  explore::MapProgress progress = progress_now({});
  std::vector<bool> swept(map_.size(), false);  // cells a sweep leg or a probe aimed at and left unobserved
  for (;;) {
    const std::vector<bool> blocked = obstacles(true);
    const std::vector<std::int32_t> steps = plan::steps_from(g, blocked, map_.index(robot_cell()));
    // Groups without room for the body are set aside where the cells seen occupied hold an echo's
    // end (the lidar) or the body's own contacts stand over the arcs (the sweep); the IR's arcs
    // close cells of open floor (generated arenas fell to 64 %).
    const std::vector<bool> closed_to_body = obstacles(false);
    explore::FrontierGroups groups = explore::group_frontier(map_, explore::frontier_cells(map_, lidar), min_cells,
                                                             lidar || body_observes_ ? &closed_to_body : nullptr);
    const std::vector<bool> frontier = explore::cells_worth_a_look(groups);
    frontier_left_ = count_of(frontier);
    frontier_aside_ = explore::set_aside_of(groups);
    // Sweep the frontier the body can cover before looking from afar: a look observes only
    // what echoes, a sweep every cell the body goes over (and probes past arcs that hide
    // unobserved ground, frontier or not).
    std::optional<explore::SweepLeg> leg;
    if (body_observes_) leg = next_sweep_leg(steps, swept, false);
    if (!leg && frontier_left_ == 0) {
      message_ = "no frontier left";
      return MetricEnding::done;
    }
    std::optional<explore::FrontierTarget> target;
    if (!leg) {
      target = next_frontier_target(frontier, view_cells, visits, steps, progress,
                                    explore::frontier_gain(groups, 2 * view_cells));
    }
    if (!leg && !target) {
      // No frontier cell has a target: each is set aside by itself, tried again once the map
      // progresses; a probe through the cells the map closes (whatever the set-up) may make it.
      for (std::size_t n = 0; n < map_.size(); ++n) {
        if (frontier[n] && !visits.aside(n)) visits.set_aside(n, progress);
      }
      if (options_.model.kind != sensing::ModelKind::ray) leg = next_sweep_leg(steps, swept, true);
    }
    if (leg) {
      if (const Motion m = sweep(*leg, blocked); m != Motion::ok) return finish(m);
      if (!covered_or_seen_free(leg->aim)) swept[leg->aim] = true;
    } else if (target) {
      if (const Motion m = visit_frontier(*target, blocked); m != Motion::ok) return finish(m);
      visits.visited(target->aim, map_.unobserved_at(target->aim), progress_now(progress));
    } else {
      std::size_t visited = 0;  // set aside after visits; the others had no target
      for (std::size_t n = 0; n < map_.size(); ++n) {
        visited += frontier[n] && visits.attempts(n) >= explore::kMaxFrontierAttempts ? 1U : 0U;
      }
      message_ = frontier_left_message(frontier_left_ - visited, visited);
      return MetricEnding::incomplete;
    }
    progress = progress_now(progress);
  }
}

}  // namespace robot
