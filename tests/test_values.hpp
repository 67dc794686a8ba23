#pragma once
// Values and paths many test files use, defined once (the test files are also compiled
// together, several to a translation unit, in the unity build: a name each file defined for
// itself would clash).

#include <limits>
#include <numbers>
#include <string>
#include <string_view>

#include "maze/world/maze.hpp"

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr float kFloatInf = std::numeric_limits<float>::infinity();
inline constexpr float kFloatNaN = std::numeric_limits<float>::quiet_NaN();
inline constexpr double kDeg = kPi / 180.0;  // radians a degree
// Half a wall of the default thickness: 0.006 m.
inline constexpr double kHalfWall_m = maze::kDefaultWallThickness_m / 2.0;

// The maze with its walls' height unstated (as the formats without heights read it): the
// course's XML states 0.5 m, so an XML maze equals a text one up to that.
inline maze::Maze heightless(maze::Maze m) {
  m.set_wall_height_m(kInf);
  return m;
}

// A world of tests/data/worlds/.
inline std::string world_fixture(std::string_view name) {
  return std::string(TEST_DATA_DIR) + "/worlds/" + std::string(name);
}
