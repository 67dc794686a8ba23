// The metric controller's legs onto ground the map has not shown clear (robot/metric/controller.hpp):
// the body sweep's and the probes (explore/metric/sweep.hpp decides them), and what a touch
// or a wedge on one marks.

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "plan/metric/wavefront.hpp"
#include "robot/metric/controller.hpp"

namespace robot {
namespace {

// A touch or a wedge marks the cell this far ahead of the body's rim.
constexpr double kContactAhead_m = 0.02;

}  // namespace

explore::BodyView MetricController::body_view() const {
  return explore::BodyView{map_, metric_.body_radius_m, [this](std::size_t n) { return seen_occupied(n); },
                           [this](std::size_t n) { return covered_or_seen_free(n); }};
}

bool MetricController::covered_or_seen_free(std::size_t flat) const {
  if (body_observes_ && flat < under_body_.size() && under_body_[flat]) return true;
  return !map_.unobserved_at(flat) && map_.probability_at(flat) < 0.5;
}

Motion MetricController::sweep(const explore::SweepLeg &leg, const std::vector<bool> &blocked) {
  const plan::FlatGrid g{map_.cells_x(), map_.cells_y()};
  const std::size_t here = map_.index(robot_cell());
  wave_ = plan::wave_from(g, blocked, leg.from);
  const auto path = plan::descend(g, wave_, here);
  path_ = path ? *path : std::vector<std::size_t>{here};
  bool stopped = false;
  // The leg ends where the rest would observe nothing (explore::body_path_adds_nothing): on
  // the way to its start, the whole leg; on the leg, what is left of it.
  const explore::BodyView view = body_view();
  const mapping::Point start = map_.centre_of(map_.cell_of_index(leg.from));
  const std::function<bool()> leg_adds_nothing = [&] { return explore::body_path_adds_nothing(view, start, leg.end); };
  Motion m = drive_path_corners(&stopped, &leg_adds_nothing);
  if (m == Motion::ok && !stopped && map_.index(robot_cell()) == leg.from) {
    // Onto unobserved ground: a return ahead about to touch the body stops it, as does a
    // wedge on what the echoes missed.
    path_.push_back(leg.aim);
    const std::function<bool()> adds_nothing = [&] {
      return explore::body_path_adds_nothing(view, position_, leg.end);
    };
    m = go_to(leg.end, StopWhen::touching, &stopped, &adds_nothing);
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

bool MetricController::mark_contact() {
  const double yaw = drive_.yaw_rad();
  const double d = metric_.body_radius_m + kContactAhead_m;
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
