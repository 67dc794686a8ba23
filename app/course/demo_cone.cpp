#include "app/course/demo_cone.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <vector>

#include <fmt/format.h>

#include "app/picture/plain_grid_picture.hpp"
#include "app/run/option_values.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/standard_streams.hpp"
#include "sensing/cone_cells.hpp"

namespace app::course {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMaxRangeCells = 10000.0;

inline constexpr Rgb kConeMarked{35, 35, 35};

// The defaults put the reading 20 cells away for either sensor.
struct ConeDefaults {
  double range_m;
  double resolution_m;
};

std::string percent(double fraction) { return fmt::format("{:g} %", fraction * 100.0); }

std::string khepera_table() {
  std::string out = "Khepera III (the lecture's numbers):\n"
                    "sensor  aperture_rad  rays  distance_error\n";
  for (const auto &s : {kKheperaIr, kKheperaSonar}) {
    out += fmt::format("{:<6}  {:<12g}  {:>4}  +-{}\n", s.name, s.aperture_rad, s.rays, percent(s.distance_error));
  }
  return out;
}

std::string step_table(const sensing::ConeCells &sweep) {
  std::string out = "   j  r_cells      x_a      y_a      x_b      y_b  omega_rad  angles\n";
  for (std::size_t j = 0; j < sweep.steps.size(); ++j) {
    const auto &s = sweep.steps[j];
    out += fmt::format("{:>4}  {:>7.2f}  {:>7.3f}  {:>7.3f}  {:>7.3f}  {:>7.3f}  {:>9.5f}  {:>6}\n", j, s.r_cells, s.xa,
                       s.ya, s.xb, s.yb, s.omega_rad, s.angles);
  }
  return out;
}

// The marked cells, north row first: `#` marked, `.` not; row and column labels are i, j.
std::string marked_cells_text(const sensing::ConeCells &sweep) {
  if (sweep.cells.empty()) return "no cell marked\n";
  int i0 = sweep.cells.front().first, i1 = sweep.cells.back().first;
  int j0 = sweep.cells.front().second, j1 = j0;
  for (const auto &[i, j] : sweep.cells) j0 = std::min(j0, j), j1 = std::max(j1, j);
  const std::set<std::pair<int, int>> marked(sweep.cells.begin(), sweep.cells.end());
  std::string out = fmt::format("marked cells: {}, i {} .. {} (west to east), j {} .. {} (rows, north first)\n",
                                sweep.cells.size(), i0, i1, j0, j1);
  for (int j = j1; j >= j0; --j) {
    out += fmt::format("{:>6} ", j);
    for (int i = i0; i <= i1; ++i) out += marked.count({i, j}) ? '#' : '.';
    out += "\n";
  }
  return out;
}

std::string cone_csv(const sensing::ConeCells &sweep) {
  std::string out = "i,j\n";
  for (const auto &[i, j] : sweep.cells) out += fmt::format("{},{}\n", i, j);
  return out;
}

// The marked cells dark on the never-observed tone, the beam's edges (phi +- sigma/2, out to
// d(1+eps)) in red, the sensor a blue disc; the format by the file's extension.
std::string cone_picture(const sensing::ConeCells &sweep, const sensing::ConeReading &in, double resolution_m,
                         const std::string &sensor, PictureFormat format) {
  int i0 = static_cast<int>(std::floor(in.x_cells)), i1 = i0, j0 = static_cast<int>(std::floor(in.y_cells)), j1 = j0;
  for (const auto &[i, j] : sweep.cells) i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
  const double reach = in.d_cells * (1.0 + in.eps);
  PlainGrid g = plain_grid_around(i0, i1, j0, j1, resolution_m, kUnknownTone);
  for (const auto &[i, j] : sweep.cells) set_tone(g, (i + 0.5) * resolution_m, (j + 0.5) * resolution_m, kConeMarked);
  Figure legend;
  legend.lines = {fmt::format("demo cone {}: d {:g} cells, sigma {:g} rad", sensor, in.d_cells, in.sigma_rad)};
  legend.items = {{Swatch::box, kConeMarked, "marked"}, {Swatch::box, kUnknownTone, "not marked"},
                  {Swatch::line, kPathColour, "beam edges"}, {Swatch::disc, kEndColour, "sensor"}};
  const PlainGridOverlay overlay = [&](Drawing &page, const PlainGridFrame &frame) {
    const auto at = [&](double x_cells, double y_cells) { return frame.at(x_cells * resolution_m, y_cells * resolution_m); };
    const PointPx from = at(in.x_cells, in.y_cells);
    for (const double side : {-0.5, 0.5}) {
      const double a = in.phi_rad + side * in.sigma_rad;
      page.polyline({from, at(in.x_cells + reach * std::cos(a), in.y_cells + reach * std::sin(a))},
                    std::max(1.5, frame.cell_w_px / 10), kPathColour);
    }
    page.ringed_disc(from, std::max(3.0, frame.cell_w_px / 2), kEndColour, 1.5, kWhite);
  };
  return plain_grid_picture(g, legend, overlay, format).encode();
}

const std::string kDifference =
    "the maze run's cone model (--model cone) differs: it marks sub-cells of the maze's grid,\n"
    "sweeps at half a sub-cell (radially and across), frees the cone inside d(1-eps), and\n"
    "weights each point as Moravec and Elfes do: w = 1 - (a / (sigma/2))^2 across the beam\n"
    "(times 1 - (r / (d(1-eps)))^2 in the free cone), p = prior + w (p - prior). Why: a sonar\n"
    "ray at a cone's edge may belong to the next wall; unweighted, the edges freed the wall\n"
    "bands beside every corridor the sonar looked along (docs/models.md).\n";

}  // namespace

std::string run_demo_cone(const DemoConeInput &input) {
  if (input.sensor != "ir" && input.sensor != "sonar") {
    throw common::InputError("--sensor must be ir or sonar (got " + input.sensor + ")");
  }
  const bool ir = input.sensor == "ir";
  const KheperaSensor &kind = ir ? kKheperaIr : kKheperaSonar;
  const ConeDefaults defaults = ir ? ConeDefaults{0.2, 0.01} : ConeDefaults{1.0, 0.05};
  const double range_m = input.range_given ? input.range_m : defaults.range_m;
  const double resolution_m = input.resolution_m.value_or(defaults.resolution_m);
  if (!(range_m > 0.0) || !std::isfinite(range_m)) throw common::InputError(fmt::format("--range must be > 0 m (got {})", range_m));
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw common::InputError(fmt::format("--resolution must be > 0 m (got {})", resolution_m));
  }
  if (range_m / resolution_m > kMaxRangeCells) {
    throw common::InputError(fmt::format("--range is more than {:g} cells of --resolution", kMaxRangeCells));
  }
  std::vector<double> pose{0.0, 0.0, 90.0};
  if (!input.pose.empty()) {
    std::vector<std::string> warnings;
    const PoseArgument given = parse_pose(input.pose, "--pose", warnings);
    for (const std::string &warning : warnings) common::print_stderr("{}\n", warning);
    pose = {given.x_m, given.y_m, given.yaw_deg};
  }
  // Far from the origin a cell index loses its precision (1e308 m printed inf and nan rows).
  constexpr double kMaxPoseCells = 1e6;
  if (!(std::abs(pose[0]) / resolution_m <= kMaxPoseCells && std::abs(pose[1]) / resolution_m <= kMaxPoseCells)) {
    throw common::InputError(fmt::format("--pose X and Y must lie within {:g} cells of --resolution of 0,0 (got {:g}, {:g})",
                                         kMaxPoseCells, pose[0], pose[1]));
  }
  const sensing::ConeReading in{pose[0] / resolution_m, pose[1] / resolution_m, pose[2] * kDeg,
                                range_m / resolution_m, kind.aperture_rad, kind.distance_error};
  const sensing::ConeCells sweep = sensing::cone_cells(in);
  if (!input.csv_path.empty()) common::write_file_atomically(input.csv_path, cone_csv(sweep));
  if (!input.png_path.empty()) {
    const PictureFormat format = picture_format_of_file(input.png_path).value_or(PictureFormat::png);
    common::write_file_atomically(input.png_path, cone_picture(sweep, in, resolution_m, input.sensor, format));
  }
  std::string out = "cone sweep (the sensor-model lecture's second loop), sensor " + input.sensor + "\n\n";
  out += khepera_table() + "\n";
  out += fmt::format("sigma {:g} rad, eps {:g} ({})\n", in.sigma_rad, in.eps, percent(in.eps));
  out += fmt::format("resolution {:g} m a cell: sensor at ({:g}, {:g}) cells facing {:g} deg, d = {:g} cells ({:g} m)\n",
                     resolution_m, in.x_cells, in.y_cells, pose[2], in.d_cells, range_m);
  out += fmt::format("r from d(1-eps) = {:.2f} to d(1+eps) = {:.2f} cells by INC = {:g}; omega halved\n\n",
                     in.d_cells * (1 - in.eps), in.d_cells * (1 + in.eps), sensing::kConeRadiusInc);
  out += step_table(sweep) + "\n" + marked_cells_text(sweep) + "\n" + kDifference;
  if (!input.csv_path.empty() || !input.png_path.empty()) out += "\n";
  for (const std::string *path : {&input.csv_path, &input.png_path}) {
    if (!path->empty()) out += "wrote " + *path + "\n";
  }
  return out;
}

}  // namespace app::course
