#pragma once
// The one compass-direction type both sides use: a maze side (maze::Side) and a robot's
// heading (mapping::Heading) are this type under the names their code reads best with.
// Order: quarter turns clockwise from north, so north 0, east 1, south 2, west 3.

#include <string_view>

#include "common/angles.hpp"

namespace common {

enum class Compass { north, east, south, west };

inline constexpr Compass kCompassPoints[] = {Compass::north, Compass::east, Compass::south,
                                             Compass::west};

constexpr Compass opposite(Compass d) { return static_cast<Compass>((static_cast<int>(d) + 2) % 4); }
constexpr Compass turned_right(Compass d) { return static_cast<Compass>((static_cast<int>(d) + 1) % 4); }
constexpr Compass turned_left(Compass d) { return static_cast<Compass>((static_cast<int>(d) + 3) % 4); }

// The step one cell towards d: x east, y north.
constexpr int dx(Compass d) { return d == Compass::east ? 1 : d == Compass::west ? -1 : 0; }
constexpr int dy(Compass d) { return d == Compass::north ? 1 : d == Compass::south ? -1 : 0; }

// Yaw in radians: east 0, north pi/2 (counter-clockwise positive).
constexpr double yaw_rad(Compass d) { return compass_yaw_rad(static_cast<int>(d)); }

// 'N', 'E', 'S', 'W'.
constexpr char to_char(Compass d) { return "NESW"[static_cast<int>(d)]; }

// "north", "east", "south", "west".
constexpr std::string_view to_string(Compass d) {
  constexpr std::string_view names[] = {"north", "east", "south", "west"};
  return names[static_cast<int>(d)];
}

}  // namespace common
