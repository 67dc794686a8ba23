#pragma once
// The IR pie-slice update on a plain grid of square cells, corners on multiples of the
// resolution: the course's rule and nothing more (`maze_mapper demo pie` prints it for the
// Waterloo assignment's Figure 1; the maze run's pie model, with its noise margins, usable
// range and arc test, is in range_models.hpp).
//
//   sensor s at the robot's centre, pointing heading + mount;  reading d;  max range m
//   d < m: contact   clear slice   |p - s| <= d,          |angle(p - s) - dir| <= beta
//                    contact slice |p - s| <= d + alpha,  same angles
//   d >= m: clear    clear slice   |p - s| <= m,          same angles
//
// Per sensor and cell, with the cell's four corners and its centre as the points: occupied
// (l += logit(0.7) = +0.8473) when the sensor is a contact and some point lies in its contact
// slice but not in its clear slice; otherwise clear (l += logit(0.4) = -0.4055) when some
// point lies in the clear slice; otherwise no update. Prior 0.5 (l0 = 0), natural log. A
// point at the sensor itself (within 1e-9 m) lies in every slice of it, so the cells around
// the robot are cleared by every sensor.

#include <vector>

namespace sensing {

// A set-up: the robot's pose, its IR sensors and the rule's numbers, every one given by the
// caller (none has a default of its own). Angles in degrees, counter-clockwise positive
// (mounts: left positive).
struct PieSliceOptions {
  double x_m = 0.0;
  double y_m = 0.0;
  double heading_deg = 0.0;
  std::vector<double> mounts_deg;  // the sensors' directions from the heading, left to right
  std::vector<double> readings_m;  // one reading a sensor, in the same order
  double half_angle_deg = 0.0;     // beta
  double contact_m = 0.0;          // alpha
  double resolution_m = 0.0;       // cell side
  double max_range_m = 0.0;        // IR max range: a reading at or above it saw nothing
};

// Throws common::InputError when a number is not finite, the readings and mounts differ in
// count or are empty, a reading is negative, beta is not in (0, 90), alpha, the resolution
// or the max range is not positive, the pose lies more than 1e6 cells from 0,0, or the
// slices would span more than 2,000 cells a side.
void validate(const PieSliceOptions &options);

inline constexpr double kPieSliceOccupiedP = 0.7;
inline constexpr double kPieSliceClearP = 0.4;

// One sensor's slices in the world (m, deg).
struct PieSlice {
  double x_m = 0.0;
  double y_m = 0.0;
  double heading_deg = 0.0;  // world direction, in [0, 360)
  double reading_m = 0.0;
  double clear_m = 0.0;      // where the clear slice ends
  double contact_m = 0.0;    // where the contact slice ends (contacts only)
  bool contact = false;
};

// The slices of a valid set-up, in the sensors' order.
std::vector<PieSlice> pie_slices(const PieSliceOptions &options);

// One updated cell: column i covers [i r, (i + 1) r] in x, row j [j r, (j + 1) r] in y.
struct PieSliceCell {
  int i = 0;
  int j = 0;
  double log_odds = 0.0;  // the sum of its (sensor, cell) updates
  int occupied = 0;       // how many sensors called it occupied
  int clear = 0;          // how many called it clear
};

// One sensor's verdict on the square cell [x0, x0 + r] x [y0, y0 + r] (m), by its four corners
// and its centre as above: contact (occupied), clear, or outside (no update). beta in rad.
// The room map (sensing/metric/map.hpp) asks it of its own cells.
enum class PieVerdict { outside, clear, contact };
PieVerdict pie_slice_verdict(const PieSlice &slice, double beta_rad, double x0_m, double y0_m, double r_m);

// Every cell some sensor updated, north row first, west to east within a row.
std::vector<PieSliceCell> pie_slice_update(const PieSliceOptions &options);

}  // namespace sensing
