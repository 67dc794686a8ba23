// The room controller's body sweep (robot/room_controller.hpp), frontier's way onto open floor
// for a set-up whose nothing-seen marks nothing (the sonar cone): the ground the body covers
// is observed free (sensing::RoomMap::observe_by_body), so the robot drives onto the nearest
// frontier cell it can cover and on straight across unobserved ground.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>

#include "plan/room_wavefront.hpp"
#include "robot/room_controller.hpp"

namespace robot {
namespace {

using mapping::Point;
using sensing::RoomCell;

// How far past the cell it aims at a sweep leg goes on across unobserved ground, at most.
constexpr double kSweepReach_m = 3.0;
// How much nearer than the body's radius the centre comes to the centre of a frontier cell it
// cannot stand on (the edge of the grid or a cell seen occupied beyond it).
constexpr double kCoverMargin_m = 0.015;

// A touch or a wedge marks the cell this far ahead of the body's rim.
constexpr double kContactAhead_m = 0.02;

constexpr std::pair<int, int> kSteps[] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};

}  // namespace

bool RoomController::body_clear_at_edge(Point p) const {
  const double r = room_.body_radius_m;
  const auto &b = map_.spec().boundary;
  const double x_end = b.x_start_m + map_.cells_x() * map_.cell_m();
  const double y_end = b.y_start_m + map_.cells_y() * map_.cell_m();
  return p.x_m - r >= b.x_start_m && p.y_m - r >= b.y_start_m && p.x_m + r <= x_end && p.y_m + r <= y_end;
}

bool RoomController::body_clear_at(Point p) const {
  const double r = room_.body_radius_m;
  if (!body_clear_at_edge(p)) return false;
  const auto lo = map_.cell_at({p.x_m - r, p.y_m - r});
  const auto hi = map_.cell_at({p.x_m + r, p.y_m + r});
  if (!lo || !hi) return false;
  for (int j = lo->j; j <= hi->j; ++j) {
    for (int i = lo->i; i <= hi->i; ++i) {
      const Point c = map_.centre_of({i, j});
      const double h = map_.cell_m() / 2;
      const double gx = std::max(0.0, std::abs(p.x_m - c.x_m) - h);
      const double gy = std::max(0.0, std::abs(p.y_m - c.y_m) - h);
      if (std::hypot(gx, gy) >= r) continue;  // the square is out of the body's reach
      if (seen_occupied(map_.index({i, j}))) return false;
    }
  }
  return true;
}

bool RoomController::covered_or_seen_free(std::size_t flat) const {
  if (body_observes_ && flat < under_body_.size() && under_body_[flat]) return true;
  return !map_.unobserved_at(flat) && map_.probability_at(flat) < 0.5;
}

std::optional<RoomController::SweepLeg> RoomController::sweep_leg(const std::vector<std::int32_t> &steps,
                                                                  const std::vector<bool> &swept) const {
  const std::vector<bool> grown = obstacles(false);
  std::optional<SweepLeg> best;
  std::int32_t best_steps = -1;
  for (std::size_t n = 0; n < map_.size(); ++n) {
    if (swept[n] || !map_.unobserved_at(n)) continue;
    const RoomCell f = map_.cell_of_index(n);
    for (const auto &d : kSteps) {
      const RoomCell t{f.i - d.first, f.j - d.second};
      if (!map_.contains(t)) continue;
      const std::size_t from = map_.index(t);
      if (steps[from] < 0 || (best && steps[from] >= best_steps) || !covered_or_seen_free(from)) continue;
      const Point a = map_.centre_of(t);
      Point end = map_.centre_of(f);
      if (grown[n]) {
        // The body cannot stand on it: come as near as covers its centre.
        const double s = std::max(0.0, map_.cell_m() - room_.body_radius_m + kCoverMargin_m);
        end = {a.x_m + s * d.first, a.y_m + s * d.second};
        if (s >= map_.cell_m() || !body_clear_at(end)) continue;
      } else {
        // Stand on it, and go on straight over unobserved ground the body clears.
        end = map_.centre_of(run_end(f, d, [&](std::size_t m) { return map_.unobserved_at(m) && !grown[m]; }));
      }
      best = SweepLeg{from, n, end};
      best_steps = steps[from];
    }
  }
  return best;
}

std::optional<RoomController::SweepLeg> RoomController::probe_leg(const std::vector<std::int32_t> &steps,
                                                                  const std::vector<bool> &swept) const {
  const int reach = static_cast<int>(std::floor(kSweepReach_m / map_.cell_m()));
  std::optional<SweepLeg> best;
  std::int32_t best_steps = -1;
  for (std::size_t from = 0; from < map_.size(); ++from) {
    if (steps[from] < 0 || (best && steps[from] >= best_steps) || !covered_or_seen_free(from)) continue;
    const RoomCell t = map_.cell_of_index(from);
    for (const auto &d : kSteps) {
      // From the edge of the ground reached, straight on to the first unobserved cell.
      RoomCell c{t.i + d.first, t.j + d.second};
      if (!map_.contains(c) || steps[map_.index(c)] >= 0) continue;
      bool found = false;
      for (int k = 0; k < reach && map_.contains(c) && body_clear_at_edge(map_.centre_of(c)); ++k) {
        if (map_.unobserved_at(map_.index(c))) {
          found = true;
          break;
        }
        c = {c.i + d.first, c.j + d.second};
      }
      if (!found || swept[map_.index(c)]) continue;
      const RoomCell last = run_end(c, d, [&](std::size_t m) { return map_.unobserved_at(m); });
      best = SweepLeg{from, map_.index(c), map_.centre_of(last)};
      best_steps = steps[from];
    }
  }
  return best;
}

RoomCell RoomController::run_end(RoomCell c, std::pair<int, int> d, const std::function<bool(std::size_t)> &on) const {
  const int reach = static_cast<int>(std::floor(kSweepReach_m / map_.cell_m()));
  for (int k = 0; k < reach; ++k) {
    const RoomCell next{c.i + d.first, c.j + d.second};
    if (!map_.contains(next) || !body_clear_at_edge(map_.centre_of(next)) || !on(map_.index(next))) break;
    c = next;
  }
  return c;
}

Motion RoomController::sweep(const SweepLeg &leg, const std::vector<bool> &blocked) {
  const plan::FlatGrid g{map_.cells_x(), map_.cells_y()};
  const std::size_t here = map_.index(robot_cell());
  wave_ = plan::wave_from(g, blocked, leg.from);
  const auto path = plan::descend(g, wave_, here);
  path_ = path ? *path : std::vector<std::size_t>{here};
  bool stopped = false;
  Motion m = drive_path_corners(&stopped);
  if (m == Motion::ok && !stopped && map_.index(robot_cell()) == leg.from) {
    // Onto unobserved ground: a return ahead about to touch the body stops it, as does a
    // wedge on what the echoes missed.
    path_.push_back(leg.aim);
    m = go_to(leg.end, StopWhen::touching, &stopped);
  }
  if (m == Motion::no_progress) {
    stopped = true;
    m = Motion::ok;
  }
  if (m != Motion::ok || !stopped) return m;
  mark_contact();
  const Motion b = back_off();
  return b == Motion::no_progress ? Motion::ok : b;
}

bool RoomController::mark_contact() {
  const double yaw = drive_.yaw_rad();
  const double d = room_.body_radius_m + kContactAhead_m;
  const auto c = map_.cell_at({position_.x_m + d * std::cos(yaw), position_.y_m + d * std::sin(yaw)});
  if (!c || *c == robot_cell()) return false;
  const std::size_t n = map_.index(*c);
  if (contact_.size() != map_.size()) contact_.assign(map_.size(), false);
  if (contact_[n]) return false;
  contact_[n] = true;
  map_.observe_contact(n);
  return true;
}

}  // namespace robot
