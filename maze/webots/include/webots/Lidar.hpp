#pragma once

#include <webots/Device.hpp>

namespace webots {

// A planar lidar. The range image is ordered left to right as seen from the sensor: a fixed
// lidar's beam i points at fov/2 - (i + 1/2) * fov / N from the heading (counter-clockwise
// positive; the centre of pixel i of the image Webots renders), a rotating lidar's at
// fov/2 - i * fov / N, so with 360 beams over 2 pi, index 0 looks back, 90 left, 180 ahead,
// 270 right. A reading outside [min range, max range] is +infinity; a fixed lidar's
// `resolution` rounds the depth as Webots does (docs/simulator.md). Ranges are computed when
// read (lazily).
//
// A rotating lidar (getFrequency() > 0; Webots' `type "rotating"`) fills its range image a
// slice per basic time step, as Webots does: its head starts facing ahead when the lidar is
// enabled and turns clockwise at the frequency, and each beam holds the range measured from
// the pose at the end of the step during which the head swept its direction (a beam not yet
// swept since enable reads 0, Webots' initial image). The beam order stays as above. So a
// controller that wants one image from one pose waits ceil(1 / (frequency x step)) steps at
// rest; mid-turn, the image mixes the poses of the last revolution's steps.
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
  // Hz: a rotating lidar's head frequency; 0 for a fixed lidar here (a real Webots returns
  // the node's defaultFrequency, 10 Hz unless set, whatever the type).
  double getFrequency() const;
  // Hz: the range setFrequency takes, Webots' minFrequency and maxFrequency defaults (1, 25).
  double getMinFrequency() const;
  double getMaxFrequency() const;
  // A rotating lidar's head turns at `frequency` Hz from now on, on from where it stands
  // (each beam keeps its reading until the head passes it again) and getFrequency() returns
  // it. Outside [getMinFrequency(), getMaxFrequency()]: Webots' error line on stderr, nothing
  // changes. On a fixed lidar (no head to turn) a warning line says the call has no effect.
  void setFrequency(double frequency);

 private:
  friend class embedded::Simulation;
  using Device::Device;
};

}  // namespace webots
