#include "robot/cell_controller.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <span>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include <webots/GPS.hpp>
#include <webots/InertialUnit.hpp>
#include <webots/Lidar.hpp>
#include <webots/Motor.hpp>
#include <webots/PositionSensor.hpp>
#include <webots/Robot.hpp>

#include "common/error.hpp"
#include "mapping/scan.hpp"
#include "mapping/walls.hpp"

namespace robot {

using mapping::Cell;
using mapping::Heading;
using mapping::Point;

namespace {

enum class Motion { ok, max_steps, no_progress, ended, stopped };

template <typename Device>
Device *require(Device *device, const std::string &name) {
  if (device == nullptr) {
    throw common::InputError(fmt::format("the robot has no device \"{}\"", name));
  }
  return device;
}

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

}  // namespace

struct CellController::Impl {
  Impl(webots::Robot &r, const ControllerOptions &o)
      : robot(r),
        options((validate(o), o)),
        model(o.sensor),
        initial(static_cast<float>(model.prior_log_odds())),
        grid(o.geometry, initial),
        visits(o.geometry.width_cells, o.geometry.height_cells),
        explorer(explore::ExplorerOptions{o.strategy, o.geometry.width_cells,
                                          o.geometry.height_cells, o.start, o.goals}) {
    const DeviceNames &d = options.devices;
    left = require(robot.getMotor(d.left_motor), d.left_motor);
    right = require(robot.getMotor(d.right_motor), d.right_motor);
    left_encoder = require(robot.getPositionSensor(d.left_encoder), d.left_encoder);
    right_encoder = require(robot.getPositionSensor(d.right_encoder), d.right_encoder);
    imu = require(robot.getInertialUnit(d.imu), d.imu);
    lidar = require(robot.getLidar(d.lidar), d.lidar);
    gps = robot.getGPS(d.gps);
    time_step_ms = options.motion.time_step_ms > 0
                       ? options.motion.time_step_ms
                       : static_cast<int>(std::lround(robot.getBasicTimeStep()));
    dt_s = time_step_ms / 1000.0;
    max_wheel_rad_s = std::min(left->getMaxVelocity(), right->getMaxVelocity());
  }

  void enable_devices() {
    left_encoder->enable(time_step_ms);
    right_encoder->enable(time_step_ms);
    imu->enable(time_step_ms);
    lidar->enable(time_step_ms);
    if (gps != nullptr) gps->enable(time_step_ms);
    left->setPosition(INFINITY);
    right->setPosition(INFINITY);
    set_wheels(0.0, 0.0);
  }

  Motion step(Action action) {
    if (!flush_step()) return Motion::stopped;
    if (steps >= options.motion.max_steps) return Motion::max_steps;
    if (robot.step(time_step_ms) == -1) return Motion::ended;
    ++steps;
    if (hooks.on_step) {
      pending = StepReport{steps, robot.getTime(), cell, heading, action, 0, &grid, &visits};
      has_pending = true;
    }
    return Motion::ok;
  }

  // Reports the last step (once its scan, if any, is done); false when the observer stops.
  bool flush_step() {
    if (!has_pending) return true;
    has_pending = false;
    return hooks.on_step(pending);
  }

  double yaw() const { return imu->getRollPitchYaw()[2]; }
  Point gps_point() const {
    const double *v = gps->getValues();
    return {v[0], v[1]};
  }
  double travelled_m() const {
    return options.motion.wheel_radius_m *
           ((left_encoder->getValue() - left0) + (right_encoder->getValue() - right0)) / 2.0;
  }

  // Wheel speeds (rad/s), scaled down together when one exceeds the motors' maximum.
  void set_wheels(double l, double r) {
    const double biggest = std::max(std::abs(l), std::abs(r));
    if (biggest > max_wheel_rad_s && biggest > 0.0) {
      l *= max_wheel_rad_s / biggest;
      r *= max_wheel_rad_s / biggest;
    }
    left->setVelocity(l);
    right->setVelocity(r);
  }

  // Robot velocities: linear v (m/s), angular w (rad/s, counter-clockwise positive).
  void set_body(double v_m_s, double w_rad_s) {
    const MotionOptions &m = options.motion;
    const double half = w_rad_s * m.axle_m / 2.0;
    set_wheels((v_m_s - half) / m.wheel_radius_m, (v_m_s + half) / m.wheel_radius_m);
  }

  Motion come_to_rest() {
    set_wheels(0.0, 0.0);
    return step(Action::rest);
  }

  Motion turn_to(Heading h) {
    const MotionOptions &m = options.motion;
    const double target = mapping::yaw_rad(h);
    const double max_w = std::min(m.turn_speed_rad_s, max_wheel_rad_s) * 2.0 * m.wheel_radius_m / m.axle_m;
    StallWatch watch(0.0, m.stall_epsilon, m.stall_steps);
    double turned = 0.0;
    double last = yaw();
    bool moved = false;
    for (;;) {
      const double error = mapping::wrap_angle_rad(target - yaw());
      if (std::abs(error) < m.yaw_tolerance_rad) break;
      const double w = std::min(m.turn_gain * std::abs(error) / dt_s, max_w);
      set_body(0.0, std::copysign(w, error));
      moved = true;
      if (const Motion s = step(Action::turn); s != Motion::ok) return s;
      turned += mapping::wrap_angle_rad(yaw() - last);
      last = yaw();
      if (watch.stalled(turned)) {
        message = fmt::format("turning to {} made no progress for {} steps (yaw {:.4f} rad)",
                              mapping::to_char(h), m.stall_steps, yaw());
        return Motion::no_progress;
      }
    }
    return moved ? come_to_rest() : Motion::ok;
  }

  Motion drive_to(Cell target_cell, Heading h) {
    const MotionOptions &m = options.motion;
    const Point target = grid.centre_of(target_cell);
    const double dir_x = mapping::dx(h);
    const double dir_y = mapping::dy(h);
    const double target_yaw = mapping::yaw_rad(h);
    const double max_v = std::min(m.cruise_speed_rad_s, max_wheel_rad_s) * m.wheel_radius_m;
    const double max_w = std::min(m.turn_speed_rad_s, max_wheel_rad_s) * 2.0 * m.wheel_radius_m / m.axle_m;
    left0 = left_encoder->getValue();
    right0 = right_encoder->getValue();
    const double distance_m = options.geometry.cell_size_m;
    const auto remaining_and_offset = [&]() -> std::pair<double, double> {
      if (gps == nullptr) return {distance_m - travelled_m(), 0.0};
      const Point p = gps_point();
      const double ex = target.x_m - p.x_m;
      const double ey = target.y_m - p.y_m;
      // Along the heading still to go; offset to the left of the line through the target.
      return {ex * dir_x + ey * dir_y, -(ex * -dir_y + ey * dir_x)};
    };
    auto [remaining, offset] = remaining_and_offset();
    StallWatch watch(remaining, m.stall_epsilon, m.stall_steps);
    while (std::abs(remaining) >= m.position_tolerance_m) {
      const double v = std::clamp(m.drive_gain * remaining / dt_s, -max_v, max_v);
      const double error = mapping::wrap_angle_rad(target_yaw - yaw()) - m.lateral_gain * offset;
      const double w = std::clamp(m.turn_gain * error / dt_s, -max_w, max_w);
      set_body(v, w);
      if (const Motion s = step(Action::drive); s != Motion::ok) return s;
      std::tie(remaining, offset) = remaining_and_offset();
      if (watch.stalled(remaining)) {
        message = fmt::format("driving {} to cell ({},{}) made no progress for {} steps ({:.3f} m to go)",
                              mapping::to_char(h), target_cell.x, target_cell.y, m.stall_steps,
                              remaining);
        return Motion::no_progress;
      }
    }
    return come_to_rest();
  }

  void scan(Cell c) {
    const float *ranges = lidar->getRangeImage();
    if (ranges == nullptr) throw common::RuntimeFailure("the lidar returned no range image");
    mapping::LidarScan s;
    s.origin = gps != nullptr ? gps_point() : grid.centre_of(c);
    s.yaw_rad = yaw();
    s.fov_rad = lidar->getFov();
    s.min_range_m = lidar->getMinRange();
    s.max_range_m = lidar->getMaxRange();
    s.ranges = std::span<const float>(ranges, static_cast<std::size_t>(lidar->getHorizontalResolution()));
    const std::size_t updated = mapping::integrate_scan(options.mapping, grid, s, c, model, update);
    if (has_pending) pending.subcells_updated += updated;
  }

  void notify(const Observer &observer, Cell c, Heading h, bool new_cell) const {
    if (!observer) return;
    observer(MoveReport{steps, moves, robot.getTime(), c, h, new_cell, &grid, &visits});
  }

  EndReason explore(const Observer &observer) {
    enable_devices();
    cell = options.start;
    heading = options.start_heading;
    if (const Motion s = step(Action::start); s != Motion::ok) {
      return s == Motion::ended ? EndReason::simulation_ended : to_reason(s);
    }
    path.push_back(cell);
    visits.record(cell, heading);
    scan(cell);
    notify(observer, cell, heading, true);
    const explore::WallQuery walls = [this](Cell c, Heading h) {
      return mapping::side_state(grid, initial, c, h);
    };
    for (;;) {
      const auto next = explorer.next(cell, heading, walls);
      if (!next) return flush_step() ? EndReason::done : EndReason::stopped;
      Motion s = turn_to(*next);
      if (s == Motion::ok) {
        heading = *next;
        visits.record(cell, heading);
        s = drive_to(mapping::neighbour(cell, heading), heading);
      }
      if (s != Motion::ok) return to_reason(s);
      cell = mapping::neighbour(cell, heading);
      ++moves;
      const bool new_cell = !visits.visited(cell);
      visits.record(cell, heading);
      path.push_back(cell);
      scan(cell);
      notify(observer, cell, heading, new_cell);
    }
  }

  static EndReason to_reason(Motion s) {
    switch (s) {
      case Motion::max_steps: return EndReason::max_steps;
      case Motion::no_progress: return EndReason::no_progress;
      case Motion::ended: return EndReason::simulation_ended;
      case Motion::stopped: return EndReason::stopped;
      case Motion::ok: break;
    }
    assert(false && "not an ending");
    return EndReason::done;
  }

  webots::Robot &robot;
  ControllerOptions options;
  mapping::SensorModel model;
  float initial;
  mapping::OccupancyGrid grid;
  explore::Visits visits;
  explore::Explorer explorer;
  mapping::ScanUpdate update;

  webots::Motor *left = nullptr;
  webots::Motor *right = nullptr;
  webots::PositionSensor *left_encoder = nullptr;
  webots::PositionSensor *right_encoder = nullptr;
  webots::InertialUnit *imu = nullptr;
  webots::Lidar *lidar = nullptr;
  webots::GPS *gps = nullptr;  // optional
  int time_step_ms = 0;
  double dt_s = 0.0;
  double max_wheel_rad_s = 0.0;
  double left0 = 0.0;
  double right0 = 0.0;

  RunHooks hooks;
  StepReport pending;
  bool has_pending = false;
  Cell cell;                  // where the robot is (the cell it left, while it moves)
  Heading heading = Heading::north;

  std::int64_t steps = 0;
  int moves = 0;
  std::vector<Cell> path;
  std::string message;
  bool ran = false;
};

CellController::CellController(webots::Robot &robot, const ControllerOptions &options)
    : impl_(std::make_unique<Impl>(robot, options)) {}

CellController::~CellController() = default;

RunResult CellController::run(const Observer &observer) {
  RunHooks hooks;
  hooks.on_move = observer;
  return run(hooks);
}

RunResult CellController::run(const RunHooks &hooks) {
  Impl &s = *impl_;
  assert(!s.ran && "CellController::run is called once");
  s.ran = true;
  s.hooks = hooks;
  const EndReason reason = s.explore(hooks.on_move);
  if (reason != EndReason::stopped) s.flush_step();
  return RunResult{reason,
                   std::move(s.message),
                   s.steps,
                   s.moves,
                   s.visits.count(),
                   s.robot.getTime(),
                   std::move(s.grid),
                   std::move(s.visits),
                   std::move(s.path)};
}

}  // namespace robot
