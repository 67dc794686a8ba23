#pragma once

#include <webots/Device.hpp>

namespace webots {

// Position in the world frame: x east, y north, z up, metres.
class GPS : public Device {
 public:
  virtual void enable(int samplingPeriod);
  virtual void disable();
  int getSamplingPeriod() const;
  const double *getValues() const;  // three values, m

 private:
  friend class embedded::Simulation;
  using Device::Device;
};

}  // namespace webots
