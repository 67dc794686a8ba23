#pragma once
// One planar lidar scan, independent of Webots: where it was taken and its ranges.
//
// Beam order is the Webots range-image order (ARCHITECTURE.md, Conventions): beam i points at
//   fov/2 - (i + beam_offset) * fov / N   radians from the heading, counter-clockwise positive,
// so with 360 beams over 2 pi, index 0 looks back, 90 left, 180 ahead, 270 right. A rotating
// lidar's beam_offset is 0; a fixed one's is 1/2 (Webots renders a fixed lidar as a camera
// whose pixel i is centred half a beam in: docs/simulator.md).
//
// Readings:
//   finite, within [min_range_m, max_range_m]   a return at that range (a hit)
//   +infinity, or finite beyond max_range_m      no return (nothing within max range)
//   NaN, negative, or below min_range_m          invalid: ignored, never stored

#include <cmath>
#include <optional>
#include <span>

#include "mapping/grid_types.hpp"

namespace sensing {

enum class ReadingKind { hit, no_return, invalid };

struct LidarScan {
  mapping::Point origin;             // sensor position in the world, m
  double yaw_rad = 0.0;     // sensor heading in the world: 0 east, pi/2 north
  double fov_rad = 0.0;     // (0, 2 pi]
  double min_range_m = 0.0;
  double max_range_m = 0.0;
  double beam_offset = 0.0;  // in beams: 0 for a rotating lidar, 0.5 for a fixed one
  std::span<const float> ranges;  // N readings, m, beam order above; not owned

  int beam_count() const { return static_cast<int>(ranges.size()); }

  // Angle of beam i relative to the heading, rad.
  double beam_angle_rad(int i) const;
  // Angle of beam i in the world frame (yaw + beam angle), rad, not wrapped.
  double beam_world_angle_rad(int i) const { return yaw_rad + beam_angle_rad(i); }

  ReadingKind kind(int i) const { return kind_of(ranges[static_cast<std::size_t>(i)]); }
  // The kind of a reading r, m (the table above). Inline: the filter and the models ask
  // for every beam.
  ReadingKind kind_of(float r) const {
    if (std::isnan(r) || r < 0.0f || r < min_range_m) return ReadingKind::invalid;
    if (std::isinf(r) || r > max_range_m) return ReadingKind::no_return;
    return ReadingKind::hit;
  }

  // The median reading, m, of the beams within half_window_rad of beam `centre` (beam
  // `centre` alone when the beams are further apart), invalid readings left out; nothing when
  // none is valid. When at least two of them are returns, no-return readings are left out too
  // (a wall is not seen through: those are dropped beams), else no return counts as
  // +infinity. A lone dropout or spike does not move it. The lower median when the count is
  // even. No allocation for a window of up to kMedianSmallWindow beams.
  static constexpr int kMedianSmallWindow = 33;
  std::optional<float> median_range(int centre, double half_window_rad) const;
  // The same window's lower and upper medians (equal when the count is odd): readings split
  // evenly between them (two returns and two further, say) are two answers, not one.
  struct Medians {
    float lower;
    float upper;
  };
  std::optional<Medians> medians(int centre, double half_window_rad) const;

  // Whether beam i is a no return with a return among the two beams on each side of it:
  // one or two dropped beams, not a view past the wall their neighbours hit.
  bool lone_no_return(int i) const;

  // The beam whose direction is nearest to a world direction, or nothing when that
  // direction is outside the field of view (or the scan has no beams).
  std::optional<int> beam_towards(double world_angle_rad) const;
};

}  // namespace sensing
