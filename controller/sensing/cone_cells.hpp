#pragma once
// The cells a range sensor's cone marks at its reading: the second loop of the sensor-model
// lecture's pseudocode (Khepera III; `maze_mapper demo cone` prints it step by step), exactly.
// Coordinates are grid cells, as the pseudocode's are: the sensor at (x_s, y_s) cells
// pointing phi (rad, counter-clockwise from +x), reading d cells, beam width sigma (rad, full
// aperture), relative distance error eps.
//
//   r_j = d (1 - eps) + j INC                      while r_j <= d (1 + eps),  INC = 0.25
//     arc end points at r_j:  x_a = x_s + r_j cos(phi + sigma/2),  y_a = y_s + r_j sin(phi + sigma/2)
//                             x_b = x_s + r_j cos(phi - sigma/2),  y_b = y_s + r_j sin(phi - sigma/2)
//     omega_j = (sigma / sqrt((x_a - x_b)^2 + (y_a - y_b)^2)) / 2    (halved "to get rid of speckles")
//     a_k = -sigma/2 + k omega_j                   while a_k <= sigma/2
//       objX = x_s + r_j cos(phi + a_k),  objY = y_s + r_j sin(phi + a_k)
//       mark cell (floor(objX), floor(objY))
//
// The steps are counted (r_j = start + j INC), not accumulated, and both "<=" tests allow
// 1e-9 of rounding, so an end that lands on the bound is swept as the text intends.

#include <utility>
#include <vector>

namespace sensing {

inline constexpr double kConeRadiusInc = 0.25;  // INC, cells

// One reading of a cone sensor, in cells.
struct ConeReading {
  double x_cells = 0.0;
  double y_cells = 0.0;
  double phi_rad = 0.0;
  double d_cells = 0.0;         // > 0
  double sigma_rad = 0.0;       // > 0
  double eps = 0.0;             // in [0, 1)
};

// One radius r_j of the sweep: its arc's end points, its angle step and how many a_k it swept.
struct ConeArc {
  double r_cells = 0.0;
  double xa = 0.0, ya = 0.0, xb = 0.0, yb = 0.0;
  double omega_rad = 0.0;
  int angles = 0;  // how many a_k this step swept
};

struct ConeCells {
  std::vector<ConeArc> steps;
  std::vector<std::pair<int, int>> cells;  // (i, j) marked, each once, sorted by i then j
};

// The cells of a valid reading's arc, d (1 - eps) ... d (1 + eps) (d, sigma > 0, eps in
// [0, 1), all finite; checked by the caller).
ConeCells cone_cells(const ConeReading &reading);
// The same sweep over the radii r_j = start + j INC while r_j <= end (cells), whatever d and
// eps say: the room map's free cone (0 ... d (1 - eps)) uses it. At r = 0 one point, the sensor.
ConeCells cone_cells_between(const ConeReading &reading, double start_cells, double end_cells);

}  // namespace sensing
