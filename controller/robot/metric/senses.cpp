#include "robot/metric/senses.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include <webots/DistanceSensor.hpp>
#include <webots/TouchSensor.hpp>

#include "common/angles.hpp"
#include "common/error.hpp"

namespace robot {
namespace {

// The marks' two levels: the set-up's own numbers (pie's), else the sensor model's.
sensing::MetricMarks marks_for(const sensing::SetUp &setup, const mapping::SensorModelOptions &sensor) {
  const sensing::MarkProbabilities p = sensing::probabilities_in_effect(setup, sensor);
  return {p.p_occ, p.p_free};
}

}  // namespace

MetricSenses::MetricSenses(webots::Robot &robot, const ControllerOptions &options, sensing::MetricMap &map)
    : options_(options),
      map_(map),
      setup_(sensing::setup(options.model.kind)),
      bump_depth_options_(map.bump_depth_options()),
      devices_(robot, options, setup_),
      filter_(options.scan_filter),
      marks_(marks_for(setup_, options.sensor)) {
  if (setup_.reads_bumpers()) find_bumpers(options.sensing.bumpers);
  if (setup_.reads_ranges() && setup_.metres_range_mark == nullptr) {
    if (options.sensing.ranges.size() != sensing::kDepthRays) {
      throw common::InputError(fmt::format("the depth set-up in a room needs {} depth rays; the robot has {}",
                                           sensing::kDepthRays, options.sensing.ranges.size()));
    }
    read_depth_mounts(options.sensing.ranges);
  }
}

// The bump marks' bumpers: right, left and front (+-45 deg and 0), as the homework's log has.
void MetricSenses::find_bumpers(const std::vector<BumperMount> &mounts) {
  for (std::size_t i = 0; i < mounts.size(); ++i) {
    const double a = mounts[i].angle_rad;
    const int side = std::abs(a) < 0.1 ? 2 : (a > 0 ? 1 : 0);
    bumper_of_side_[side] = static_cast<int>(i);
    bump_depth_options_.bump_radius_m = mounts[i].offset_m;
  }
  if (mounts.size() != 3 || bumper_of_side_[0] < 0 || bumper_of_side_[1] < 0 || bumper_of_side_[2] < 0) {
    throw common::InputError(fmt::format(
        "the bump set-up in a room needs three bumpers, front and +-45 deg (the homework's); the robot has {}",
        mounts.size()));
  }
}

// The depth marks' options for these rays (sensing/bump_depth_marks.hpp): their angles, and
// either the range from the centre (rays on the rim: the reading plus the rim's offset) or,
// from a common origin, the reading itself as the rays say it (range or axial); a reading at
// depth_max is ignored.
void MetricSenses::read_depth_mounts(const std::vector<RangeSensorMount> &mounts) {
  const RangeSensorMount &first = mounts.front();
  for (std::size_t i = 0; i < mounts.size(); ++i) {
    const RangeSensorMount &m = mounts[i];
    const bool same_origin = m.origin.has_value() == first.origin.has_value() &&
                             (!m.origin || (m.origin->x_m == first.origin->x_m && m.origin->y_m == first.origin->y_m));
    if (!same_origin || m.axial != first.axial) {
      throw common::InputError("the depth set-up in a room needs its nine rays read alike: from one origin, all axial or none");
    }
    bump_depth_options_.depth_angles_deg[i] = m.angle_rad * 180.0 / std::numbers::pi;
    bump_depth_options_.depth_max_m = m.max_range_m + (m.origin ? 0.0 : m.offset_m);
  }
  bump_depth_options_.depth_reading = first.axial ? sensing::DepthReading::axial : sensing::DepthReading::range;
  if (first.origin) {
    bump_depth_options_.depth_origin_x_m = first.origin->x_m;
    bump_depth_options_.depth_origin_y_m = first.origin->y_m;
  }
}

void MetricSenses::enable(int time_step_ms) { devices_.enable(time_step_ms); }

bool MetricSenses::nothing_seen_marks_nothing() const {
  if (setup_.kind != sensing::ModelKind::cone) return false;
  return std::any_of(devices_.range_sensors.begin(), devices_.range_sensors.end(), [](const webots::DistanceSensor *d) {
    return d->getType() == webots::DistanceSensor::SONAR;
  });
}

void MetricSenses::read_ranges(mapping::Point centre, double yaw_rad) {
  read_range_sensors(devices_.range_sensors, options_.sensing.ranges, centre, yaw_rad, readings_);
  clearance_ahead_m_ = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < readings_.size(); ++i) {
    const RangeSensorMount &m = options_.sensing.ranges[i];
    const double value = readings_[i].range_m;
    if (std::abs(m.angle_rad) <= kAheadHalfAngle_rad && value > 0.0 && value < m.max_range_m) {
      const sensing::RangeReading &r = readings_[i];
      const double from_centre = m.origin ? std::hypot(r.origin.x_m + value * std::cos(r.angle_rad) - centre.x_m,
                                                       r.origin.y_m + value * std::sin(r.angle_rad) - centre.y_m)
                                          : value + m.offset_m;
      clearance_ahead_m_ = std::min(clearance_ahead_m_, from_centre);
    }
  }
}

std::size_t MetricSenses::scan(mapping::Point centre, double yaw_rad, double time_s) {
  pose_step_ = {};
  pose_step_.t = time_s;
  pose_step_.x_m = centre.x_m;
  pose_step_.y_m = centre.y_m;
  pose_step_.theta_rad = yaw_rad;
  if (setup_.reads_lidar()) {
    const sensing::LidarScan filtered = filter_.apply(lidar_scan(*devices_.lidar, centre, yaw_rad));
    clearance_ahead_m_ = std::numeric_limits<double>::infinity();
    for (int n = 0; n < filtered.beam_count(); ++n) {
      if (filtered.kind(n) != sensing::ReadingKind::hit) continue;
      if (std::abs(common::wrap_angle_rad(filtered.beam_angle_rad(n))) > kAheadHalfAngle_rad) continue;
      clearance_ahead_m_ = std::min(clearance_ahead_m_, static_cast<double>(filtered.ranges[static_cast<std::size_t>(n)]));
    }
    sensing::mark_metric_lidar(map_, filtered, marks_);
    return marks_.apply(map_);
  }
  if (setup_.metres_range_mark != nullptr) {
    read_ranges(centre, yaw_rad);
    setup_.metres_range_mark(map_, options_.sensing.range_model, readings_, marks_);
    return marks_.apply(map_);
  }
  // The pose log's marks: the bumpers pressed, or the depth rays' readings.
  if (setup_.reads_bumpers()) {
    pose_step_.bump_right = devices_.bumpers[static_cast<std::size_t>(bumper_of_side_[0])]->getValue() > 0.5;
    pose_step_.bump_left = devices_.bumpers[static_cast<std::size_t>(bumper_of_side_[1])]->getValue() > 0.5;
    pose_step_.bump_front = devices_.bumpers[static_cast<std::size_t>(bumper_of_side_[2])]->getValue() > 0.5;
    bumped_ = pose_step_.bump_right || pose_step_.bump_left || pose_step_.bump_front;
  } else {
    read_depth_rays(centre, yaw_rad);
  }
  sensing::apply_bump_depth_marks(bump_depth_options_,
                                  setup_.reads_bumpers() ? sensing::BumpDepthSensor::bump : sensing::BumpDepthSensor::depth,
                                  pose_step_, map_.log_grid());
  return 1;
}

void MetricSenses::read_depth_rays(mapping::Point centre, double yaw_rad) {
  read_ranges(centre, yaw_rad);
  for (std::size_t i = 0; i < readings_.size(); ++i) {
    // the depth marks' reading: from the centre along the ray, or from the rays' origin as the device says it
    const RangeSensorMount &m = options_.sensing.ranges[i];
    pose_step_.depth_m[i] = m.origin ? devices_.range_sensors[i]->getValue() : readings_[i].range_m + m.offset_m;
  }
}

}  // namespace robot
