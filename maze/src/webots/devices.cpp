// The webots:: device classes of the embedded build: each forwards to the simulation that
// owns it (maze/include/maze/sim/simulation.hpp). A real Webots build links Webots' own
// CppController library instead of this file.

#include <algorithm>
#include <stdexcept>

#include <webots/Device.hpp>
#include <webots/DistanceSensor.hpp>
#include <webots/GPS.hpp>
#include <webots/InertialUnit.hpp>
#include <webots/Lidar.hpp>
#include <webots/Motor.hpp>
#include <webots/PositionSensor.hpp>
#include <webots/Robot.hpp>
#include <webots/TouchSensor.hpp>

#include <fmt/format.h>

#include "common/standard_streams.hpp"
#include "maze/sim/simulation.hpp"

namespace webots {

namespace {
// Webots' Lidar minFrequency and maxFrequency defaults (no robot file here sets them).
constexpr double kLidarMinFrequency_hz = 1.0;
constexpr double kLidarMaxFrequency_hz = 25.0;
}  // namespace

// ---- Device ----

Device::Device(const std::string &name, embedded::Simulation &simulation, int index)
    : name_(name), simulation_(&simulation), index_(index) {}

Device::~Device() = default;

const std::string &Device::getName() const { return name_; }
std::string Device::getModel() const { return simulation_->profile().name; }

// ---- Robot ----

namespace {

embedded::Simulation &require_current() {
  embedded::Simulation *simulation = embedded::current_simulation();
  if (simulation == nullptr) {
    throw std::logic_error(
        "webots::Robot: no simulation is running (the embedded entry point must create a "
        "webots::embedded::CurrentSimulation first)");
  }
  return *simulation;
}

template <typename D>
D *find(embedded::Simulation &simulation, const std::string &name) {
  return dynamic_cast<D *>(simulation.device(name));
}

}  // namespace

Robot::Robot() : simulation_(&require_current()) {}
Robot::Robot(embedded::Simulation &simulation) : simulation_(&simulation) {}
Robot::~Robot() = default;

int Robot::step(int duration) { return simulation_->step(duration); }
double Robot::getTime() const { return static_cast<double>(simulation_->time_ms()) / 1000.0; }
double Robot::getBasicTimeStep() const { return simulation_->basic_time_step_ms(); }
std::string Robot::getName() const { return simulation_->profile().name; }

Lidar *Robot::getLidar(const std::string &name) { return find<Lidar>(*simulation_, name); }
Motor *Robot::getMotor(const std::string &name) { return find<Motor>(*simulation_, name); }
PositionSensor *Robot::getPositionSensor(const std::string &name) {
  return find<PositionSensor>(*simulation_, name);
}
InertialUnit *Robot::getInertialUnit(const std::string &name) {
  return find<InertialUnit>(*simulation_, name);
}
GPS *Robot::getGPS(const std::string &name) { return find<GPS>(*simulation_, name); }
TouchSensor *Robot::getTouchSensor(const std::string &name) {
  return find<TouchSensor>(*simulation_, name);
}
DistanceSensor *Robot::getDistanceSensor(const std::string &name) {
  return find<DistanceSensor>(*simulation_, name);
}
Device *Robot::getDevice(const std::string &name) { return simulation_->device(name); }

// ---- Lidar ----

void Lidar::enable(int samplingPeriod) { simulation().set_sampling_period(index(), samplingPeriod); }
void Lidar::disable() { simulation().set_sampling_period(index(), 0); }
int Lidar::getSamplingPeriod() const { return simulation().sampling_period(index()); }
const float *Lidar::getRangeImage() const { return simulation().lidar_range_image(index()); }
int Lidar::getHorizontalResolution() const {
  return simulation().lidar_spec(index()).horizontal_resolution;
}
int Lidar::getNumberOfLayers() const { return 1; }
double Lidar::getFov() const { return simulation().lidar_spec(index()).fov_rad; }
double Lidar::getMinRange() const { return simulation().lidar_spec(index()).min_range_m; }
double Lidar::getMaxRange() const { return simulation().lidar_spec(index()).max_range_m; }
double Lidar::getFrequency() const { return simulation().lidar_spec(index()).frequency_hz; }
double Lidar::getMinFrequency() const { return kLidarMinFrequency_hz; }
double Lidar::getMaxFrequency() const { return kLidarMaxFrequency_hz; }
void Lidar::setFrequency(double frequency) {
  if (!(frequency >= kLidarMinFrequency_hz && frequency <= kLidarMaxFrequency_hz)) {
    common::print_stderr("Error: wb_lidar_set_frequency() out of frequency range [{:f}, {:f}].\n",
                         kLidarMinFrequency_hz, kLidarMaxFrequency_hz);
    return;
  }
  if (!(getFrequency() > 0.0)) {
    common::print_stderr("Warning: Lidar.setFrequency({}): {} is a fixed lidar: it has no head to turn, the "
                         "call changes nothing\n", frequency, getName());
    return;
  }
  simulation().set_lidar_frequency(index(), frequency);
}

// ---- Motor ----

void Motor::setPosition(double position) { simulation().motor_set_position(index(), position); }
void Motor::setVelocity(double vel) { simulation().motor_set_velocity(index(), vel); }
double Motor::getVelocity() const { return simulation().motor_velocity(index()); }
double Motor::getMaxVelocity() const { return simulation().motor_max_velocity(); }

// ---- PositionSensor ----

void PositionSensor::enable(int samplingPeriod) {
  simulation().set_sampling_period(index(), samplingPeriod);
}
void PositionSensor::disable() { simulation().set_sampling_period(index(), 0); }
int PositionSensor::getSamplingPeriod() const { return simulation().sampling_period(index()); }
double PositionSensor::getValue() const { return simulation().encoder_value(index()); }

// ---- InertialUnit ----

void InertialUnit::enable(int samplingPeriod) {
  simulation().set_sampling_period(index(), samplingPeriod);
}
void InertialUnit::disable() { simulation().set_sampling_period(index(), 0); }
int InertialUnit::getSamplingPeriod() const { return simulation().sampling_period(index()); }
const double *InertialUnit::getRollPitchYaw() const {
  return simulation().imu_roll_pitch_yaw(index());
}

// ---- GPS ----

void GPS::enable(int samplingPeriod) { simulation().set_sampling_period(index(), samplingPeriod); }
void GPS::disable() { simulation().set_sampling_period(index(), 0); }
int GPS::getSamplingPeriod() const { return simulation().sampling_period(index()); }
const double *GPS::getValues() const { return simulation().gps_values(index()); }

// ---- TouchSensor ----

void TouchSensor::enable(int samplingPeriod) {
  simulation().set_sampling_period(index(), samplingPeriod);
}
void TouchSensor::disable() { simulation().set_sampling_period(index(), 0); }
int TouchSensor::getSamplingPeriod() const { return simulation().sampling_period(index()); }
double TouchSensor::getValue() const { return simulation().touch_value(index()); }

// ---- DistanceSensor ----

void DistanceSensor::enable(int samplingPeriod) {
  simulation().set_sampling_period(index(), samplingPeriod);
}
void DistanceSensor::disable() { simulation().set_sampling_period(index(), 0); }
int DistanceSensor::getSamplingPeriod() const { return simulation().sampling_period(index()); }
double DistanceSensor::getValue() const { return simulation().distance_value(index()); }
double DistanceSensor::getMaxValue() const {
  const auto &table = simulation().distance_spec(index()).lookup_table;
  double max = table.front().value;
  for (const auto &row : table) max = std::max(max, row.value);
  return max;
}
double DistanceSensor::getMinValue() const {
  const auto &table = simulation().distance_spec(index()).lookup_table;
  double min = table.front().value;
  for (const auto &row : table) min = std::min(min, row.value);
  return min;
}
double DistanceSensor::getAperture() const { return simulation().distance_spec(index()).aperture_rad; }
DistanceSensor::Type DistanceSensor::getType() const {
  switch (simulation().distance_spec(index()).type) {
    case maze::sim::DistanceSensorType::generic: return GENERIC;
    case maze::sim::DistanceSensorType::infra_red: return INFRA_RED;
    case maze::sim::DistanceSensorType::sonar: return SONAR;
  }
  return GENERIC;
}

}  // namespace webots
