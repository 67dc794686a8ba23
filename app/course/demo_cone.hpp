#pragma once
// `maze_mapper demo cone`: the sensor-model lecture's cone sweep for the Khepera III's IR and
// sonar (sensing/cone_cells.hpp for the loop, docs/lab-cone.md for the exercise), from its
// options as typed to the text it prints: the lecture's numbers, each radius's step, the
// marked cells and how the maze run's cone model differs; on request the cells' CSV and a
// picture with the beam's edges.

#include <optional>
#include <string>

namespace app::course {

// The lecture's Khepera III numbers. `rays` is what the maze run's simulated sensor casts
// across the aperture (the ir-ring and sonar-ring profiles); the sweep itself has no rays.
struct KheperaSensor {
  const char *name;
  double aperture_rad;
  int rays;
  double distance_error;  // eps, a fraction of the reading
};
inline constexpr KheperaSensor kKheperaIr{"ir", 0.03, 3, 0.03};
inline constexpr KheperaSensor kKheperaSonar{"sonar", 0.4, 5, 0.066};

// demo cone's options as typed; a range or resolution not given is the sensor's default
// (0.2 m and 0.01 m for ir, 1 m and 0.05 m for sonar: the reading 20 cells away).
struct DemoConeInput {
  std::string sensor = "ir";  // ir or sonar
  double range_m = 0.0;
  std::optional<double> resolution_m;  // m; none: the sensor's
  bool range_given = false;
  std::string pose;      // Xm,Ym,YAW (app/run/option_values.hpp's parse_pose); empty: 0m,0m,90
  std::string csv_path;  // i,j of the marked cells
  std::string png_path;  // the picture; SVG or PDF when the name ends in .svg or .pdf
};

// Checks the input (common::InputError naming the option: "--sensor must be ir or sonar (got
// x)", "--range must be > 0 m (got 0)", a range over 10,000 cells, a pose more than 1e6 cells
// from 0,0), prints a pose's warning on standard error, writes the files asked for and
// returns the text.
std::string run_demo_cone(const DemoConeInput &input);

}  // namespace app::course
