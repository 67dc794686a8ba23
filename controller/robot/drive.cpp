#include "robot/drive.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include <webots/GPS.hpp>
#include <webots/InertialUnit.hpp>
#include <webots/Motor.hpp>
#include <webots/PositionSensor.hpp>
#include <webots/Robot.hpp>

#include "common/angles.hpp"
#include "common/error.hpp"
#include "robot/require_device.hpp"

namespace robot {
namespace {

using mapping::Heading;
using mapping::Point;

// Counts consecutive steps in which a value stays within epsilon of where it last moved.
class StallWatch {
 public:
  StallWatch(double value, double epsilon, int limit) : ref_(value), epsilon_(epsilon), limit_(limit) {}
  // True when the value has not moved by epsilon for `limit` steps.
  bool stalled(double value) {
    if (std::abs(value - ref_) > epsilon_) {
      ref_ = value;
      count_ = 0;
      return false;
    }
    return ++count_ >= limit_;
  }

 private:
  double ref_;
  double epsilon_;
  int limit_;
  int count_ = 0;
};

// The legs. Each: arrived() before a step, command() the body's (v, w), measure() after a
// step, progress() the value the stall watch follows, stalled() the failure's words.
struct Command {
  double v_m_s;
  double w_rad_s;
};

class TurnLeg {
 public:
  TurnLeg(const Drive &drive, Heading h, double tolerance_rad)
      : drive_(drive), name_(1, mapping::to_char(h)), target_rad_(mapping::yaw_rad(h)), tolerance_rad_(tolerance_rad),
        last_(drive.yaw_rad()) {}
  TurnLeg(const Drive &drive, double yaw_rad, double tolerance_rad)
      : drive_(drive), name_(fmt::format("{:.4f} rad", yaw_rad)), target_rad_(yaw_rad), tolerance_rad_(tolerance_rad),
        last_(drive.yaw_rad()) {}
  bool arrived() const { return std::abs(error()) < tolerance_rad_; }
  Command command() const { return {0.0, drive_.turn_rate_rad_s(error())}; }
  void after_step() const {}
  void measure() {
    turned_ += common::wrap_angle_rad(drive_.yaw_rad() - last_);
    last_ = drive_.yaw_rad();
  }
  double progress() const { return turned_; }
  std::string stalled(int steps) const {
    return fmt::format("turning to {} made no progress for {} steps (yaw {:.4f} rad)", name_, steps, drive_.yaw_rad());
  }

 private:
  double error() const { return common::wrap_angle_rad(target_rad_ - drive_.yaw_rad()); }
  const Drive &drive_;
  std::string name_;
  double target_rad_;
  double tolerance_rad_;
  double last_;
  double turned_ = 0.0;
};

// Along heading h to a point: by the GPS (distance along h still to go, offset to the left
// of the line through the target), else by the encoders (distance_m less what they count).
class DriveLeg {
 public:
  DriveLeg(const Drive &drive, Point target, Heading h, double distance_m, double tolerance_m, std::string_view what,
           const std::function<void()> &after)
      : drive_(drive), target_(target), name_(1, mapping::to_char(h)), yaw_rad_(mapping::yaw_rad(h)),
        dir_x_(mapping::dx(h)), dir_y_(mapping::dy(h)), distance_m_(distance_m), tolerance_m_(tolerance_m),
        what_(what), after_(after) {
    measure();
  }
  // Along any yaw (the room controller's legs), stopping early when stop() says so.
  DriveLeg(const Drive &drive, Point target, double yaw_rad, double distance_m, double tolerance_m,
           std::string_view what, const std::function<void()> &after, const std::function<bool()> &stop)
      : drive_(drive), target_(target), name_(fmt::format("{:.4f} rad", yaw_rad)), yaw_rad_(yaw_rad),
        dir_x_(std::cos(yaw_rad)), dir_y_(std::sin(yaw_rad)), distance_m_(distance_m), tolerance_m_(tolerance_m),
        what_(what), after_(after), stop_(&stop) {
    measure();
  }
  bool arrived() const { return std::abs(remaining_m_) < tolerance_m_ || (stop_ != nullptr && *stop_ && (*stop_)()); }
  Command command() {
    double v = drive_.speed_m_s(remaining_m_);
    if (ramped_) {
      v = drive_.ramped_speed_m_s(remaining_m_, last_v_m_s_);
      last_v_m_s_ = v;
    }
    return {v, drive_.turn_rate_rad_s(drive_.heading_error_rad(yaw_rad_, offset_m_))};
  }
  void after_step() const {
    if (after_) after_();
  }
  void ramp() { ramped_ = true; }
  void measure() {
    const std::optional<Point> p = drive_.gps();
    if (!p) {
      remaining_m_ = distance_m_ - drive_.travelled_m();
      offset_m_ = 0.0;
      return;
    }
    const double ex = target_.x_m - p->x_m;
    const double ey = target_.y_m - p->y_m;
    remaining_m_ = ex * dir_x_ + ey * dir_y_;
    offset_m_ = -(ex * -dir_y_ + ey * dir_x_);
  }
  double progress() const { return remaining_m_; }
  std::string stalled(int steps) const {
    return fmt::format("driving {} to {} made no progress for {} steps ({:.3f} m to go)", name_, what_, steps,
                       remaining_m_);
  }

 private:
  const Drive &drive_;
  Point target_;
  std::string name_;
  double yaw_rad_;
  double dir_x_;
  double dir_y_;
  double distance_m_;
  double tolerance_m_;
  std::string_view what_;
  const std::function<void()> &after_;
  const std::function<bool()> *stop_ = nullptr;
  double remaining_m_ = 0.0;
  double offset_m_ = 0.0;
  bool ramped_ = false;
  double last_v_m_s_ = 0.0;
};

// Forward along heading h from `centre` at creep speed until stop() or limit_m along.
class CreepLeg {
 public:
  CreepLeg(const Drive &drive, Heading h, Point centre, double limit_m, double speed_m_s, std::string_view what,
           const std::function<bool()> &stop)
      : drive_(drive), h_(h), centre_(centre), limit_m_(limit_m), speed_m_s_(speed_m_s), what_(what), stop_(stop) {
    measure();
  }
  bool arrived() const { return stop_() || !(along_m_ < limit_m_); }
  Command command() const { return {speed_m_s_, drive_.turn_rate_rad_s(drive_.heading_error_rad(h_, offset_m_))}; }
  void after_step() const {}
  void measure() {
    const std::optional<Point> p = drive_.gps();
    if (!p) {
      along_m_ = drive_.travelled_m();
      offset_m_ = 0.0;
      return;
    }
    const double ex = p->x_m - centre_.x_m;
    const double ey = p->y_m - centre_.y_m;
    along_m_ = ex * mapping::dx(h_) + ey * mapping::dy(h_);
    offset_m_ = ex * -mapping::dy(h_) + ey * mapping::dx(h_);
  }
  double progress() const { return along_m_; }
  std::string stalled(int steps) const { return fmt::format("{} made no progress for {} steps", what_, steps); }

 private:
  const Drive &drive_;
  Heading h_;
  Point centre_;
  double limit_m_;
  double speed_m_s_;
  std::string_view what_;
  const std::function<bool()> &stop_;
  double along_m_ = 0.0;
  double offset_m_ = 0.0;
};

}  // namespace

WebotsChassis::WebotsChassis(webots::Robot &robot, const DeviceNames &d)
    : left_(require_device(robot.getMotor(d.left_motor), d.left_motor)),
      right_(require_device(robot.getMotor(d.right_motor), d.right_motor)),
      left_encoder_(require_device(robot.getPositionSensor(d.left_encoder), d.left_encoder)),
      right_encoder_(require_device(robot.getPositionSensor(d.right_encoder), d.right_encoder)),
      imu_(require_device(robot.getInertialUnit(d.imu), d.imu)),
      gps_(d.gps.empty() ? nullptr : robot.getGPS(d.gps)) {}  // Webots warns about an unknown name

void WebotsChassis::enable(int time_step_ms) {
  left_encoder_->enable(time_step_ms);
  right_encoder_->enable(time_step_ms);
  imu_->enable(time_step_ms);
  if (gps_ != nullptr) gps_->enable(time_step_ms);
  left_->setPosition(INFINITY);
  right_->setPosition(INFINITY);
  set_wheel_speeds(0.0, 0.0);
}

double WebotsChassis::yaw_rad() const { return imu_->getRollPitchYaw()[2]; }

WheelAngles WebotsChassis::wheel_angles() const { return {left_encoder_->getValue(), right_encoder_->getValue()}; }

std::optional<Point> WebotsChassis::gps() const {
  if (gps_ == nullptr) return std::nullopt;
  const double *v = gps_->getValues();
  return Point{v[0], v[1]};
}

double WebotsChassis::max_wheel_speed_rad_s() const {
  return std::min(left_->getMaxVelocity(), right_->getMaxVelocity());
}

void WebotsChassis::set_wheel_speeds(double left_rad_s, double right_rad_s) {
  left_->setVelocity(left_rad_s);
  right_->setVelocity(right_rad_s);
}

Drive::Drive(Chassis &chassis, const MotionOptions &options, int time_step_ms, StepFunction step)
    : chassis_(chassis), options_(options), step_(std::move(step)), dt_s_(time_step_ms / 1000.0) {
  max_wheel_rad_s_ = chassis.max_wheel_speed_rad_s();
  max_v_m_s_ = std::min(options.cruise_speed_rad_s, max_wheel_rad_s_) * options.wheel_radius_m;
  max_w_rad_s_ = std::min(options.turn_speed_rad_s, max_wheel_rad_s_) * 2.0 * options.wheel_radius_m / options.axle_m;
}

template <typename Leg>
Motion Drive::follow(Leg &leg, Action action) {
  StallWatch watch(leg.progress(), options_.stall_epsilon, options_.stall_steps);
  while (!leg.arrived()) {
    const Command c = leg.command();
    set_body(c.v_m_s, c.w_rad_s);
    moved_ = true;
    if (const Motion s = step_(action); s != Motion::ok) return s;
    leg.after_step();
    leg.measure();
    if (watch.stalled(leg.progress())) {
      failure_ = leg.stalled(options_.stall_steps);
      return Motion::no_progress;
    }
  }
  return Motion::ok;
}

Motion Drive::come_to_rest() {
  chassis_.set_wheel_speeds(0.0, 0.0);
  return step_(Action::rest);
}

Motion Drive::turn_to(Heading h) {
  moved_ = false;
  TurnLeg leg(*this, h, options_.yaw_tolerance_rad);
  if (const Motion s = follow(leg, Action::turn); s != Motion::ok) return s;
  return moved_ ? come_to_rest() : Motion::ok;
}

Motion Drive::drive_to(Point target, Heading h, double distance_m, std::string_view what,
                       const std::function<void()> &after_step) {
  start_odometry();
  DriveLeg leg(*this, target, h, distance_m, options_.position_tolerance_m, what, after_step);
  if (const Motion s = follow(leg, Action::drive); s != Motion::ok) return s;
  return come_to_rest();
}

Motion Drive::drive_ramped(Point target, Heading h, double distance_m, std::string_view what) {
  start_odometry();
  const std::function<void()> none;
  DriveLeg leg(*this, target, h, distance_m, options_.position_tolerance_m, what, none);
  leg.ramp();
  if (const Motion s = follow(leg, Action::drive); s != Motion::ok) return s;
  return come_to_rest();
}

Motion Drive::turn_to_yaw(double yaw_rad) {
  moved_ = false;
  TurnLeg leg(*this, yaw_rad, options_.yaw_tolerance_rad);
  if (const Motion s = follow(leg, Action::turn); s != Motion::ok) return s;
  return moved_ ? come_to_rest() : Motion::ok;
}

Motion Drive::drive_along(Point target, double yaw_rad, double distance_m, std::string_view what,
                          const std::function<void()> &after_step, const std::function<bool()> &stop) {
  start_odometry();
  DriveLeg leg(*this, target, yaw_rad, distance_m, options_.position_tolerance_m, what, after_step, stop);
  if (const Motion s = follow(leg, Action::drive); s != Motion::ok) return s;
  return come_to_rest();
}

Motion Drive::creep(Heading h, Point centre, double limit_m, std::string_view what, const std::function<bool()> &stop) {
  start_odometry();
  CreepLeg leg(*this, h, centre, limit_m, options_.creep_speed_m_s, what, stop);
  return follow(leg, Action::probe);
}

double Drive::travelled_m() const {
  const WheelAngles now = chassis_.wheel_angles();
  return options_.wheel_radius_m *
         ((now.left_rad - start_angles_.left_rad) + (now.right_rad - start_angles_.right_rad)) / 2.0;
}

double Drive::speed_m_s(double remaining_m) const {
  return std::clamp(options_.drive_gain * remaining_m / dt_s_, -max_v_m_s_, max_v_m_s_);
}

double Drive::ramped_speed_m_s(double remaining_m, double last_m_s) const {
  const double a = options_.ramp_acceleration_m_s2;
  const double top = std::min(options_.ramp_top_speed_m_s, max_wheel_rad_s_ * options_.wheel_radius_m);
  const double stop = std::sqrt(2.0 * a * std::max(remaining_m, 0.0));
  const double v = std::min({options_.drive_gain * remaining_m / dt_s_, last_m_s + a * dt_s_, top, stop});
  return std::clamp(v, -top, top);
}

double Drive::turn_rate_rad_s(double heading_error_rad) const {
  return std::clamp(options_.turn_gain * heading_error_rad / dt_s_, -max_w_rad_s_, max_w_rad_s_);
}

double Drive::heading_error_rad(Heading h, double offset_m) const {
  return heading_error_rad(mapping::yaw_rad(h), offset_m);
}

double Drive::heading_error_rad(double target_yaw_rad, double offset_m) const {
  return common::wrap_angle_rad(target_yaw_rad - yaw_rad()) - options_.lateral_gain * offset_m;
}

void Drive::start_odometry() { start_angles_ = chassis_.wheel_angles(); }

// Wheel speeds (rad/s) for body velocities v (m/s) and w (rad/s, counter-clockwise), scaled
// down together when one exceeds the motors' maximum.
void Drive::set_body(double v_m_s, double w_rad_s) {
  const double half = w_rad_s * options_.axle_m / 2.0;
  double l = (v_m_s - half) / options_.wheel_radius_m;
  double r = (v_m_s + half) / options_.wheel_radius_m;
  const double biggest = std::max(std::abs(l), std::abs(r));
  if (biggest > max_wheel_rad_s_ && biggest > 0.0) {
    l *= max_wheel_rad_s_ / biggest;
    r *= max_wheel_rad_s_ / biggest;
  }
  chassis_.set_wheel_speeds(l, r);
}

}  // namespace robot
