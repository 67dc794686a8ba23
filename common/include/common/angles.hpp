#pragma once
// Angles both sides use: no maze knowledge, radians throughout, counter-clockwise positive,
// 0 east (the Webots convention; ARCHITECTURE.md, Conventions).

#include <cmath>
#include <numbers>

namespace common {

inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;  // degrees * kRadPerDeg = radians

// Angle wrapped into (-pi, pi].
inline double wrap_angle_rad(double angle_rad) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  // Already wrapped: the common case, and fmod would return it unchanged.
  if (angle_rad > -std::numbers::pi && angle_rad <= std::numbers::pi) return angle_rad;
  double a = std::fmod(angle_rad, two_pi);
  if (a <= -std::numbers::pi) a += two_pi;
  if (a > std::numbers::pi) a -= two_pi;
  return a;
}

// The yaw of a compass heading given as quarter turns clockwise from north (north 0, east 1,
// south 2, west 3: the order of maze::Side and mapping::Heading): pi/2, 0, -pi/2, pi.
constexpr double compass_yaw_rad(int quarter_turns_from_north) {
  switch (quarter_turns_from_north) {
    case 0: return std::numbers::pi / 2;
    case 1: return 0.0;
    case 2: return -std::numbers::pi / 2;
    case 3: return std::numbers::pi;
  }
  return 0.0;
}

}  // namespace common
