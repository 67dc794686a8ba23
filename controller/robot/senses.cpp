#include "robot/senses.hpp"

#include <cmath>
#include <utility>
#include <variant>

#include <webots/Lidar.hpp>
#include <webots/TouchSensor.hpp>

#include "sensing/cell_model.hpp"

namespace robot {

using mapping::Cell;
using mapping::Point;

Senses::Senses(webots::Robot &robot, const ControllerOptions &options, const Drive &drive,
               mapping::OccupancyGrid &grid, const mapping::SensorModel &model)
    : options_(options),
      setup_(sensing::setup(options.model.kind)),
      drive_(drive),
      grid_(grid),
      model_(model),
      devices_(robot, options, setup_),
      filter_(options.scan_filter) {
  if (setup_.make_update != nullptr) leveled_.emplace(setup_.make_update(options.sensor));
}

void Senses::enable(int time_step_ms) {
  devices_.enable(time_step_ms);
  if (devices_.lidar != nullptr && devices_.lidar->getFrequency() > 0.0) {
    revolution_steps_ = static_cast<int>(std::ceil(1000.0 / (devices_.lidar->getFrequency() * time_step_ms)));
  }
}

void Senses::scan(Cell c, std::int64_t step) {
  std::visit(
      [&](auto mark) {
        using Mark = decltype(mark);
        if constexpr (std::is_same_v<Mark, sensing::LidarMark>) {
          scan_lidar(mark, c, step);
        } else if constexpr (std::is_same_v<Mark, sensing::RangeMark>) {
          scan_ranges(mark, c);
        } else {
          gather_bumps(c);
          apply_bumps();
        }
      },
      setup_.mark);
}

std::size_t Senses::take_lidar_updates() { return std::exchange(lidar_updates_, 0); }

mapping::SideState Senses::reads_side(Cell c, mapping::Heading h) const {
  if (setup_.reads_lidar()) {
    if (previous_scan_.ranges.empty()) return mapping::SideState::unknown;
    return sensing::read_cell_side(options_.model, grid_, previous_scan_, c, h);
  }
  return sensing::read_range_side(grid_, range_readings_, c, h);
}

mapping::SideState Senses::sees_side_ahead(Cell from, Cell c, mapping::Heading h) const {
  if (!setup_.reads_lidar() || previous_scan_.ranges.empty() || previous_scan_cell_ != from) {
    return mapping::SideState::unknown;
  }
  return sensing::read_side_ahead(options_.model, grid_, previous_scan_, c, h);
}

Point Senses::position(Cell c) const { return drive_.gps().value_or(grid_.centre_of(c)); }

Point Senses::mounted(Point centre, double angle_rad, double offset_m) const {
  const double a = drive_.yaw_rad() + angle_rad;
  return {centre.x_m + offset_m * std::cos(a), centre.y_m + offset_m * std::sin(a)};
}

void Senses::scan_lidar(sensing::LidarMark mark, Cell c, std::int64_t step) {
  const sensing::LidarScan s = lidar_scan(*devices_.lidar, position(c), drive_.yaw_rad());
  // A scan before in the same control step is the same reading, not a second look.
  const bool second_look = !previous_scan_.ranges.empty() && previous_scan_step_ < step;
  const sensing::LidarScan filtered = second_look ? filter_.apply(s, previous_scan_) : filter_.apply(s);
  mark(options_.model, grid_, filtered, c, update_);
  lidar_updates_ += update_.apply(grid_, model_);
  // Kept for the next scan's filter: a short view past max range seen again from the same
  // pose is a view, not dropped beams.
  previous_ranges_.assign(s.ranges.begin(), s.ranges.end());
  previous_scan_ = s;
  previous_scan_.ranges = previous_ranges_;
  previous_scan_step_ = step;
  previous_scan_cell_ = c;
}

void Senses::scan_ranges(sensing::RangeMark mark, Cell c) {
  const Point centre = position(c);
  read_range_sensors(devices_.range_sensors, options_.sensing.ranges, centre, drive_.yaw_rad(), range_readings_);
  mark(grid_, options_.sensing.range_model, centre, range_readings_, *leveled_);
  leveled_->apply(grid_, model_);
}

bool Senses::gather_bumps(Cell c) {
  const Point centre = position(c);
  bump_readings_.clear();
  bool pressed = false;
  for (std::size_t i = 0; i < devices_.bumpers.size(); ++i) {
    const BumperMount &m = options_.sensing.bumpers[i];
    const bool on = devices_.bumpers[i]->getValue() > 0.5;
    pressed = pressed || on;
    bump_readings_.push_back({mounted(centre, m.angle_rad, m.offset_m), on});
  }
  std::get<sensing::BumpMark>(setup_.mark)(grid_, centre, bump_readings_, *leveled_);
  return pressed;
}

void Senses::apply_bumps() { leveled_->apply(grid_, model_); }

}  // namespace robot
