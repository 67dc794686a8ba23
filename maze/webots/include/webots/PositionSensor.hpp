#pragma once

#include <webots/Device.hpp>

namespace webots {

// A wheel encoder: the wheel's angle in radians.
class PositionSensor : public Device {
 public:
  virtual void enable(int samplingPeriod);
  virtual void disable();
  int getSamplingPeriod() const;
  double getValue() const;  // rad; NaN when disabled, as in Webots

 private:
  friend class embedded::Simulation;
  using Device::Device;
};

}  // namespace webots
