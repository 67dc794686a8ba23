#pragma once
// Index types of the occupancy grid. Distinct types, never a bare pair of ints.
//
//   Cell{x, y}          a maze cell: column x from the west, row y from the south (ARCHITECTURE.md)
//   LocalSubCell{i, j}  a sub-cell inside its cell: row i from the north, column j from the west
//   SubCell{x, y}       a sub-cell of the whole grid: column x from the west, row y from the south
//
//   one cell, K = 3:         j=0  j=1  j=2
//                     i=0   [ NW ][ N  ][ NE ]   <- north band
//                     i=1   [ W  ][ C  ][ E  ]   C = (K/2, K/2), where the robot stands
//                     i=2   [ SW ][ S  ][ SE ]   <- south band
//
// Conversions (K sub-cells per cell side):
//   SubCell.x = Cell.x * K + j
//   SubCell.y = Cell.y * K + (K - 1 - i)

#include <compare>
#include <cstddef>
#include <functional>

#include "common/compass.hpp"

namespace mapping {

struct Cell {
  int x = 0;
  int y = 0;
  friend constexpr auto operator<=>(const Cell &, const Cell &) = default;
};

struct LocalSubCell {
  int i = 0;  // row, 0 = north band
  int j = 0;  // column, 0 = west band
  friend constexpr auto operator<=>(const LocalSubCell &, const LocalSubCell &) = default;
};

struct SubCell {
  int x = 0;  // column from the west over the whole grid
  int y = 0;  // row from the south over the whole grid
  friend constexpr auto operator<=>(const SubCell &, const SubCell &) = default;
};

// A world point in metres: x east, y north.
struct Point {
  double x_m = 0.0;
  double y_m = 0.0;
};

// A robot's heading, and the side of a cell it faces: the one compass type (common/compass.hpp).
using Heading = common::Compass;
inline constexpr const auto &kHeadings = common::kCompassPoints;
using common::dx;
using common::dy;
using common::opposite;
using common::to_char;
using common::turned_left;
using common::turned_right;
using common::yaw_rad;

constexpr Cell neighbour(Cell c, Heading h) { return {c.x + dx(h), c.y + dy(h)}; }

constexpr SubCell to_global(Cell c, LocalSubCell s, int k) {
  return {c.x * k + s.j, c.y * k + (k - 1 - s.i)};
}
constexpr Cell cell_of(SubCell s, int k) {
  // Floor division keeps sub-cells west or south of the grid in negative cells.
  auto floor_div = [](int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); };
  return {floor_div(s.x, k), floor_div(s.y, k)};
}
constexpr LocalSubCell local_of(SubCell s, int k) {
  const Cell c = cell_of(s, k);
  return {k - 1 - (s.y - c.y * k), s.x - c.x * k};
}

}  // namespace mapping

template <>
struct std::hash<mapping::Cell> {
  std::size_t operator()(const mapping::Cell &c) const noexcept {
    return std::hash<long long>{}((static_cast<long long>(c.y) << 32) ^ static_cast<unsigned>(c.x));
  }
};

template <>
struct std::hash<mapping::SubCell> {
  std::size_t operator()(const mapping::SubCell &s) const noexcept {
    return std::hash<long long>{}((static_cast<long long>(s.y) << 32) ^ static_cast<unsigned>(s.x));
  }
};
