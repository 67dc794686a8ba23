// A stand-in for Webots' libCppController, for CI (build.sh): every function of the
// project's webots:: headers (maze/webots/include, API-identical to Webots' own for what the
// controller uses) with the behaviour of a Webots world whose robot has no devices and whose
// simulation has ended: Robot::step returns -1, every get*() returns nullptr. It lets the
// Webots controller build link and run to its first error; the embedded simulator
// (maze/src/webots/devices.cpp) is the real implementation the tests run.

#include <cmath>
#include <string>

#include <webots/Device.hpp>
#include <webots/DistanceSensor.hpp>
#include <webots/GPS.hpp>
#include <webots/InertialUnit.hpp>
#include <webots/Lidar.hpp>
#include <webots/Motor.hpp>
#include <webots/PositionSensor.hpp>
#include <webots/Robot.hpp>
#include <webots/TouchSensor.hpp>

namespace webots {

Device::Device(const std::string &name, embedded::Simulation &simulation, int index)
    : name_(name), simulation_(&simulation), index_(index) {}
Device::~Device() = default;
const std::string &Device::getName() const { return name_; }
std::string Device::getModel() const { return "stand-in"; }

Robot::Robot() : simulation_(nullptr) {}
Robot::Robot(embedded::Simulation &simulation) : simulation_(&simulation) {}
Robot::~Robot() = default;
int Robot::step(int) { return -1; }
double Robot::getTime() const { return 0.0; }
double Robot::getBasicTimeStep() const { return 32.0; }
std::string Robot::getName() const { return "stand-in"; }
Lidar *Robot::getLidar(const std::string &) { return nullptr; }
Motor *Robot::getMotor(const std::string &) { return nullptr; }
PositionSensor *Robot::getPositionSensor(const std::string &) { return nullptr; }
InertialUnit *Robot::getInertialUnit(const std::string &) { return nullptr; }
GPS *Robot::getGPS(const std::string &) { return nullptr; }
TouchSensor *Robot::getTouchSensor(const std::string &) { return nullptr; }
DistanceSensor *Robot::getDistanceSensor(const std::string &) { return nullptr; }
Device *Robot::getDevice(const std::string &) { return nullptr; }

void Lidar::enable(int) {}
void Lidar::disable() {}
int Lidar::getSamplingPeriod() const { return 0; }
const float *Lidar::getRangeImage() const { return nullptr; }
int Lidar::getHorizontalResolution() const { return 0; }
int Lidar::getNumberOfLayers() const { return 0; }
double Lidar::getFov() const { return 0.0; }
double Lidar::getMinRange() const { return 0.0; }
double Lidar::getMaxRange() const { return 0.0; }
double Lidar::getFrequency() const { return 0.0; }

void Motor::setPosition(double) {}
void Motor::setVelocity(double) {}
double Motor::getVelocity() const { return 0.0; }
double Motor::getMaxVelocity() const { return 0.0; }

void PositionSensor::enable(int) {}
void PositionSensor::disable() {}
int PositionSensor::getSamplingPeriod() const { return 0; }
double PositionSensor::getValue() const { return NAN; }

void InertialUnit::enable(int) {}
void InertialUnit::disable() {}
int InertialUnit::getSamplingPeriod() const { return 0; }
const double *InertialUnit::getRollPitchYaw() const { return nullptr; }

void GPS::enable(int) {}
void GPS::disable() {}
int GPS::getSamplingPeriod() const { return 0; }
const double *GPS::getValues() const { return nullptr; }

void TouchSensor::enable(int) {}
void TouchSensor::disable() {}
int TouchSensor::getSamplingPeriod() const { return 0; }
double TouchSensor::getValue() const { return NAN; }

void DistanceSensor::enable(int) {}
void DistanceSensor::disable() {}
int DistanceSensor::getSamplingPeriod() const { return 0; }
double DistanceSensor::getValue() const { return NAN; }
double DistanceSensor::getMaxValue() const { return 0.0; }
double DistanceSensor::getMinValue() const { return 0.0; }
double DistanceSensor::getAperture() const { return 0.0; }
DistanceSensor::Type DistanceSensor::getType() const { return GENERIC; }

}  // namespace webots
