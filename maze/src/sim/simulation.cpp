#include "maze/sim/simulation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

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

namespace maze::sim {

namespace {

void require_non_negative(double value, const char *what) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw common::InputError(fmt::format("{} must be a finite number >= 0 (got {})", what, value));
  }
}

void require_fraction(double value, const char *what) {
  if (!(value >= 0.0 && value <= 1.0)) {
    throw common::InputError(fmt::format("{} must be a fraction from 0 to 1 (got {})", what, value));
  }
}

}  // namespace

void SimulationOptions::validate() const {
  if (basic_time_step_ms <= 0) {
    throw common::InputError(
        fmt::format("the basic time step must be at least 1 ms (got {})", basic_time_step_ms));
  }
  require_non_negative(time_limit_s, "the time limit");
  if (noise) require_non_negative(*noise, "--noise");
  require_non_negative(gps_noise_m, "the GPS noise");
  require_non_negative(imu_noise_rad, "the IMU noise");
  require_non_negative(encoder_noise_rad, "the encoder noise");
  require_fraction(dropout, "--dropout");
  require_fraction(spikes, "--spikes");
  require_fraction(wheel_slip, "--wheel-slip");
  if (dropout + spikes > 1.0) {
    throw common::InputError(fmt::format(
        "--dropout and --spikes together must be at most 1 (got {} + {})", dropout, spikes));
  }
}

}  // namespace maze::sim

namespace webots::embedded {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Salts the seed of the fault draws so they are independent of the noise's.
constexpr std::uint64_t kFaultSalt = 0x6a09e667f3bcc909ULL;

void check_stuck_bumper(const maze::sim::RobotProfile &profile, const std::string &name) {
  if (name.empty()) return;
  std::string known;
  for (const maze::sim::BumperSpec &b : profile.bumpers) {
    if (b.name == name) return;
    known += (known.empty() ? "" : ", ") + b.name;
  }
  throw common::InputError(fmt::format("--stuck-bumper: the robot {} has no bumper named '{}' ({})",
                                       profile.name, name,
                                       known.empty() ? "it has none" : "it has " + known));
}

maze::sim::Pose start_pose(const maze::Maze &maze) {
  const double s = maze.cell_size_m();
  return {maze.origin_x_m() + (maze.start().x + 0.5) * s,
          maze.origin_y_m() + (maze.start().y + 0.5) * s, common::compass_yaw_rad(static_cast<int>(maze.start_heading()))};
}

maze::sim::Pose start_pose(const maze::Arena &arena) {
  const maze::ArenaPose p = arena.start();
  return {p.x_m, p.y_m, p.yaw_rad};
}

thread_local Simulation *g_current = nullptr;

}  // namespace

Simulation *current_simulation() { return g_current; }

CurrentSimulation::CurrentSimulation(Simulation &simulation) : previous_(g_current) {
  g_current = &simulation;
}

CurrentSimulation::~CurrentSimulation() { g_current = previous_; }

template <typename D>
void Simulation::add_device(const std::string &name, Kind kind, int spec) {
  if (name.empty()) return;
  const int index = static_cast<int>(states_.size());
  states_.push_back({kind, spec, 0, -1, -1, {}, {}, {}, {0.0, 0.0, 0.0}});
  devices_.push_back(std::unique_ptr<Device>(new D(name, *this, index)));
}

Simulation::Simulation(const maze::World &world, const maze::sim::RobotProfile &profile,
                       const maze::sim::SimulationOptions &options)
    : profile_(profile), options_(options) {
  const maze::Maze *lattice = world.lattice();
  if (lattice != nullptr && lattice->landmarks().empty()) {
    lattice_ = *lattice;
    walls_.emplace(*lattice);
    pose_ = options.start.value_or(start_pose(*lattice));
  } else {
    use_geometry(world.geometry());
    initial_geometry_ = geometry_;
    pose_ = options.start.value_or(start_pose(*geometry_));
  }
  set_up();
}

void Simulation::set_up() {
  initial_pose_ = pose_;
  lidar_planes_.place(geometry(), lattice(), profile_, height_m_);
  options_.validate();
  basic_step_s_ = options_.basic_time_step_ms / 1000.0;
  // A limit past what the millisecond clock counts (about 292 million years) is none.
  const double limit_ms = options_.time_limit_s * 1000.0;
  time_limit_ms_ = limit_ms < 9.0e18 ? static_cast<std::int64_t>(std::llround(limit_ms)) : 0;
  check_stuck_bumper(profile_, options_.stuck_bumper);
  const bool overlaps = with_solids([&](const auto &solids) {
    maze::sim::check_pose_free(solids, pose_);
    for (const maze::sim::Contact &c : solids.contacts(pose_.x_m, pose_.y_m, profile_.body_radius_m)) {
      if (c.distance_m < profile_.body_radius_m - 1e-9) return true;
    }
    return false;
  });
  if (overlaps) {
    throw common::InputError(fmt::format("the robot's body (radius {} m) overlaps {} at ({}, {})",
                                         profile_.body_radius_m, solids_ ? "an obstacle" : "a wall", pose_.x_m,
                                         pose_.y_m));
  }
  for (const maze::sim::LidarSpec &spec : profile_.lidars) {
    lidar_models_.emplace_back(spec);
    lidar_sweeps_.emplace_back();
    if (spec.frequency_hz > 0.0) {
      lidar_sweeps_.back().emplace(lidar_models_.back(), spec.frequency_hz * options_.basic_time_step_ms / 1000.0);
      // A beam holds a reading at most one revolution (and one step) old.
      const double steps_per_revolution = 1000.0 / (spec.frequency_hz * options_.basic_time_step_ms);
      history_steps_ = std::max(history_steps_, static_cast<std::size_t>(std::ceil(steps_per_revolution)) + 1);
    }
  }
  if (history_steps_ > 0) history_.push_back({0, pose_});
  for (int i = 0; i < static_cast<int>(profile_.lidars.size()); ++i) {
    add_device<Lidar>(profile_.lidars[static_cast<std::size_t>(i)].name, Kind::lidar, i);
  }
  add_device<Motor>(profile_.left_motor, Kind::motor, kLeftWheel);
  add_device<Motor>(profile_.right_motor, Kind::motor, kRightWheel);
  add_device<PositionSensor>(profile_.left_encoder, Kind::encoder, kLeftWheel);
  add_device<PositionSensor>(profile_.right_encoder, Kind::encoder, kRightWheel);
  add_device<InertialUnit>(profile_.imu, Kind::imu, 0);
  add_device<GPS>(profile_.gps, Kind::gps, 0);
  for (int i = 0; i < static_cast<int>(profile_.bumpers.size()); ++i) {
    add_device<TouchSensor>(profile_.bumpers[static_cast<std::size_t>(i)].name, Kind::touch, i);
  }
  for (int i = 0; i < static_cast<int>(profile_.distance_sensors.size()); ++i) {
    add_device<DistanceSensor>(profile_.distance_sensors[static_cast<std::size_t>(i)].name,
                               Kind::distance, i);
  }
  // A Webots motor starts in position control at position 0, at up to its maximum velocity.
  for (Wheel &w : wheels_) w.velocity_rad_s = profile_.max_wheel_velocity_rad_s;
  robot_ = std::unique_ptr<Robot>(new Robot(*this));
}

Simulation::~Simulation() = default;

Device *Simulation::device(const std::string &name) {
  for (const auto &d : devices_) {
    if (d->getName() == name) return d.get();
  }
  return nullptr;
}

int Simulation::step(int duration_ms) {
  if (stop_requested_ || ended_) return -1;
  const int basic = options_.basic_time_step_ms;
  if (duration_ms <= 0) return 0;  // no time passes
  const int count = duration_ms / basic + (duration_ms % basic != 0 ? 1 : 0);
  const std::int64_t limit_ms = time_limit_ms_;
  for (int i = 0; i < count; ++i) {
    advance(basic_step_s_);
    if (collisions_.touching_this_step && !collisions_.touching_last_step) ++collisions_.count;
    collisions_.touching_last_step = collisions_.touching_this_step;
    collisions_.touching_this_step = false;
    time_ms_ += basic;
    ++steps_;
    if (history_steps_ > 0) {
      if (history_.size() == history_steps_) history_.erase(history_.begin());
      history_.push_back({steps_, pose_});
    }
    if (limit_ms > 0 && steps_ * basic >= limit_ms) {  // the run's whole time: a reset leaves it
      ended_ = true;
      return -1;
    }
  }
  return stop_requested_ ? -1 : 0;
}

int Simulation::sampling_period(int device) const {
  return states_[static_cast<std::size_t>(device)].sampling_period_ms;
}

void Simulation::read_disabled(DeviceState &state) {
  state.cache[0] = state.cache[1] = state.cache[2] = kNaN;
  state.read_at_step = -1;
}

bool Simulation::fresh(DeviceState &state) {
  if (state.read_at_step == steps_) return true;
  state.read_at_step = steps_;
  return false;
}

common::Rng Simulation::rng_for(int device) const {
  return maze::sim::sensor_rng(options_.seed, device, steps_);
}

double Simulation::lidar_noise(const maze::sim::LidarSpec &spec) const {
  return options_.noise.value_or(spec.noise);
}

const maze::sim::LidarSpec &Simulation::lidar_spec(int device) const {
  return profile_.lidars[static_cast<std::size_t>(states_[static_cast<std::size_t>(device)].spec)];
}

const float *Simulation::lidar_range_image(int device) {
  DeviceState &state = states_[static_cast<std::size_t>(device)];
  if (state.sampling_period_ms == 0) return nullptr;
  const maze::sim::LidarSpec &spec = lidar_spec(device);
  if (spec.frequency_hz > 0.0) {
    if (!fresh(state)) rotating_range_image(device, state, spec);
    return state.ranges.data();
  }
  if (!fresh(state)) {
    state.ranges.resize(static_cast<std::size_t>(spec.horizontal_resolution));
    common::Rng rng = rng_for(device);
    const maze::sim::LidarModel &model = lidar_models_[static_cast<std::size_t>(state.spec)];
    const auto image = [&](const auto &solids) { model.range_image(solids, lidar_noise(spec), pose_, rng, state.ranges); };
    if (const maze::sim::SolidGeometry *above = lidar_planes_.of(state.spec)) {
      image(*above);
    } else {
      with_solids(image);
    }
    lidar_beams_cast_ += spec.horizontal_resolution;
    apply_lidar_faults(device, spec, state.ranges);
  }
  return state.ranges.data();
}

const maze::sim::Pose &Simulation::pose_at_step(std::int64_t step) const {
  for (const PastPose &p : history_) {
    if (p.step == step) return p.pose;
  }
  assert(false && "a rotating lidar's beam is older than the pose history");
  return pose_;
}

void Simulation::rotating_range_image(int device, DeviceState &state, const maze::sim::LidarSpec &spec) {
  if (const maze::sim::SolidGeometry *above = lidar_planes_.of(state.spec)) {
    rotating_range_image_in(*above, device, state, spec);
  } else {
    with_solids([&](const auto &solids) { rotating_range_image_in(solids, device, state, spec); });
  }
}

template <typename Solids>
void Simulation::rotating_range_image_in(const Solids &solids, int device, DeviceState &state,
                                         const maze::sim::LidarSpec &spec) {
  const auto n = static_cast<std::size_t>(spec.horizontal_resolution);
  if (state.beam_steps.size() != n) {
    state.beam_steps.assign(n, -1);
    state.ranges.assign(n, 0.0f);
    state.last_pass.assign(n, 0);
  }
  const std::int64_t steps_enabled = steps_ - state.enabled_at_step;
  lidar_sweeps_[static_cast<std::size_t>(state.spec)]->last_pass_steps(steps_enabled, state.last_pass);
  const maze::sim::LidarModel &model = lidar_models_[static_cast<std::size_t>(state.spec)];
  const double noise = lidar_noise(spec);
  // The viewpoints of the few steps the new beams hold, each computed once.
  std::vector<std::pair<std::int64_t, maze::sim::ViewpointIn<Solids>>> viewpoints;
  const auto viewpoint_at = [&](std::int64_t step) -> const maze::sim::ViewpointIn<Solids> & {
    for (const auto &v : viewpoints) {
      if (v.first == step) return v.second;
    }
    viewpoints.emplace_back(step, maze::sim::LidarModel::viewpoint(solids, pose_at_step(step)));
    return viewpoints.back().second;
  };
  for (std::size_t b = 0; b < n; ++b) {
    const auto i = static_cast<int>(b);
    const std::int64_t s = state.last_pass[b];
    if (s == 0 && state.sweep_resumed) continue;  // not passed since the frequency changed
    const std::int64_t step = s == 0 ? 0 : state.enabled_at_step + s;
    if (state.beam_steps[b] == step) continue;  // the head has not passed it since
    state.beam_steps[b] = step;
    if (s == 0) {
      state.ranges[b] = 0.0f;
      continue;
    }
    const std::uint64_t seed = maze::sim::beam_seed(options_.seed, device, step, i);
    const float range = model.beam_range(solids, noise, viewpoint_at(step), i, seed);
    ++lidar_beams_cast_;
    state.ranges[b] = faulty_beam(device, spec, step, i, range);
  }
}

float Simulation::faulty_beam(int device, const maze::sim::LidarSpec &spec, std::int64_t step,
                              int beam, float range) const {
  if (options_.dropout <= 0.0 && options_.spikes <= 0.0) return range;
  common::Rng rng = maze::sim::beam_rng(options_.seed ^ kFaultSalt, device, step, beam);
  const double u = rng.uniform01();
  const double spike_m = rng.uniform(spec.min_range_m, spec.max_range_m);
  if (u < options_.dropout) return std::numeric_limits<float>::infinity();
  if (u < options_.dropout + options_.spikes) return static_cast<float>(spike_m);
  return range;
}

void Simulation::apply_lidar_faults(int device, const maze::sim::LidarSpec &spec,
                                    std::vector<float> &ranges) const {
  if (options_.dropout <= 0.0 && options_.spikes <= 0.0) return;
  common::Rng rng = maze::sim::sensor_rng(options_.seed ^ kFaultSalt, device, steps_);
  for (float &r : ranges) {
    const double u = rng.uniform01();
    const double spike_m = rng.uniform(spec.min_range_m, spec.max_range_m);
    if (u < options_.dropout) {
      r = std::numeric_limits<float>::infinity();
    } else if (u < options_.dropout + options_.spikes) {
      r = static_cast<float>(spike_m);
    }
  }
}

void Simulation::motor_set_position(int device, double position_rad) {
  wheels_[states_[static_cast<std::size_t>(device)].spec].target_rad = position_rad;
}

void Simulation::motor_set_velocity(int device, double velocity_rad_s) {
  // Webots clamps a velocity above the maximum (with a warning).
  const double max = profile_.max_wheel_velocity_rad_s;
  wheels_[states_[static_cast<std::size_t>(device)].spec].velocity_rad_s =
      std::clamp(velocity_rad_s, -max, max);
}

double Simulation::motor_velocity(int device) const {
  return wheels_[states_[static_cast<std::size_t>(device)].spec].velocity_rad_s;
}

double Simulation::encoder_value(int device) {
  DeviceState &state = states_[static_cast<std::size_t>(device)];
  if (state.sampling_period_ms == 0) return kNaN;
  if (!fresh(state)) {
    // The random stream is made only when it is drawn from (seeding it costs).
    const double angle = wheels_[state.spec].angle_rad;
    state.cache[0] = options_.encoder_noise_rad > 0.0
                         ? angle + rng_for(device).normal(0.0, options_.encoder_noise_rad)
                         : angle;
  }
  return state.cache[0];
}

const double *Simulation::imu_roll_pitch_yaw(int device) {
  DeviceState &state = states_[static_cast<std::size_t>(device)];
  if (state.sampling_period_ms == 0) {
    read_disabled(state);
  } else if (!fresh(state)) {
    double yaw = pose_.yaw_rad;
    if (options_.imu_noise_rad > 0.0) yaw += rng_for(device).normal(0.0, options_.imu_noise_rad);
    state.cache[0] = 0.0;
    state.cache[1] = 0.0;
    state.cache[2] = common::wrap_angle_rad(yaw);
  }
  return state.cache;
}

const double *Simulation::gps_values(int device) {
  DeviceState &state = states_[static_cast<std::size_t>(device)];
  if (state.sampling_period_ms == 0) {
    read_disabled(state);
  } else if (!fresh(state)) {
    const double sigma = options_.gps_noise_m;
    state.cache[0] = pose_.x_m;
    state.cache[1] = pose_.y_m;
    state.cache[2] = height_m_;
    if (sigma > 0.0) {
      common::Rng rng = rng_for(device);
      state.cache[0] += rng.normal(0.0, sigma);
      state.cache[1] += rng.normal(0.0, sigma);
      state.cache[2] += rng.normal(0.0, sigma);
    }
  }
  return state.cache;
}

double Simulation::touch_value(int device) {
  const DeviceState &state = states_[static_cast<std::size_t>(device)];
  if (state.sampling_period_ms == 0) return kNaN;
  const maze::sim::BumperSpec &bumper = profile_.bumpers[static_cast<std::size_t>(state.spec)];
  if (bumper.name == options_.stuck_bumper) return 1.0;
  const bool pressed = with_solids(
      [&](const auto &solids) { return maze::sim::bumper_pressed(solids, bumper, profile_.body_radius_m, pose_); });
  return pressed ? 1.0 : 0.0;
}

const maze::sim::DistanceSensorSpec &Simulation::distance_spec(int device) const {
  return profile_.distance_sensors[static_cast<std::size_t>(
      states_[static_cast<std::size_t>(device)].spec)];
}

double Simulation::distance_value(int device) {
  DeviceState &state = states_[static_cast<std::size_t>(device)];
  if (state.sampling_period_ms == 0) return kNaN;
  if (!fresh(state)) {
    common::Rng rng = rng_for(device);
    const bool noisy = !(options_.noise && *options_.noise == 0.0);
    const maze::sim::DistanceSensorSpec &sensor = distance_spec(device);
    state.cache[0] = with_solids([&](const auto &solids) {
      return maze::sim::distance_sensor_value(solids, sensor, profile_.body_radius_m, pose_, noisy, rng);
    });
  }
  return state.cache[0];
}

}  // namespace webots::embedded
