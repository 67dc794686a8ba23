#pragma once

#include <webots/Device.hpp>

namespace webots {

// A planar lidar. The range image is ordered left to right as seen from the sensor:
// beam i points at fov/2 - i * fov / N from the heading (counter-clockwise positive), so
// with 360 beams over 2 pi, index 0 looks back, 90 left, 180 ahead, 270 right. A reading
// outside [min range, max range] is +infinity. Ranges are computed when read (lazily).
class Lidar : public Device {
 public:
  virtual void enable(int samplingPeriod);
  virtual void disable();
  int getSamplingPeriod() const;  // ms, 0 when disabled
  const float *getRangeImage() const;  // nullptr when disabled; getHorizontalResolution() values
  int getHorizontalResolution() const;
  int getNumberOfLayers() const;
  double getFov() const;       // rad
  double getMinRange() const;  // m
  double getMaxRange() const;  // m

 private:
  friend class embedded::Simulation;
  using Device::Device;
};

}  // namespace webots
