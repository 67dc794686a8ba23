#include "robot/cell_controller.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <span>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include <webots/DistanceSensor.hpp>
#include <webots/GPS.hpp>
#include <webots/InertialUnit.hpp>
#include <webots/Lidar.hpp>
#include <webots/Motor.hpp>
#include <webots/PositionSensor.hpp>
#include <webots/Robot.hpp>
#include <webots/TouchSensor.hpp>

#include "common/angles.hpp"
#include "common/error.hpp"
#include "sensing/cell_model.hpp"
#include "sensing/scan.hpp"
#include "mapping/walls.hpp"
#include "plan/wavefront.hpp"

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

sensing::LeveledUpdate range_update_for(const ControllerOptions &o) {
  switch (o.model.kind) {
    case sensing::ModelKind::depth: return sensing::make_depth_update();
    case sensing::ModelKind::pie: return sensing::make_pie_update();
    case sensing::ModelKind::cone: return sensing::make_cone_update(o.sensor);
    default: return sensing::make_bump_update();
  }
}

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
    if (sensing::uses_lidar(options.model.kind)) {
      lidar = require(robot.getLidar(d.lidar), d.lidar);
    } else if (options.model.kind == sensing::ModelKind::bump) {
      for (const BumperMount &b : options.sensing.bumpers) {
        bumpers.push_back(require(robot.getTouchSensor(b.name), b.name));
      }
    } else {
      for (const RangeSensorMount &mount : options.sensing.ranges) {
        range_sensors.push_back(require(robot.getDistanceSensor(mount.name), mount.name));
      }
    }
    gps = d.gps.empty() ? nullptr : robot.getGPS(d.gps);  // Webots warns about an unknown name
    time_step_ms = options.motion.time_step_ms > 0
                       ? options.motion.time_step_ms
                       : static_cast<int>(std::lround(robot.getBasicTimeStep()));
    dt_s = time_step_ms / 1000.0;
    max_wheel_rad_s = std::min(left->getMaxVelocity(), right->getMaxVelocity());
    if (lidar != nullptr && lidar->getFrequency() > 0.0) {
      lidar_revolution_steps = static_cast<int>(std::ceil(1000.0 / (lidar->getFrequency() * time_step_ms)));
    }
  }

  void enable_devices() {
    left_encoder->enable(time_step_ms);
    right_encoder->enable(time_step_ms);
    imu->enable(time_step_ms);
    if (lidar != nullptr) lidar->enable(time_step_ms);
    for (webots::TouchSensor *b : bumpers) b->enable(time_step_ms);
    for (webots::DistanceSensor *r : range_sensors) r->enable(time_step_ms);
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
      const double error = common::wrap_angle_rad(target - yaw());
      if (std::abs(error) < m.yaw_tolerance_rad) break;
      const double w = std::min(m.turn_gain * std::abs(error) / dt_s, max_w);
      set_body(0.0, std::copysign(w, error));
      moved = true;
      if (const Motion s = step(Action::turn); s != Motion::ok) return s;
      turned += common::wrap_angle_rad(yaw() - last);
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
    return drive_to_point(grid.centre_of(target_cell), h, options.geometry.cell_size_m,
                          fmt::format("cell ({},{})", target_cell.x, target_cell.y), nullptr);
  }

  // Drives along heading h (backwards when the target is behind) to the point `target`,
  // distance_m away by the encoders when there is no GPS. on_step, when given, runs after
  // every control step.
  Motion drive_to_point(Point target, Heading h, double distance_m, const std::string &what,
                        const std::function<void()> &on_step) {
    const MotionOptions &m = options.motion;
    const double dir_x = mapping::dx(h);
    const double dir_y = mapping::dy(h);
    const double target_yaw = mapping::yaw_rad(h);
    const double max_v = std::min(m.cruise_speed_rad_s, max_wheel_rad_s) * m.wheel_radius_m;
    const double max_w = std::min(m.turn_speed_rad_s, max_wheel_rad_s) * 2.0 * m.wheel_radius_m / m.axle_m;
    left0 = left_encoder->getValue();
    right0 = right_encoder->getValue();
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
      const double error = common::wrap_angle_rad(target_yaw - yaw()) - m.lateral_gain * offset;
      const double w = std::clamp(m.turn_gain * error / dt_s, -max_w, max_w);
      set_body(v, w);
      if (const Motion s = step(Action::drive); s != Motion::ok) return s;
      if (on_step) on_step();
      std::tie(remaining, offset) = remaining_and_offset();
      if (watch.stalled(remaining)) {
        message = fmt::format("driving {} to {} made no progress for {} steps ({:.3f} m to go)",
                              mapping::to_char(h), what, m.stall_steps, remaining);
        return Motion::no_progress;
      }
    }
    return come_to_rest();
  }

  Point position(Cell c) const { return gps != nullptr ? gps_point() : grid.centre_of(c); }

  // A point offset_m from the robot's centre along angle_rad relative to its heading.
  Point mounted(Point centre, double angle_rad, double offset_m) const {
    const double a = yaw() + angle_rad;
    return {centre.x_m + offset_m * std::cos(a), centre.y_m + offset_m * std::sin(a)};
  }

  // The bumpers as read now, marked into bump_update (not applied).
  bool gather_bumps(Cell c) {
    const Point centre = position(c);
    bump_readings.clear();
    bool pressed = false;
    for (std::size_t i = 0; i < bumpers.size(); ++i) {
      const BumperMount &mount = options.sensing.bumpers[i];
      const bool on = bumpers[i]->getValue() > 0.5;
      pressed = pressed || on;
      bump_readings.push_back({mounted(centre, mount.angle_rad, mount.offset_m), on});
    }
    sensing::mark_bumps(grid, centre, bump_readings, bump_update);
    return pressed;
  }

  void read_ranges(Cell c) {
    const Point centre = position(c);
    range_readings.clear();
    for (std::size_t i = 0; i < range_sensors.size(); ++i) {
      const RangeSensorMount &mount = options.sensing.ranges[i];
      range_readings.push_back({mounted(centre, mount.angle_rad, mount.offset_m),
                                yaw() + mount.angle_rad, range_sensors[i]->getValue(), mount.max_range_m,
                                mount.aperture_rad, mount.range_error});
    }
  }

  void scan(Cell c) {
    switch (options.model.kind) {
      case sensing::ModelKind::cell:
      case sensing::ModelKind::ray: scan_lidar(c); return;
      case sensing::ModelKind::bump:
        gather_bumps(c);
        bump_update.apply(grid, model);
        return;
      case sensing::ModelKind::depth:
        read_ranges(c);
        sensing::mark_depth(grid, position(c), range_readings, range_update);
        break;
      case sensing::ModelKind::pie:
        read_ranges(c);
        sensing::mark_pie(grid, options.sensing.range_model, range_readings, range_update);
        break;
      case sensing::ModelKind::cone:
        read_ranges(c);
        sensing::mark_cone(grid, range_readings, range_update);
        break;
    }
    range_update.apply(grid, model);
  }

  // Bump model: feels for the wall on side h of cell c (see the header), then backs to the
  // centre. Each pass is one scan.
  Motion probe(Cell c, Heading h) {
    if (const Motion s = turn_to(h); s != Motion::ok) return s;
    const MotionOptions &m = options.motion;
    const Point centre = grid.centre_of(c);
    const double dir_x = mapping::dx(h);
    const double dir_y = mapping::dy(h);
    const double limit_m = options.geometry.cell_size_m / 2.0 + options.geometry.subcell_size_m() / 2.0;
    const double max_w = std::min(m.turn_speed_rad_s, max_wheel_rad_s) * 2.0 * m.wheel_radius_m / m.axle_m;
    left0 = left_encoder->getValue();
    right0 = right_encoder->getValue();
    const auto along_and_offset = [&]() -> std::pair<double, double> {
      if (gps == nullptr) return {travelled_m(), 0.0};
      const Point p = gps_point();
      const double ex = p.x_m - centre.x_m;
      const double ey = p.y_m - centre.y_m;
      return {ex * dir_x + ey * dir_y, ex * -dir_y + ey * dir_x};
    };
    auto [along, offset] = along_and_offset();
    StallWatch watch(along, m.stall_epsilon, m.stall_steps);
    while (!gather_bumps(c) && along < limit_m) {
      const double error = common::wrap_angle_rad(mapping::yaw_rad(h) - yaw()) - m.lateral_gain * offset;
      set_body(m.creep_speed_m_s, std::clamp(m.turn_gain * error / dt_s, -max_w, max_w));
      if (const Motion s = step(Action::probe); s != Motion::ok) return s;
      std::tie(along, offset) = along_and_offset();
      if (watch.stalled(along)) {
        message = fmt::format("probing {} of cell ({},{}) made no progress for {} steps",
                              mapping::to_char(h), c.x, c.y, m.stall_steps);
        return Motion::no_progress;
      }
    }
    bump_update.apply(grid, model);
    if (const Motion s = come_to_rest(); s != Motion::ok) return s;
    const Motion back = drive_to_point(centre, h, -travelled_m(),
                                       fmt::format("the centre of cell ({},{})", c.x, c.y),
                                       [this, c] { gather_bumps(c); });
    bump_update.apply(grid, model);
    return back;
  }

  // Depth model: the rays fan over the front 120 deg only, and a ray grazing a side frees its
  // band; so in a new cell the robot faces each side in turn (the one it faces first) and
  // scans, which puts the straight-ahead ray on every band middle.
  Motion look_around(Cell c, Heading &facing) {
    for (const Heading h : {mapping::turned_right(facing), mapping::opposite(facing),
                            mapping::turned_left(facing)}) {
      if (const Motion s = turn_to(h); s != Motion::ok) return s;
      facing = h;
      visits.record(c, facing);
      scan(c);
    }
    return Motion::ok;
  }

  // Bump model: probes every side of c that is still unknown (the maze's outer walls too).
  Motion probe_unknown_sides(Cell c, Heading &facing, const explore::WallQuery &walls) {
    for (const Heading h : mapping::kHeadings) {
      if (walls(c, h) != mapping::SideState::unknown) continue;
      if (const Motion s = probe(c, h); s != Motion::ok) return s;
      facing = h;
      visits.record(c, facing);
    }
    return Motion::ok;
  }

  // A rotating lidar fills its range image a slice per step: before a scan, stays at rest
  // for a whole revolution (ceil(period / step) steps), so that every beam is read from here.
  Motion await_lidar_revolution() {
    for (int i = 0; i < lidar_revolution_steps; ++i) {
      if (const Motion s = come_to_rest(); s != Motion::ok) return s;
    }
    return Motion::ok;
  }

  // One control step at rest (a rotating lidar: then a whole revolution), then a scan: the
  // next reading is a new draw of the sensor, not the same one.
  Motion rest_and_scan(Cell c) {
    if (const Motion s = come_to_rest(); s != Motion::ok) return s;
    if (const Motion s = await_lidar_revolution(); s != Motion::ok) return s;
    scan(c);
    return Motion::ok;
  }

  void scan_lidar(Cell c) {
    const float *ranges = lidar->getRangeImage();
    if (ranges == nullptr) throw common::RuntimeFailure("the lidar returned no range image");
    sensing::LidarScan s;
    s.origin = gps != nullptr ? gps_point() : grid.centre_of(c);
    s.yaw_rad = yaw();
    s.fov_rad = lidar->getFov();
    s.min_range_m = lidar->getMinRange();
    s.max_range_m = lidar->getMaxRange();
    s.ranges = std::span<const float>(ranges, static_cast<std::size_t>(lidar->getHorizontalResolution()));
    // A scan before in the same control step is the same reading, not a second look.
    const bool second_look = !previous_scan.ranges.empty() && previous_scan_step < steps;
    const sensing::LidarScan filtered = second_look ? scan_filter.apply(s, previous_scan) : scan_filter.apply(s);
    const std::size_t updated = sensing::integrate_scan(options.model, grid, filtered, c, model, update);
    if (has_pending) pending.subcells_updated += updated;
    // Kept for the next scan's filter: a short view past max range seen again from the same
    // pose is a view, not dropped beams.
    previous_ranges.assign(s.ranges.begin(), s.ranges.end());
    previous_scan = s;
    previous_scan.ranges = previous_ranges;
    previous_scan_step = steps;
  }

  bool unknown(const explore::WallQuery &walls, Cell c, Heading h) const {
    return walls(c, h) == mapping::SideState::unknown;
  }

  // Lidar models and range rings: while a side of c is unknown after its scan (every beam
  // towards it was filtered out as a fault, every range reading about it ignored by the pie
  // model), waits one control step at rest and scans again: the next reading is a new draw of
  // the sensor, not the same faulty one. Then faces each side still unknown and does the
  // same (other beams look at it, and the cell model's beams point straight at it). A side
  // still unknown that leads to a cell inside the maze is listed in `unresolved`.
  Motion resolve_unknown_sides(Cell c, Heading &facing, const explore::WallQuery &walls) {
    const auto unknown_side = [&] {
      return std::ranges::any_of(mapping::kHeadings, [&](Heading h) { return unknown(walls, c, h); });
    };
    const auto rescan_while = [&](const auto &still_unknown) {
      for (int attempt = 0; attempt < options.max_rescans && still_unknown(); ++attempt) {
        if (const Motion s = rest_and_scan(c); s != Motion::ok) return s;
      }
      return Motion::ok;
    };
    if (const Motion s = rescan_while(unknown_side); s != Motion::ok) return s;
    for (const Heading h : mapping::kHeadings) {
      if (!unknown(walls, c, h)) continue;
      const std::int64_t before_turn = steps;
      if (const Motion s = turn_to(h); s != Motion::ok) return s;
      facing = h;
      visits.record(c, facing);
      if (steps > before_turn) {  // else: facing it already, scanned this step
        if (const Motion s = await_lidar_revolution(); s != Motion::ok) return s;
        scan(c);
      }
      if (const Motion s = rescan_while([&] { return unknown(walls, c, h); }); s != Motion::ok) return s;
      const std::pair<Cell, Heading> side{c, h};
      if (unknown(walls, c, h) && grid.contains(mapping::neighbour(c, h)) &&
          std::ranges::find(unresolved, side) == unresolved.end()) {
        unresolved.push_back(side);
      }
    }
    return Motion::ok;
  }

  // Lidar models: a side the grid calls open while the last scan, taken here, reads a wall
  // on it (the cell model's reading: a return within the side plus a quarter cell) is
  // scanned again until the grid agrees: a band freed by a faulty beam from afar (a spike
  // passing its neighbours' test where their own beams were dropped) must not send the
  // robot into the wall. Each scan adds one occupied update; max_rescans * 3 at most.
  Motion confirm_open_sides(Cell c, const explore::WallQuery &walls) {
    for (const Heading h : mapping::kHeadings) {
      for (int attempt = 0; attempt < 3 * options.max_rescans && walls(c, h) == mapping::SideState::open &&
                            sensing::read_cell_side(options.model, grid, previous_scan, c, h) == mapping::SideState::wall;
           ++attempt) {
        if (const Motion s = rest_and_scan(c); s != Motion::ok) return s;
      }
    }
    return Motion::ok;
  }

  // The sides listed as unresolved that are still unknown and lead to a cell never visited,
  // as "E of (3,4), ..." (the first few), or empty.
  std::string unresolved_sides(const explore::WallQuery &walls) const {
    std::string text;
    int count = 0;
    for (const auto &[c, h] : unresolved) {
      if (!unknown(walls, c, h) || visits.visited(mapping::neighbour(c, h))) continue;
      if (++count <= 3) text += fmt::format("{}{} of ({},{})", count > 1 ? ", " : "", mapping::to_char(h), c.x, c.y);
    }
    if (count == 0) return {};
    return fmt::format("{} side{} of visited cells still unknown: {}{}", count, count == 1 ? "" : "s", text,
                       count > 3 ? ", ..." : "");
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
    const explore::WallQuery walls = [this](Cell c, Heading h) {
      return mapping::side_state(grid, initial, c, h, options.occupied_threshold);
    };
    const bool bump = options.model.kind == sensing::ModelKind::bump;
    const bool depth = options.model.kind == sensing::ModelKind::depth;
    const bool ring = options.model.kind == sensing::ModelKind::pie ||
                      options.model.kind == sensing::ModelKind::cone;
    // Scan on arrival (the bump model then probes the unknown sides), then report.
    const auto arrive = [&](bool new_cell) {
      if (const Motion r = await_lidar_revolution(); r != Motion::ok) return r;
      scan(cell);
      Motion s = Motion::ok;
      if (lidar != nullptr || ring) s = resolve_unknown_sides(cell, heading, walls);
      if (s == Motion::ok && lidar != nullptr) s = confirm_open_sides(cell, walls);
      if (bump) s = probe_unknown_sides(cell, heading, walls);
      if (depth && new_cell) s = look_around(cell, heading);
      notify(observer, cell, heading, new_cell);
      return s;
    };
    if (const Motion s = arrive(true); s != Motion::ok) return to_reason(s);
    for (;;) {
      const auto next = explorer.next(cell, heading, walls);
      if (!next) {
        if (!flush_step()) return EndReason::stopped;
        message = unresolved_sides(walls);
        return message.empty() ? EndReason::done : EndReason::incomplete;
      }
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
      if (const Motion a = arrive(new_cell); a != Motion::ok) return to_reason(a);
    }
  }

  // Drives the wavefront path from the robot's cell back to the start, cell by cell, without
  // mapping; keeps `cell` and `heading` current.
  EndReason speed_run() {
    plan::WavefrontOptions known_free;
    known_free.unknown_blocked = true;
    const auto route = plan::wavefront(grid, model, cell, options.start, known_free);
    if (!route) return EndReason::done;
    const double started = robot.getTime();
    int cells = 0;
    const int k = grid.k();
    for (const mapping::SubCell s : route->subcells) {
      const Cell next = mapping::cell_of(s, k);
      if (next == cell) continue;
      for (const Heading h : mapping::kHeadings) {
        if (mapping::neighbour(cell, h) == next) heading = h;
      }
      Motion m = turn_to(heading);
      if (m == Motion::ok) m = drive_to(next, heading);
      if (m != Motion::ok) return to_reason(m);
      cell = next;
      ++cells;
      path.push_back(cell);
      visits.record(cell, heading);
    }
    speed_run_cells = cells;
    speed_run_time_s = robot.getTime() - started;
    return EndReason::done;
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
  sensing::ScanFilter scan_filter{options.scan_filter};
  sensing::LeveledUpdate bump_update = sensing::make_bump_update();
  sensing::LeveledUpdate range_update = range_update_for(options);
  std::vector<sensing::BumpReading> bump_readings;
  std::vector<sensing::RangeReading> range_readings;

  webots::Motor *left = nullptr;
  webots::Motor *right = nullptr;
  webots::PositionSensor *left_encoder = nullptr;
  webots::PositionSensor *right_encoder = nullptr;
  webots::InertialUnit *imu = nullptr;
  webots::Lidar *lidar = nullptr;
  webots::GPS *gps = nullptr;  // optional
  std::vector<webots::TouchSensor *> bumpers;      // bump model, as options.sensing.bumpers
  std::vector<webots::DistanceSensor *> range_sensors;    // depth, pie, cone, as options.sensing.ranges
  int time_step_ms = 0;
  double dt_s = 0.0;
  double max_wheel_rad_s = 0.0;
  int lidar_revolution_steps = 0;  // 0 unless the lidar rotates
  double left0 = 0.0;
  double right0 = 0.0;

  RunHooks hooks;
  StepReport pending;
  bool has_pending = false;
  Cell cell;                  // where the robot is (the cell it left, while it moves)
  Heading heading = Heading::north;

  std::int64_t steps = 0;
  int moves = 0;
  std::optional<double> speed_run_time_s;
  int speed_run_cells = 0;
  std::vector<Cell> path;
  std::string message;
  bool ran = false;
  // The lidar's last raw scan (for the filter's repeated-view rule), its ranges owned here.
  sensing::LidarScan previous_scan;
  std::vector<float> previous_ranges;
  std::int64_t previous_scan_step = 0;
  // Sides the robot looked at in every way it has and still does not know (cell, side).
  std::vector<std::pair<Cell, Heading>> unresolved;
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
  EndReason reason = s.explore(hooks.on_move);
  const double explore_time_s = s.robot.getTime();
  if (reason == EndReason::done && s.options.speed_run) reason = s.speed_run();
  if (reason != EndReason::stopped) s.flush_step();
  return RunResult{reason,
                   std::move(s.message),
                   s.steps,
                   s.moves,
                   s.visits.count(),
                   s.robot.getTime(),
                   std::move(s.grid),
                   std::move(s.visits),
                   std::move(s.path),
                   explore_time_s,
                   s.speed_run_time_s,
                   s.speed_run_cells};
}

}  // namespace robot
