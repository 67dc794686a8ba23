#pragma once
// The textbook 1-D log-odds exercise: a row of cells in front of a range sensor, updated with
// a list of range measurements through a simple inverse sensor model.
//
//   robot at 0 cm, looking toward the far end
//   cells at x = 0, r, 2r, ..., up to the length (r = resolution, all in cm)
//
//        x < z          z <= x <= z + behind      x > z + behind
//   ---- free ---------|===== occupied =====|---- no update ----->  x
//   0                  z                 z + behind
//
// Conventions (the exercise leaves them open; these are the ones chosen here):
// - a cell is a point at its position x; it is not an interval;
// - "nearer than the measurement" is x < z strictly: a cell exactly at the measured distance
//   is where the beam ended, so it is occupied;
// - "up to `behind` cm behind it" includes both ends: z <= x <= z + behind;
// - a measurement beyond the length is allowed: every cell is then nearer than it (free),
//   and the occupied stretch lies past the last cell. A measurement must be finite and >= 0.
// - one measurement gives each cell at most one update; the update rule is
//   l <- l + l(inv(z)) - l(prior), with the SensorModel's increments.
//
// With the defaults (21 cells 0 ... 200 cm, measurements 101, 82, 91, 112, 99, 151, 96, 85,
// 99, 105, prior 0.5, p_free 0.3, p_occ 0.6, behind 20 cm) the cell at 110 cm gets six
// occupied and two free updates: l = 6 * 0.4055 - 2 * 0.8473 = 0.7382, p = 0.6766.

#include <cstdint>
#include <span>
#include <vector>

#include "mapping/sensor_model.hpp"

namespace app::course {

// The exercise's measurements, in cm, in the order they arrive.
inline const std::vector<double> kDemo1dMeasurementsCm{101, 82, 91, 112, 99, 151, 96, 85, 99, 105};

// Most cells a demo may have (0 ... 10,000 cm at 1 cm); the table prints one line a cell.
inline constexpr int kDemo1dMaxCells = 10001;

// What a user sets with demo 1d's options. Distances in cm.
struct Demo1dOptions {
  std::vector<double> measurements_cm = kDemo1dMeasurementsCm;
  double resolution_cm = 10.0;  // spacing of the cells, > 0
  double length_cm = 200.0;     // position of the last cell at most, >= 0
  double behind_cm = 20.0;      // depth of the occupied stretch behind a hit, >= 0
  mapping::SensorModelOptions model;   // p_free, p_occ, prior, base (clamp unused: it breaks order independence)
};

// Throws common::InputError naming the option and its value when the options cannot be used
// (see the checks in demo_1d.cpp: lengths finite, resolution > 0, at most kDemo1dMaxCells
// cells, at least one measurement, every measurement finite and >= 0, a valid sensor model).
void validate(const Demo1dOptions &options);

// Cell positions 0, r, 2r, ... while <= length (with 1e-9 relative slack so that 200 / 10
// gives 21 cells). Options must be valid.
std::vector<double> cell_positions_cm(const Demo1dOptions &options);

enum class CellUpdate { free, occupied, none };

// What one measurement z says about the cell at x (the conventions above).
CellUpdate classify(double cell_cm, double measurement_cm, double behind_cm);

struct Demo1dCell {
  double position_cm = 0.0;
  int free_updates = 0;      // how many measurements called it free
  int occupied_updates = 0;  // ... and occupied
  double log_odds = 0.0;     // in the model's base
  double belief = 0.0;       // probability of occupied
};

// Integrates the measurements in the given order, one update per cell per measurement.
// Options must be valid; `measurements_cm` replaces options.measurements_cm (so a shuffled
// order can be integrated with the same set-up).
std::vector<Demo1dCell> integrate(const Demo1dOptions &options,
                                  std::span<const double> measurements_cm);

// The measurements in an order drawn with common::Rng(seed).shuffle.
std::vector<double> shuffled(std::span<const double> measurements_cm, std::uint64_t seed);

// Largest |a.log_odds - b.log_odds| over the cells of two results of the same set-up.
double max_log_odds_difference(std::span<const Demo1dCell> a, std::span<const Demo1dCell> b);

// Two integrations count as the same result when no cell's log-odds differs by more than
// this: floating-point addition is not associative, so another order may change the last bits.
inline constexpr double kOrderTolerance = 1e-9;

}  // namespace app::course
