// A student's own arrays and cell lists, read into the program's types.

#include <algorithm>
#include <cctype>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "bindings.hpp"
#include "common/error.hpp"

namespace maze_mapper_python {

namespace {

std::string shape_text(const py::array &a) {
  std::string s = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s += fmt::format("{}{}", d == 0 ? "" : ", ", a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

mapping::Cell cell_from(const py::handle &key, int width_cells, int height_cells) {
  const auto xy = key.cast<std::pair<int, int>>();
  if (xy.first < 0 || xy.second < 0 || xy.first >= width_cells || xy.second >= height_cells) {
    throw common::InputError(fmt::format("visited cell ({},{}) is outside the {}x{} grid", xy.first, xy.second,
                                         width_cells, height_cells));
  }
  return {xy.first, xy.second};
}

}  // namespace

mapping::Heading parse_heading(const std::string &text) {
  std::string t = text;
  std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (t == "n" || t == "north") return mapping::Heading::north;
  if (t == "e" || t == "east") return mapping::Heading::east;
  if (t == "s" || t == "south") return mapping::Heading::south;
  if (t == "w" || t == "west") return mapping::Heading::west;
  throw common::InputError(fmt::format("a heading is N, E, S or W (got '{}')", text));
}

mapping::OccupancyGrid grid_from_array(const py::handle &array, float initial_log_odds) {
  const auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!a) throw common::InputError("the grid must be an array of numbers, rows x columns x K x K");
  if (a.ndim() != 4 || a.shape(2) != a.shape(3)) {
    throw common::InputError(
        fmt::format("the grid must have the shape rows x columns x K x K (got {})", shape_text(a)));
  }
  mapping::GridGeometry geometry;
  geometry.height_cells = static_cast<int>(std::min<py::ssize_t>(a.shape(0), mapping::kMaxCellsPerSide + 1));
  geometry.width_cells = static_cast<int>(std::min<py::ssize_t>(a.shape(1), mapping::kMaxCellsPerSide + 1));
  geometry.subcells = static_cast<int>(std::min<py::ssize_t>(a.shape(2), mapping::kMaxSubcells + 1));
  mapping::OccupancyGrid grid(geometry, initial_log_odds);
  std::memcpy(&grid.at_index(0), a.data(), grid.size() * sizeof(float));
  return grid;
}

explore::Visits visits_from(const py::handle &visited, int width_cells, int height_cells) {
  explore::Visits visits(width_cells, height_cells);
  if (visited.is_none()) return visits;
  if (py::isinstance<PyGrid>(visited)) {
    const PyGrid &g = visited.cast<const PyGrid &>();
    if (g.visits.width() != width_cells || g.visits.height() != height_cells) {
      throw common::InputError(fmt::format("the visits are of a {}x{} grid, the array is {}x{}", g.visits.width(),
                                           g.visits.height(), width_cells, height_cells));
    }
    return g.visits;
  }
  if (py::isinstance<py::dict>(visited)) {
    for (const auto &item : visited.cast<py::dict>()) {
      visits.record(cell_from(item.first, width_cells, height_cells), parse_heading(py::str(item.second)));
    }
    return visits;
  }
  for (const py::handle &cell : visited) {
    visits.record(cell_from(cell, width_cells, height_cells), mapping::Heading::north);
  }
  return visits;
}

}  // namespace maze_mapper_python
