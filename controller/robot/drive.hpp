#pragma once
// The robot's wheels and pose sensors, and the one proportional motion loop that turning in
// place, driving to a point and creeping forward share.
//
// A motion is a leg: each control step it reads the pose (IMU yaw; the encoders' distance,
// or the GPS when the robot has one), stops when it has arrived, else sets the body's speeds
// and steps. Speeds are proportional to the error left (gain: the fraction of it to close
// in one step), capped by the motors: v = clamp(drive_gain * remaining / dt, +-max_v),
// w = clamp(turn_gain * heading_error / dt, +-max_w), where the heading error includes
// lateral_gain rad a metre of offset from the line (GPS). A leg whose progress stays within
// stall_epsilon for stall_steps steps fails with Motion::no_progress and a message.
//
// Drive reads and commands the robot through Chassis, which WebotsChassis implements over
// the webots:: devices (a kinematic fake of a few lines stands in for it in the tests).

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "mapping/grid_types.hpp"

namespace webots {
class GPS;
class InertialUnit;
class Motor;
class PositionSensor;
class Robot;
}

namespace robot {

// Device names, as a robot profile gives them (the hambot's by default).
struct DeviceNames {
  std::string left_motor = "left motor";
  std::string right_motor = "right motor";
  std::string left_encoder = "left wheel encoder";  // FAIRIS-Lite HamBot's names
  std::string right_encoder = "right wheel encoder";
  std::string imu = "imu";
  std::string gps = "gps";      // optional device: used when the robot has it
  std::string lidar = "lidar";
};

struct MotionOptions {
  int time_step_ms = 0;               // 0: the world's basic time step
  double wheel_radius_m = 0.045;      // hambot
  double axle_m = 0.184;              // distance between the wheels, hambot
  double cruise_speed_rad_s = 10.0;   // wheel speed driving (capped by the motor's maximum)
  double turn_speed_rad_s = 5.0;      // wheel speed turning in place (capped likewise)
  double yaw_tolerance_rad = 0.002;   // a turn ends within this of the target yaw
  double position_tolerance_m = 0.002;  // a drive ends within this of the target point
  // Proportional gains as the fraction of the remaining error to close in one time step
  // (0, 1]: smaller is smoother, 1 would aim to arrive in one step.
  double turn_gain = 0.5;
  double drive_gain = 0.5;
  // Steering while driving, rad of heading correction per metre of lateral offset (GPS).
  double lateral_gain = 2.0;
  // No progress: a move whose distance (m) or yaw (rad) changes by less than
  // stall_epsilon over stall_steps consecutive steps is reported as a failure.
  int stall_steps = 60;
  double stall_epsilon = 1e-4;
  std::int64_t max_steps = 2'000'000;  // --max-steps: control steps, the whole run
  double creep_speed_m_s = 0.1;       // bump probing: forward speed while feeling for a wall
  // The speed run's straights (the robot's description): a trapezoidal speed profile up to
  // this acceleration and top speed (capped by the motors); 0: none, cell by cell.
  double ramp_acceleration_m_s2 = 0.0;
  double ramp_top_speed_m_s = 0.0;
};

// Whether straights are ramped legs (the robot's description gives a ramp).
inline bool has_ramp(const MotionOptions &options) {
  return options.ramp_acceleration_m_s2 > 0.0 && options.ramp_top_speed_m_s > 0.0;
}

// Throws common::InputError when a number is unusable: positive sizes, speeds and
// tolerances, gains in (0, 1], stall_steps and max_steps >= 1, time_step_ms >= 0.
void validate(const MotionOptions &options);

// What the controller was doing in a control step.
enum class Action { start, turn, drive, rest, probe };
std::string_view to_string(Action action);  // "start", "turn", "drive", "rest", "probe" (bump)

// How a motion (or a step) ended: ok, or why the run must end.
enum class Motion { ok, max_steps, no_progress, ended, stopped };

// One control step doing `action`; anything but Motion::ok ends the motion.
using StepFunction = std::function<Motion(Action)>;

struct WheelAngles {
  double left_rad = 0.0;
  double right_rad = 0.0;
};

// The wheels and pose sensors, as the motion loop reads and commands them each step.
class Chassis {
 public:
  virtual ~Chassis() = default;
  virtual double yaw_rad() const = 0;                           // IMU, 0 east, counter-clockwise
  virtual WheelAngles wheel_angles() const = 0;                // the encoders
  virtual std::optional<mapping::Point> gps() const = 0;       // nothing without a GPS
  virtual double max_wheel_speed_rad_s() const = 0;            // the slower motor's maximum
  virtual void set_wheel_speeds(double left_rad_s, double right_rad_s) = 0;
};

// Chassis over webots:: devices: motors and encoders by name, the IMU, the GPS when the
// profile names one and the robot has it.
class WebotsChassis final : public Chassis {
 public:
  // Throws common::InputError naming a required device the robot lacks.
  WebotsChassis(webots::Robot &robot, const DeviceNames &devices);
  // Enables the sensors every time_step_ms; the motors in velocity control, at rest.
  void enable(int time_step_ms);
  double yaw_rad() const override;
  WheelAngles wheel_angles() const override;
  std::optional<mapping::Point> gps() const override;
  double max_wheel_speed_rad_s() const override;
  void set_wheel_speeds(double left_rad_s, double right_rad_s) override;

 private:
  webots::Motor *left_;
  webots::Motor *right_;
  webots::PositionSensor *left_encoder_;
  webots::PositionSensor *right_encoder_;
  webots::InertialUnit *imu_;
  webots::GPS *gps_;  // optional
};

class Drive {
 public:
  // The chassis must outlive the Drive; options validated by the caller.
  Drive(Chassis &chassis, const MotionOptions &options, int time_step_ms, StepFunction step);

  double yaw_rad() const { return chassis_.yaw_rad(); }
  std::optional<mapping::Point> gps() const { return chassis_.gps(); }

  // Stops the wheels and takes one step (Action::rest).
  Motion come_to_rest();
  // Turns in place to heading h; comes to rest when it moved. moved() tells whether it did.
  Motion turn_to(mapping::Heading h);
  bool moved() const { return moved_; }
  // Drives along heading h (backwards when the target is behind) to `target`, distance_m away
  // by the encoders when there is no GPS, then comes to rest. after_step runs after every
  // step. `what` names the target in the no-progress message.
  Motion drive_to(mapping::Point target, mapping::Heading h, double distance_m, std::string_view what,
                  const std::function<void()> &after_step = {});
  // As drive_to, with the speed also capped by a trapezoidal profile: from rest, up by
  // ramp_acceleration_m_s2 each second to ramp_top_speed_m_s, and down so as to stop at the
  // target (v <= sqrt(2 a d)). Needs the ramp options set.
  Motion drive_ramped(mapping::Point target, mapping::Heading h, double distance_m, std::string_view what);
  // Continuous space (the room controller): turns in place to a yaw (rad, the conventions),
  // coming to rest when it moved; drives along yaw_rad to `target` (backwards when it is
  // behind), distance_m away by the encoders without a GPS, then comes to rest. The drive
  // also ends, at rest, when stop() (asked before every step, when set) says so.
  Motion turn_to_yaw(double yaw_rad);
  Motion drive_along(mapping::Point target, double yaw_rad, double distance_m, std::string_view what,
                     const std::function<void()> &after_step, const std::function<bool()> &stop);
  // Creeps forward along heading h from `centre` until stop() (asked before every step) or
  // limit_m along; stays moving (the caller comes to rest). `what` names it when it stalls.
  Motion creep(mapping::Heading h, mapping::Point centre, double limit_m, std::string_view what,
               const std::function<bool()> &stop);
  // Distance by the encoders since the last drive or creep began, m.
  double travelled_m() const;
  // What made no progress (after Motion::no_progress).
  const std::string &failure() const { return failure_; }

  // The loop's commands, shared by every leg: v = drive_gain * remaining / dt and
  // w = turn_gain * heading_error / dt, capped.
  double speed_m_s(double remaining_m) const;
  // drive_ramped's command: speed_m_s's proportional law, capped by the motors (not the
  // cruise speed), the ramp's top speed, last_m_s plus one step's acceleration, and the
  // speed that still stops at the target, sqrt(2 a remaining).
  double ramped_speed_m_s(double remaining_m, double last_m_s) const;
  double turn_rate_rad_s(double heading_error_rad) const;
  // The heading error driving along heading h with `offset_m` to the left of the line.
  double heading_error_rad(mapping::Heading h, double offset_m) const;
  double heading_error_rad(double target_yaw_rad, double offset_m) const;

 private:
  template <typename Leg>
  Motion follow(Leg &leg, Action action);
  void set_body(double v_m_s, double w_rad_s);
  void start_odometry();

  Chassis &chassis_;
  const MotionOptions &options_;
  StepFunction step_;
  double dt_s_;
  double max_wheel_rad_s_;
  double max_v_m_s_;
  double max_w_rad_s_;
  WheelAngles start_angles_;
  bool moved_ = false;
  std::string failure_;
};

}  // namespace robot
