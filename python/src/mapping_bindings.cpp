// SensorModel, log-odds and the occupancy grid, whose values NumPy sees in place.

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "common/error.hpp"
#include "mapping/log_odds.hpp"
#include "mapping/walls.hpp"
#include "render/ascii_map.hpp"

namespace maze_mapper_python {

namespace {

// "e" or "10" (the --log-base words), or the number 10.
mapping::LogBase parse_base(const py::handle &base) {
  const std::string text = py::str(base);
  if (text == "e") return mapping::LogBase::e;
  if (text == "10" || text == "10.0") return mapping::LogBase::ten;
  throw common::InputError("--log-base must be e or 10 (got " + text + ")");
}

mapping::SensorModel make_model(double p_free, double p_occ, double prior, const py::handle &base,
                                const std::optional<std::pair<double, double>> &clamp) {
  mapping::SensorModelOptions options;
  options.p_free = p_free;
  options.p_occ = p_occ;
  options.prior = prior;
  options.base = parse_base(base);
  if (clamp) options.clamp = mapping::Clamp{clamp->first, clamp->second};
  return mapping::SensorModel(options);
}

const char *side_word(mapping::SideState s) {
  switch (s) {
    case mapping::SideState::wall: return "wall";
    case mapping::SideState::open: return "open";
    case mapping::SideState::unknown: return "unknown";
  }
  return "unknown";
}

mapping::Cell cell_inside(const PyGrid &g, int x, int y) {
  const mapping::Cell c{x, y};
  if (!g.grid.contains(c)) {
    throw common::InputError("cell (" + std::to_string(x) + "," + std::to_string(y) + ") is outside the " +
                             std::to_string(g.grid.width()) + "x" + std::to_string(g.grid.height()) + " grid");
  }
  return c;
}

// The 4D view: shape (H, W, K, K), C order, the grid's own memory (the grid object is its base).
py::array_t<float> array_view(py::object self) {
  PyGrid &g = self.cast<PyGrid &>();
  const auto k = static_cast<py::ssize_t>(g.grid.k());
  const auto w = static_cast<py::ssize_t>(g.grid.width());
  const auto h = static_cast<py::ssize_t>(g.grid.height());
  const auto f = static_cast<py::ssize_t>(sizeof(float));
  return py::array_t<float>({h, w, k, k}, {w * k * k * f, k * k * f, k * f, f}, &g.grid.at_index(0), self);
}

// l(p) of a probability strictly between 0 and 1 (0 and 1 have none: -inf and +inf).
double checked_log_odds(double p, const py::object &base) {
  if (!(p > 0.0 && p < 1.0)) {
    throw common::InputError(fmt::format("log_odds: p must be a probability strictly between 0 and 1 (got {})", p));
  }
  return mapping::log_odds(p, parse_base(base));
}

// The probability of a log-odds value; +-inf are certainty (1 and 0), NaN is no value.
double checked_probability(double l, const py::object &base) {
  if (std::isnan(l)) throw common::InputError("probability: log_odds must be a number (got nan)");
  return mapping::probability(l, parse_base(base));
}

}  // namespace

void bind_mapping(py::module_ &m) {
  m.def("log_odds", &checked_log_odds, py::arg("p"), py::arg("base") = "e",
        "l(p) = log_b(p / (1 - p)), base e or 10; p strictly between 0 and 1.");
  m.def("probability", &checked_probability, py::arg("log_odds"), py::arg("base") = "e",
        "The probability of a log-odds value: 1 - 1 / (1 + b^l).");

  py::class_<mapping::SensorModel>(m, "SensorModel",
                                   "The inverse sensor model's numbers (--p-free, --p-occ, --prior, --log-base, "
                                   "--clamp), checked once, with the increments l(p) - l(prior).")
      .def(py::init(&make_model), py::kw_only(), py::arg("p_free") = 0.3, py::arg("p_occ") = 0.6,
           py::arg("prior") = 0.5, py::arg("log_base") = "e", py::arg("clamp") = py::none())
      .def_property_readonly("p_free", [](const mapping::SensorModel &s) { return s.options().p_free; })
      .def_property_readonly("p_occ", [](const mapping::SensorModel &s) { return s.options().p_occ; })
      .def_property_readonly("prior", [](const mapping::SensorModel &s) { return s.options().prior; })
      .def_property_readonly("log_base",
                             [](const mapping::SensorModel &s) { return std::string(mapping::to_string(s.options().base)); })
      .def_property_readonly("clamp",
                             [](const mapping::SensorModel &s) -> std::optional<std::pair<double, double>> {
                               if (!s.options().clamp) return std::nullopt;
                               return std::make_pair(s.options().clamp->min, s.options().clamp->max);
                             })
      .def_property_readonly("prior_log_odds", &mapping::SensorModel::prior_log_odds)
      .def_property_readonly("free_increment", &mapping::SensorModel::free_increment)
      .def_property_readonly("occupied_increment", &mapping::SensorModel::occupied_increment)
      .def("increment_for", &mapping::SensorModel::increment_for, py::arg("p"))
      .def("update_free", &mapping::SensorModel::update_free, py::arg("log_odds"))
      .def("update_occupied", &mapping::SensorModel::update_occupied, py::arg("log_odds"))
      .def("probability_of", &mapping::SensorModel::probability_of, py::arg("log_odds"));

  py::class_<PyGrid>(m, "OccupancyGrid",
                     "The 4D occupancy grid: rows x columns x K x K log-odds; `array` is a writable NumPy "
                     "view of it, grid[y, x, i, j] (y from the south, x from the west, i from the north, "
                     "j from the west).")
      .def(py::init([](int width, int height, int subcells, double cell_size_m, std::pair<double, double> origin,
                       const mapping::SensorModel &model) {
             mapping::GridGeometry geometry;
             geometry.width_cells = width;
             geometry.height_cells = height;
             geometry.subcells = subcells;
             geometry.cell_size_m = cell_size_m;
             geometry.origin = {origin.first, origin.second};
             return PyGrid(geometry, model);
           }),
           py::arg("width"), py::arg("height"), py::kw_only(), py::arg("subcells") = 3, py::arg("cell_size_m") = 1.0,
           py::arg("origin") = std::make_pair(0.0, 0.0), py::arg("model") = mapping::SensorModel())
      .def_property_readonly("width", [](const PyGrid &g) { return g.grid.width(); })
      .def_property_readonly("height", [](const PyGrid &g) { return g.grid.height(); })
      .def_property_readonly("subcells", [](const PyGrid &g) { return g.grid.k(); })
      .def_property_readonly("cell_size_m", [](const PyGrid &g) { return g.grid.geometry().cell_size_m; })
      .def_property_readonly("origin",
                             [](const PyGrid &g) {
                               return std::make_pair(g.grid.geometry().origin.x_m, g.grid.geometry().origin.y_m);
                             })
      .def_property_readonly("model", [](const PyGrid &g) { return g.model; })
      .def_property_readonly("initial_log_odds", &PyGrid::initial_log_odds)
      .def_property_readonly("array", &array_view)
      .def(
          "visit",
          [](PyGrid &g, int x, int y, const std::string &heading) {
            g.visits.record(cell_inside(g, x, y), parse_heading(heading));
          },
          py::arg("x"), py::arg("y"), py::arg("heading"),
          "Marks cell (x, y) visited, the robot facing heading (N, E, S, W) there: its arrow on the map.")
      .def("visited", [](const PyGrid &g, int x, int y) { return g.visits.visited(cell_inside(g, x, y)); })
      .def_property_readonly("visited_count", [](const PyGrid &g) { return g.visits.count(); })
      .def(
          "side",
          [](const PyGrid &g, int x, int y, const std::string &heading) {
            return side_word(
                mapping::side_state(g.grid, g.initial_log_odds(), cell_inside(g, x, y), parse_heading(heading)));
          },
          py::arg("x"), py::arg("y"), py::arg("heading"), "What the grid says of a cell's side: wall, open or unknown.")
      .def(
          "cell_of",
          [](const PyGrid &g, double x_m, double y_m) -> std::optional<std::pair<int, int>> {
            const auto s = g.grid.subcell_at({x_m, y_m});
            if (!s) return std::nullopt;
            const mapping::Cell c = mapping::cell_of(*s, g.grid.k());
            return std::make_pair(c.x, c.y);
          },
          py::arg("x_m"), py::arg("y_m"), "The cell (x, y) containing a world point, or None outside the grid.")
      .def(
          "render",
          [](const PyGrid &g, bool ascii, std::optional<char> unknown) {
            render::MapStyle style;
            style.ascii = ascii;
            style.unknown = unknown;
            style.initial_log_odds = g.initial_log_odds();
            return render::render_map(g.grid, g.visits, style);
          },
          py::kw_only(), py::arg("ascii") = false, py::arg("unknown") = py::none(),
          "The map as the program prints it: W, arrows, blanks; one line a sub-cell row, north first.")
      .def(
          "cell_matrix", [](const PyGrid &g, int x, int y) { return render::format_cell_matrix(g.grid, cell_inside(g, x, y)); },
          py::arg("x"), py::arg("y"), "Cell (x, y)'s K x K log-odds as the program prints them, north row first.");
}

}  // namespace maze_mapper_python
