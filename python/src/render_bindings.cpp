// The program's ASCII map and K x K matrix, drawn from any array of the grid's shape.

#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "common/error.hpp"
#include "render/ascii_map.hpp"

namespace maze_mapper_python {

void bind_render(py::module_ &m) {
  m.def(
      "render",
      [](const py::object &array, const py::object &visited, bool ascii, std::optional<char> unknown,
         float initial_log_odds, std::optional<float> threshold) {
        render::MapStyle style;
        style.ascii = ascii;
        style.unknown = unknown;
        style.threshold = threshold;
        if (py::isinstance<PyGrid>(array)) {  // an OccupancyGrid: its own values, visits and prior
          const PyGrid &g = array.cast<const PyGrid &>();
          style.initial_log_odds = g.initial_log_odds();
          const explore::Visits visits =
              visited.is_none() ? g.visits : visits_from(visited, g.grid.width(), g.grid.height());
          return render::render_map(g.grid, visits, style);
        }
        style.initial_log_odds = initial_log_odds;
        const mapping::OccupancyGrid grid = grid_from_array(array, initial_log_odds);
        const explore::Visits visits = visits_from(visited, grid.width(), grid.height());
        return render::render_map(grid, visits, style);
      },
      py::arg("array"), py::arg("visited") = py::none(), py::kw_only(), py::arg("ascii") = false,
      py::arg("unknown") = py::none(), py::arg("initial_log_odds") = 0.0f, py::arg("threshold") = py::none(),
      "The map of any rows x columns x K x K array of log-odds (grid[y, x, i, j], y from the south), as "
      "the program prints its own: W where log-odds > 0 (or >= threshold), the heading's arrow at the "
      "centre of a visited cell, a blank elsewhere; north at the top. visited: {(x, y): 'N'|'E'|'S'|'W'}, "
      "or (x, y) pairs (drawn facing north), or an OccupancyGrid (its own visits); the array may be an "
      "OccupancyGrid itself (its values, visits and prior). initial_log_odds: the "
      "value of a never-updated sub-cell (never drawn as W; drawn as `unknown` when given).");
  m.def(
      "format_cell_matrix",
      [](const py::object &array, int x, int y) {
        const mapping::OccupancyGrid grid = grid_from_array(array, 0.0f);
        if (!grid.contains(mapping::Cell{x, y})) {
          throw common::InputError(
              fmt::format("cell ({},{}) is outside the {}x{} grid", x, y, grid.width(), grid.height()));
        }
        return render::format_cell_matrix(grid, {x, y});
      },
      py::arg("array"), py::arg("x"), py::arg("y"),
      "Cell (x, y)'s K x K log-odds as the program prints them: north row first, signed, 2 decimals.");
}

}  // namespace maze_mapper_python
