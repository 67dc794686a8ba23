#pragma once

#include <webots/Device.hpp>

namespace webots {

// Orientation as roll, pitch, yaw in radians; yaw 0 faces east (+x), counter-clockwise positive.
class InertialUnit : public Device {
 public:
  virtual void enable(int samplingPeriod);
  virtual void disable();
  int getSamplingPeriod() const;
  const double *getRollPitchYaw() const;  // three values, rad

 private:
  friend class embedded::Simulation;
  using Device::Device;
};

}  // namespace webots
