// The room controller's frontier strategy (robot/room_controller.hpp): one round finds the
// frontier, picks the nearest reachable cell that sees a frontier cell, drives the path there,
// and turns a full turn scanning.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "plan/room_wavefront.hpp"
#include "robot/room_controller.hpp"

namespace robot {
namespace {

using mapping::Point;
using sensing::RoomCell;

// A frontier cell aimed at this often and still unobserved is set aside.
constexpr int kMaxFrontierAttempts = 3;

struct Frontier {
  std::vector<bool> cells;  // one flag a map cell: a frontier cell not set aside
  std::size_t open = 0;     // how many `cells` flags
  std::size_t aside = 0;    // frontier cells set aside (not flagged)
};

// Frontier cells: unobserved, beside a cell seen free; those set aside are counted apart.
Frontier find_frontier(const sensing::RoomMap &map, const std::vector<bool> &set_aside) {
  Frontier count;
  count.cells = std::vector<bool>(map.size(), false);
  for (std::size_t n = 0; n < map.size(); ++n) {
    if (!map.unobserved_at(n)) continue;
    const RoomCell c = map.cell_of_index(n);
    bool beside_free = false;
    for (const auto &d : {std::pair{0, 1}, std::pair{1, 0}, std::pair{0, -1}, std::pair{-1, 0}}) {
      const RoomCell nb{c.i + d.first, c.j + d.second};
      if (!map.contains(nb)) continue;
      const std::size_t k = map.index(nb);
      beside_free = beside_free || (!map.unobserved_at(k) && map.probability_at(k) < 0.5);
    }
    if (!beside_free) continue;
    if (set_aside[n]) {
      ++count.aside;
    } else {
      count.cells[n] = true;
      ++count.open;
    }
  }
  return count;
}

}  // namespace

void RoomController::spread_view(const std::vector<bool> &frontier, int view_cells, std::vector<std::int32_t> &near,
                                 std::vector<std::size_t> &nearest_frontier) const {
  // Cells within view of a frontier: a breadth-first spread from every frontier cell, view_cells deep,
  // over cells not seen occupied.
  near.assign(map_.size(), -1);
  nearest_frontier.assign(map_.size(), 0);
  std::deque<std::size_t> queue;
  for (std::size_t n = 0; n < map_.size(); ++n) {
    if (frontier[n]) {
      near[n] = 0;
      nearest_frontier[n] = n;
      queue.push_back(n);
    }
  }
  while (!queue.empty()) {
    const std::size_t c = queue.front();
    queue.pop_front();
    if (near[c] >= view_cells) continue;
    const RoomCell rc = map_.cell_of_index(c);
    for (const auto &d : {std::pair{0, 1}, std::pair{1, 0}, std::pair{0, -1}, std::pair{-1, 0}}) {
      const RoomCell nb{rc.i + d.first, rc.j + d.second};
      if (!map_.contains(nb)) continue;
      const std::size_t k = map_.index(nb);
      if (near[k] >= 0 || map_.probability_at(k) >= room_.free_below_p - 1e-9) continue;
      near[k] = near[c] + 1;
      nearest_frontier[k] = nearest_frontier[c];
      queue.push_back(k);
    }
  }
}

std::size_t RoomController::frontier_target(const std::vector<bool> &frontier, int view_cells,
                                            const std::vector<std::uint8_t> &attempts,
                                            const std::vector<std::int32_t> &steps,
                                            std::vector<std::size_t> &nearest_frontier) const {
  std::vector<std::int32_t> near;
  spread_view(frontier, view_cells, near, nearest_frontier);
  // The nearest reachable cell that sees its frontier cell: no cell seen occupied on the line.
  std::vector<std::size_t> candidates;
  for (std::size_t n = 0; n < map_.size(); ++n) {
    // Each visit that left its frontier cell unobserved brings the next one nearer to it.
    if (steps[n] >= 0 && near[n] >= 0 && near[n] <= std::max(1, view_cells >> attempts[nearest_frontier[n]])) {
      candidates.push_back(n);
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&steps](std::size_t a, std::size_t b) { return steps[a] < steps[b]; });
  for (const std::size_t n : candidates) {
    if (sees(n, nearest_frontier[n])) return n;
  }
  return map_.size();
}

Motion RoomController::drive_path_corners(bool *stopped) {
  *stopped = false;
  // Drive the path's corners: cells where the direction changes, and the last.
  for (std::size_t k = 1; k < path_.size(); ++k) {
    const bool last = k + 1 == path_.size();
    if (!last) {
      const long d1 = static_cast<long>(path_[k]) - static_cast<long>(path_[k - 1]);
      const long d2 = static_cast<long>(path_[k + 1]) - static_cast<long>(path_[k]);
      if (d1 == d2) continue;
    }
    if (const Motion m = go_to(map_.centre_of(map_.cell_of_index(path_[k])), StopWhen::touching, stopped);
        m != Motion::ok) {
      return m;
    }
    if (*stopped) return Motion::ok;
    // The map grew while driving: stop when the rest of the path is now blocked.
    bool now_blocked = false;
    const std::vector<bool> fresh = obstacles(false);
    for (std::size_t r = k; r < path_.size(); ++r) now_blocked = now_blocked || fresh[path_[r]];
    if (now_blocked) return Motion::ok;
  }
  return Motion::ok;
}

Motion RoomController::back_off() {
  const double yaw = drive_.yaw_rad();
  const Point back{position_.x_m - room_.back_off_m * std::cos(yaw), position_.y_m - room_.back_off_m * std::sin(yaw)};
  const std::function<void()> none;
  const std::function<bool()> never = [] { return false; };
  return drive_.drive_along(back, yaw, -room_.back_off_m, "backing off", none, never);
}

RoomEnding RoomController::run_frontier() {
  const plan::FlatGrid g{map_.cells_x(), map_.cells_y()};
  std::vector<bool> set_aside(map_.size(), false);
  std::vector<std::uint8_t> attempts(map_.size(), 0);  // visits aimed at each frontier cell
  const int view_cells = std::max(1, static_cast<int>(std::floor(room_.view_m / map_.cell_m())));
  if (const Motion m = look_around(); m != Motion::ok) return finish(m);
  std::vector<bool> swept(map_.size(), false);  // frontier cells a sweep leg left unobserved
  for (;;) {
    const Frontier found = find_frontier(map_, set_aside);
    const std::vector<bool> &frontier = found.cells;
    frontier_left_ = found.open + found.aside;
    const std::size_t here = map_.index(robot_cell());
    const std::vector<bool> blocked = obstacles(true);
    const std::vector<std::int32_t> steps = plan::steps_from(g, blocked, here);
    if (body_observes_) {
      // Sweep the frontier the body can cover before looking from afar: a look observes only
      // what echoes, a sweep every cell the body goes over.
      std::optional<SweepLeg> leg = sweep_leg(steps, swept);
      if (!leg && (leg = probe_leg(steps, swept))) ++probe_legs_;
      if (leg) {
        ++sweep_legs_;
        if (const Motion m = sweep(*leg, blocked); m != Motion::ok) return finish(m);
        if (!covered_or_seen_free(leg->aim)) swept[leg->aim] = true;
        continue;
      }
    }
    if (found.open == 0) {
      if (found.aside == 0) {
        message_ = "no frontier left";
        return RoomEnding::done;
      }
      message_ = fmt::format("{} frontier cell{} could not be observed from the free space reached", found.aside,
                             found.aside == 1 ? "" : "s");
      return RoomEnding::incomplete;
    }
    std::vector<std::size_t> nearest_frontier;
    const std::size_t target = frontier_target(frontier, view_cells, attempts, steps, nearest_frontier);
    if (target == map_.size()) {
      for (std::size_t n = 0; n < map_.size(); ++n) set_aside[n] = set_aside[n] || frontier[n];
      continue;  // every frontier out of reach: the next round ends
    }
    const std::size_t aim = nearest_frontier[target];
    // The path there: down a wave from the target.
    wave_ = plan::wave_from(g, blocked, target);
    const auto path = plan::descend(g, wave_, here);
    path_ = path ? *path : std::vector<std::size_t>{here};
    bool stopped = false;
    Motion driven = drive_path_corners(&stopped);
    if (driven == Motion::no_progress) {
      // Wedged on something the map had not shown (a corner between the beams): stopped, as
      // by a touch; the visit counts against its frontier cell like any other.
      stopped = true;
      driven = Motion::ok;
    }
    if (driven != Motion::ok) return finish(driven);
    if (stopped) {
      // Back off a little before planning again (from a wedge it may not get far).
      if (const Motion m = back_off(); m != Motion::ok && m != Motion::no_progress) return finish(m);
    }
    if (map_.index(robot_cell()) == target || !stopped) {
      if (const Motion m = look_around(); m != Motion::ok) return finish(m);
    }
    attempts[aim] = static_cast<std::uint8_t>(std::min(attempts[aim] + 1, 255));
    if (map_.unobserved_at(aim) && attempts[aim] >= kMaxFrontierAttempts) set_aside[aim] = true;
  }
}

}  // namespace robot
