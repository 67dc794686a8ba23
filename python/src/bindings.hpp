#pragma once
// The pieces of the Python module `maze_mapper._native`, one function a part, and what they
// share: the grid a Python object holds, and the reading of a student's own arrays.

#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "explore/visits.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"

namespace maze_mapper_python {

namespace py = pybind11;

void bind_mapping(py::module_ &m);    // SensorModel, log_odds, probability, OccupancyGrid
void bind_models(py::module_ &m);     // CellModel, RayModel
void bind_render(py::module_ &m);     // render, format_cell_matrix
void bind_world(py::module_ &m);      // World, load_world, score
void bind_simulator(py::module_ &m);  // Simulation and the webots:: devices
void bind_run_files(py::module_ &m);  // RunFiles (maze_mapper.run --out), format_entries, option_help
void bind_signals(py::module_ &m);    // the commands' stop signals (common/interrupt.hpp), for the runner (module.cpp)

// An occupancy grid as Python holds it: the 4D log-odds (exposed as a NumPy view, no copy),
// the sensor model that updates it, and the cells the robot visited with its heading there.
struct PyGrid {
  PyGrid(const mapping::GridGeometry &geometry, const mapping::SensorModel &sensor_model)
      : model(sensor_model),
        grid(geometry, static_cast<float>(sensor_model.prior_log_odds())),
        visits(geometry.width_cells, geometry.height_cells) {}

  float initial_log_odds() const { return static_cast<float>(model.prior_log_odds()); }

  mapping::SensorModel model;
  mapping::OccupancyGrid grid;
  explore::Visits visits;
};

// A float32 copy of a student's array of shape (rows, columns, K, K) in the documented
// layout (grid[y, x, i, j]: y from the south, x from the west, i from the north, j from the
// west), as an occupancy grid with 1 m cells at the origin. Throws common::InputError
// naming the shape when it is not such an array (K odd, 3 ... 9).
mapping::OccupancyGrid grid_from_array(const py::handle &array, float initial_log_odds);

// Visited cells and headings from Python: None (no cell), a PyGrid's own visits, a mapping
// {(x, y): heading} or an iterable of (x, y) (visited, heading north). A heading is "N", "E",
// "S", "W" (or the words). Throws common::InputError for a cell outside the grid or a heading
// that is none of these.
explore::Visits visits_from(const py::handle &visited, int width_cells, int height_cells);

// "N", "north", ... as a heading; throws common::InputError otherwise.
mapping::Heading parse_heading(const std::string &text);

}  // namespace maze_mapper_python
