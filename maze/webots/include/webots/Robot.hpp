#pragma once
// webots::Robot: the controller's handle on the simulation (ARCHITECTURE.md, the two sides).

#include <memory>
#include <string>

namespace webots {

class Device;
class DistanceSensor;
class GPS;
class InertialUnit;
class Lidar;
class Motor;
class PositionSensor;
class TouchSensor;

namespace embedded {
class Simulation;
}

class Robot {
 public:
  // Attaches to the simulation the embedded entry point has made current (as a Webots
  // controller attaches to the running simulator). Throws std::logic_error when none is.
  Robot();
  virtual ~Robot();
  Robot(const Robot &) = delete;
  Robot &operator=(const Robot &) = delete;

  // Advances simulated time by duration ms (a multiple of the basic time step; a partial one
  // counts whole); a duration <= 0 advances nothing. Returns -1 when the simulation ends,
  // else 0.
  virtual int step(int duration);

  double getTime() const;           // simulated seconds since the start
  double getBasicTimeStep() const;  // ms
  std::string getName() const;

  // Devices by name; nullptr when the robot has no such device (Webots prints a warning).
  Lidar *getLidar(const std::string &name);
  Motor *getMotor(const std::string &name);
  PositionSensor *getPositionSensor(const std::string &name);
  InertialUnit *getInertialUnit(const std::string &name);
  GPS *getGPS(const std::string &name);
  TouchSensor *getTouchSensor(const std::string &name);
  DistanceSensor *getDistanceSensor(const std::string &name);
  Device *getDevice(const std::string &name);

 private:
  friend class embedded::Simulation;
  explicit Robot(embedded::Simulation &simulation);
  embedded::Simulation *simulation_;
};

}  // namespace webots
