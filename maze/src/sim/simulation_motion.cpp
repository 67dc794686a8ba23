// The motion half of the embedded simulator: the differential drive over one basic step
// (exact arcs at constant wheel rates) and the body kept out of the walls.
#include <algorithm>
#include <cmath>
#include <limits>

#include "common/angles.hpp"
#include "maze/sim/simulation.hpp"

namespace webots::embedded {

double Simulation::wheel_rate_rad_s(const Wheel &wheel) const {
  if (std::isinf(wheel.target_rad)) return wheel.velocity_rad_s;
  // Position control: towards the target at up to the set velocity, stopping on it.
  const double limit = std::abs(wheel.velocity_rad_s);
  if (wheel.target_rad == wheel.angle_rad || limit == 0.0) return 0.0;
  return wheel.target_rad > wheel.angle_rad ? limit : -limit;
}

double Simulation::time_to_target_s(const Wheel &wheel, double rate_rad_s) const {
  if (std::isinf(wheel.target_rad) || rate_rad_s == 0.0) return std::numeric_limits<double>::infinity();
  return (wheel.target_rad - wheel.angle_rad) / rate_rad_s;
}

void Simulation::advance(double dt_s) {
  // The wheels turn at constant rates except when a position-controlled wheel reaches its
  // target, so a step is at most three pieces of constant rates, each an exact arc.
  double left_s = dt_s;
  for (int piece = 0; piece < 3 && left_s > 0.0; ++piece) {
    const double left_rate = wheel_rate_rad_s(wheels_[kLeftWheel]);
    const double right_rate = wheel_rate_rad_s(wheels_[kRightWheel]);
    const double to_left_s = time_to_target_s(wheels_[kLeftWheel], left_rate);
    const double to_right_s = time_to_target_s(wheels_[kRightWheel], right_rate);
    const double h = std::min({left_s, to_left_s, to_right_s});
    turn_wheel(wheels_[kLeftWheel], left_rate, h, h == to_left_s);
    turn_wheel(wheels_[kRightWheel], right_rate, h, h == to_right_s);
    move_body(left_rate, right_rate, h);
    left_s -= h;
  }
}

void Simulation::turn_wheel(Wheel &wheel, double rate_rad_s, double h_s, bool arrives) {
  wheel.angle_rad = arrives ? wheel.target_rad : wheel.angle_rad + rate_rad_s * h_s;
}

void Simulation::move_body(double left_rad_s, double right_rad_s, double h_s) {
  const double r = profile_.wheel_radius_m;
  const double grip = 1.0 - options_.wheel_slip;
  const double left = options_.wheel_slip > 0.0 ? left_rad_s * grip : left_rad_s;
  const double right = options_.wheel_slip > 0.0 ? right_rad_s * grip : right_rad_s;
  const double v_m_s = r * (left + right) / 2.0;
  const double w_rad_s = r * (right - left) / profile_.axle_m;
  const maze::sim::Pose end = arc_end(pose_, v_m_s, w_rad_s, h_s);
  const int substeps = substeps_for(end, v_m_s, w_rad_s, h_s);
  if (substeps == 1) {
    pose_ = end;
    keep_body_out_of_walls();
    return;
  }
  const double h = h_s / substeps;
  for (int k = 0; k < substeps; ++k) {
    pose_ = arc_end(pose_, v_m_s, w_rad_s, h);
    keep_body_out_of_walls();
  }
}

maze::sim::Pose Simulation::arc_end(const maze::sim::Pose &from, double v_m_s, double w_rad_s,
                                    double h_s) {
  // Exact arc: the chord of length v h sinc(turn / 2) along the mean heading.
  const double turn = w_rad_s * h_s;
  const double half = turn / 2.0;
  const double length_m = v_m_s * h_s;
  // Turning in place (no length, a finite turn): the chord is 0 whatever sinc is, so no sin.
  const bool no_chord = length_m == 0.0 && std::isfinite(half);
  const double chord = no_chord ? 0.0 : length_m * (half == 0.0 ? 1.0 : std::sin(half) / half);
  maze::sim::Pose to = from;
  if (chord != 0.0) {  // at rest: no sin/cos (adding 0 would change nothing)
    to.x_m += chord * std::cos(from.yaw_rad + half);
    to.y_m += chord * std::sin(from.yaw_rad + half);
  }
  to.yaw_rad = common::wrap_angle_rad(from.yaw_rad + turn);
  return to;
}

int Simulation::substeps_for(const maze::sim::Pose &end, double v_m_s, double w_rad_s, double h_s) {
  const double length_m = std::abs(v_m_s) * h_s;
  const double fine = std::ceil(length_m / (0.1 * profile_.body_radius_m));
  if (fine <= 1.0) return 1;
  // One arc when it cannot reach a wall: the (convex) box of free centres holds both of its
  // ends with the arc's sagitta (at most length |turn| / 8) to spare, so it holds the arc.
  const double x = pose_.x_m, y = pose_.y_m;
  if (!free_centres_ || !free_centres_->strictly_contains(x, y)) {
    free_centres_ = with_solids([&](const auto &solids) { return solids.free_centres(x, y, profile_.body_radius_m); });
  }
  const double sagitta_m = length_m * std::abs(w_rad_s * h_s) / 8.0;
  if (free_centres_ && free_centres_->contains_with_margin(x, y, sagitta_m) &&
      free_centres_->contains_with_margin(end.x_m, end.y_m, sagitta_m)) {
    return 1;
  }
  return static_cast<int>(fine);
}

void Simulation::keep_body_out_of_walls() {
  const double radius = profile_.body_radius_m;
  if (free_centres_ && free_centres_->strictly_contains(pose_.x_m, pose_.y_m)) return;
  free_centres_ = with_solids([&](const auto &solids) { return solids.free_centres(pose_.x_m, pose_.y_m, radius); });
  if (free_centres_ && free_centres_->strictly_contains(pose_.x_m, pose_.y_m)) return;
  if (with_solids([&](const auto &solids) { return solids.push_out(pose_.x_m, pose_.y_m, radius); })) {
    collisions_.touching_this_step = true;
  }
}

}  // namespace webots::embedded
