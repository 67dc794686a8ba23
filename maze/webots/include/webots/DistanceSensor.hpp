#pragma once

#include <webots/Device.hpp>

namespace webots {

// A range sensor (IR, sonar) whose value follows its lookup table: rows of
// (distance m, value, noise as a fraction of the value), linear in between.
class DistanceSensor : public Device {
 public:
  // getType(): how the rays make one value (Webots' `type` field): GENERIC and INFRA_RED
  // average them, SONAR takes the nearest echo and loses rays beyond 22.5 deg incidence.
  typedef enum { GENERIC = 0, INFRA_RED, SONAR, LASER } Type;

  virtual void enable(int samplingPeriod);
  virtual void disable();
  int getSamplingPeriod() const;
  double getValue() const;
  double getMaxValue() const;
  double getMinValue() const;
  double getAperture() const;  // rad
  Type getType() const;

 private:
  friend class embedded::Simulation;
  using Device::Device;
};

}  // namespace webots
