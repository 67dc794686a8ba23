#pragma once

#include <webots/Device.hpp>

namespace webots {

// A wheel motor. Velocity control: setPosition(INFINITY), then setVelocity(v) in rad/s,
// |v| <= getMaxVelocity().
class Motor : public Device {
 public:
  virtual void setPosition(double position);
  virtual void setVelocity(double vel);
  double getVelocity() const;
  double getMaxVelocity() const;

 private:
  friend class embedded::Simulation;
  using Device::Device;
};

}  // namespace webots
