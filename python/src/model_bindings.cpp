// The lidar models, fed the way a student's controller has its readings: a range image (a
// NumPy float32 array, read in place) and a pose from the GPS and the IMU.

#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "common/error.hpp"
#include "sensing/cell_model.hpp"
#include "sensing/ray_model.hpp"
#include "sensing/scan.hpp"
#include "sensing/setups.hpp"

namespace maze_mapper_python {

namespace {

// One lidar model and its options; update() marks a scan into a grid and applies it.
class LidarModel {
 public:
  explicit LidarModel(const sensing::ModelOptions &options) : options_(options) { sensing::validate(options_); }

  std::size_t update(PyGrid &g, const py::array_t<float, py::array::c_style | py::array::forcecast> &ranges,
                     std::pair<double, double> position_m, double yaw_rad, double max_range_m, double min_range_m,
                     double fov_rad, const std::optional<std::pair<int, int>> &cell) {
    if (ranges.ndim() != 1 || ranges.size() == 0) {
      throw common::InputError(fmt::format("the range image must be one row of readings (got {} dimensions, {} values)",
                                           ranges.ndim(), ranges.size()));
    }
    if (!(min_range_m >= 0.0 && min_range_m < max_range_m && std::isfinite(max_range_m))) {
      throw common::InputError(fmt::format("the lidar's range must satisfy 0 <= min_range_m < max_range_m, finite "
                                           "(got {} ... {})", min_range_m, max_range_m));
    }
    if (!(fov_rad > 0.0 && fov_rad <= 2.0 * std::numbers::pi + 1e-9)) {
      throw common::InputError(fmt::format("fov_rad must be in (0, 2 pi] (got {})", fov_rad));
    }
    if (!(std::isfinite(position_m.first) && std::isfinite(position_m.second) && std::isfinite(yaw_rad))) {
      throw common::InputError(fmt::format("the pose must be finite numbers (got position ({}, {}), yaw_rad {})",
                                           position_m.first, position_m.second, yaw_rad));
    }
    sensing::LidarScan scan;
    scan.origin = {position_m.first, position_m.second};
    scan.yaw_rad = yaw_rad;
    scan.fov_rad = fov_rad;
    scan.min_range_m = min_range_m;
    scan.max_range_m = max_range_m;
    scan.ranges = std::span<const float>(ranges.data(), static_cast<std::size_t>(ranges.size()));
    const mapping::Cell robot_cell = cell ? mapping::Cell{cell->first, cell->second} : cell_at(g, scan.origin);
    if (!g.grid.contains(robot_cell)) {
      throw common::InputError(fmt::format("cell ({},{}) is outside the {}x{} grid", robot_cell.x, robot_cell.y,
                                           g.grid.width(), g.grid.height()));
    }
    return sensing::integrate_scan(options_, g.grid, scan, robot_cell, g.model, update_);
  }

  const sensing::ModelOptions &options() const { return options_; }

 private:
  static mapping::Cell cell_at(const PyGrid &g, mapping::Point p) {
    const auto s = g.grid.subcell_at(p);
    if (!s) throw common::InputError(fmt::format("the pose ({}, {}) is outside the grid", p.x_m, p.y_m));
    return mapping::cell_of(*s, g.grid.k());
  }

  sensing::ModelOptions options_;
  mapping::ScanUpdate update_;
};

// The two models as Python sees them (pybind11 registers a C++ type once).
struct CellModel : LidarModel {
  using LidarModel::LidarModel;
};
struct RayModel : LidarModel {
  using LidarModel::LidarModel;
};

constexpr const char *kUpdateDoc =
    "Marks one scan into the grid and applies it (one update a sub-cell; occupied wins); returns how many "
    "sub-cells changed. ranges: the lidar's range image (Webots' order: beam i at fov/2 - i*fov/N from the "
    "heading; inf for no return), read in place when it is a float32 array; position_m: (x, y) of the "
    "lidar, from the GPS; yaw_rad: from the IMU (0 east, pi/2 north); cell: the robot's cell, by default "
    "the one containing position_m.";

template <typename Model>
void def_update(py::class_<Model> &c) {
  c.def("update", &LidarModel::update, py::arg("grid"), py::arg("ranges"), py::arg("position_m"), py::arg("yaw_rad"),
        py::kw_only(), py::arg("max_range_m"), py::arg("min_range_m") = 0.0,
        py::arg("fov_rad") = 2.0 * std::numbers::pi, py::arg("cell") = py::none(), kUpdateDoc);
}

}  // namespace

void bind_models(py::module_ &m) {
  py::class_<CellModel> cell(m, "CellModel",
                              "The classroom sub-cell model (--model cell): the beams towards world N, E, S, W "
                              "decide each side of the robot's cell; a wall marks its whole band occupied, an "
                              "opening frees the band's middle and the path to it.");
  cell.def(py::init([](double wall_margin) {
             sensing::ModelOptions o;
             o.kind = sensing::ModelKind::cell;
             o.wall_margin = wall_margin;
             return CellModel(o);
           }),
           py::kw_only(), py::arg("wall_margin") = 0.25)
      .def_property_readonly("wall_margin", [](const LidarModel &model) { return model.options().wall_margin; });
  def_update(cell);

  py::class_<RayModel> ray(m, "RayModel",
                             "The ray model (--model ray): every beam traced through the sub-cells it crosses, "
                             "free before the hit, occupied at it.");
  ray.def(py::init([](int hit_depth, bool ignore_no_return) {
            sensing::ModelOptions o;
            o.kind = sensing::ModelKind::ray;
            o.hit_depth = hit_depth;
            o.ignore_no_return = ignore_no_return;
            return RayModel(o);
          }),
          py::kw_only(), py::arg("hit_depth") = 0, py::arg("ignore_no_return") = false)
      .def_property_readonly("hit_depth", [](const LidarModel &model) { return model.options().hit_depth; })
      .def_property_readonly("ignore_no_return", [](const LidarModel &model) { return model.options().ignore_no_return; });
  def_update(ray);
}

}  // namespace maze_mapper_python
