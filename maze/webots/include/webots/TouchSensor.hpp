#pragma once

#include <webots/Device.hpp>

namespace webots {

// A bumper: 1.0 pressed, 0.0 not.
class TouchSensor : public Device {
 public:
  virtual void enable(int samplingPeriod);
  virtual void disable();
  int getSamplingPeriod() const;
  double getValue() const;

 private:
  friend class embedded::Simulation;
  using Device::Device;
};

}  // namespace webots
