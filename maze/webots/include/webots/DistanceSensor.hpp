#pragma once

#include <webots/Device.hpp>

namespace webots {

// A range sensor (IR, sonar) whose value follows its lookup table: rows of
// (distance m, value, noise as a fraction of the value), linear in between.
class DistanceSensor : public Device {
 public:
  virtual void enable(int samplingPeriod);
  virtual void disable();
  int getSamplingPeriod() const;
  double getValue() const;
  double getMaxValue() const;
  double getMinValue() const;
  double getAperture() const;  // rad

 private:
  friend class embedded::Simulation;
  using Device::Device;
};

}  // namespace webots
