// The metric map a Python controller keeps (python/src/kept_map.hpp).

#include "kept_map.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "common/error.hpp"
#include "mapping/log_odds.hpp"

namespace maze_mapper_python {

namespace {

constexpr const char *kArrayWords = "a 2-D array of numbers, map[j, i] (row j from the south, column i from the west)";

MapValues values_of(const std::string &word) {
  if (word == "log_odds") return MapValues::log_odds;
  if (word == "probability") return MapValues::probability;
  throw common::InputError(fmt::format("keep_map: values must be log_odds or probability (got '{}')", word));
}

// The array's shape, rows and columns, when it is a non-empty 2-D array of numbers.
std::pair<py::ssize_t, py::ssize_t> array_shape(const py::handle &source) {
  const py::array a = py::array::ensure(source);
  if (!a || a.ndim() != 2) throw common::InputError(fmt::format("keep_map: the map must be {}", kArrayWords));
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b') {
    throw common::InputError(fmt::format("keep_map: the map must be {} (got dtype {})", kArrayWords,
                                         std::string(py::str(a.dtype()))));
  }
  return {a.shape(0), a.shape(1)};
}

sensing::MetricGridSpec spec_of(std::pair<double, double> origin, double cell_m, py::ssize_t rows, py::ssize_t columns) {
  if (!(std::isfinite(origin.first) && std::isfinite(origin.second))) {
    throw common::InputError(fmt::format("keep_map: origin must be the map's south-west corner in metres (got ({}, {}))",
                                         origin.first, origin.second));
  }
  if (!(std::isfinite(cell_m) && cell_m > 0.0)) {
    throw common::InputError(fmt::format("keep_map: cell_size_m must be a length above 0 (got {})", cell_m));
  }
  const auto most = static_cast<py::ssize_t>(sensing::kMaxMetricCellsPerSide);
  if (rows < 1 || columns < 1 || rows > most || columns > most) {
    throw common::InputError(fmt::format("keep_map: the map must have 1 to {} cells a side (got {} rows x {} columns)",
                                         most, rows, columns));
  }
  sensing::MetricGridSpec spec;
  spec.cells_x = static_cast<int>(columns);
  spec.cells_y = static_cast<int>(rows);
  spec.cell_m = cell_m;
  spec.boundary = {origin.first, origin.first + cell_m * spec.cells_x, origin.second, origin.second + cell_m * spec.cells_y};
  sensing::validate(spec);
  return spec;
}

// A value as the map's log-odds: never observed (NaN, a probability outside 0 ... 1) at
// `initial`, beyond +-kMaxShownLogOdds at the bound.
float as_log_odds(double value, MapValues values, mapping::LogBase base, float initial) {
  if (std::isnan(value)) return initial;
  if (values == MapValues::probability) {
    if (value < 0.0 || value > 1.0) return initial;
    value = value <= 0.0 ? -kMaxShownLogOdds : value >= 1.0 ? kMaxShownLogOdds : mapping::log_odds(value, base);
  }
  return static_cast<float>(std::clamp(value, -kMaxShownLogOdds, kMaxShownLogOdds));
}

template <typename T>
void read_array(const py::array_t<T> &a, MapValues values, mapping::LogBase base, float initial,
                std::vector<float> &cells) {
  const auto r = a.template unchecked<2>();
  cells.resize(static_cast<std::size_t>(r.shape(0)) * static_cast<std::size_t>(r.shape(1)));
  std::size_t n = 0;
  for (py::ssize_t j = 0; j < r.shape(0); ++j) {
    for (py::ssize_t i = 0; i < r.shape(1); ++i) cells[n++] = as_log_odds(static_cast<double>(r(j, i)), values, base, initial);
  }
}

// An OccupancyGrid's sub-cells as cells: sub-cell (x, y) of the whole grid (x from the west,
// y from the south) is cell (x, y).
void read_grid(const PyGrid &g, std::vector<float> &cells) {
  const int columns = g.grid.width() * g.grid.k();
  const int rows = g.grid.height() * g.grid.k();
  cells.resize(g.grid.size());
  std::size_t n = 0;
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < columns; ++x) cells[n++] = g.grid.at(mapping::SubCell{x, y});
  }
}

}  // namespace

KeptMap::KeptMap(py::object source, std::optional<std::pair<double, double>> origin, std::optional<double> cell_size_m,
                 std::optional<mapping::SensorModel> model, const std::string &values)
    : source_(std::move(source)), is_grid_(py::isinstance<PyGrid>(source_)), values_(values_of(values)) {
  if (is_grid_) {
    if (origin || cell_size_m || model || values_ != MapValues::log_odds) {
      throw common::InputError(
          "keep_map: an OccupancyGrid carries its own origin, cell size and model (give only the grid)");
    }
    const PyGrid &g = source_.cast<const PyGrid &>();
    model_ = g.model;
    const mapping::GridGeometry &geometry = g.grid.geometry();
    spec_ = spec_of({geometry.origin.x_m, geometry.origin.y_m}, geometry.cell_size_m / geometry.subcells,
                    static_cast<py::ssize_t>(geometry.height_cells) * geometry.subcells,
                    static_cast<py::ssize_t>(geometry.width_cells) * geometry.subcells);
    return;
  }
  const auto [rows, columns] = array_shape(source_);
  if (!origin || !cell_size_m) {
    throw common::InputError("keep_map: an array needs origin=(x_m, y_m), its south-west corner, and cell_size_m, "
                             "its cells' side in metres");
  }
  if (model) model_ = *model;
  spec_ = spec_of(*origin, *cell_size_m, rows, columns);
}

app::MapTones KeptMap::tones() const {
  app::MapTones tones;
  tones.initial_log_odds = initial_log_odds();
  tones.occupied_increment = model_.occupied_increment();
  tones.free_increment = model_.free_increment();
  return tones;
}

app::MapView KeptMap::view() const {
  app::MapView view;
  view.spec = spec_;
  view.initial_log_odds = initial_log_odds();
  view.tones = tones();
  view.read = [this](std::vector<float> &cells) { return read(cells); };
  return view;
}

bool KeptMap::read(std::vector<float> &cells) const {
  if (is_grid_) {
    read_grid(source_.cast<const PyGrid &>(), cells);
    return true;
  }
  const py::array a = py::array::ensure(source_);
  if (!a || a.ndim() != 2 || a.shape(0) != spec_.cells_y || a.shape(1) != spec_.cells_x) return false;
  const mapping::LogBase base = model_.options().base;
  if (a.dtype().kind() == 'f' && a.itemsize() == sizeof(float)) {
    read_array(py::array_t<float>(a), values_, base, initial_log_odds(), cells);
  } else {
    read_array(py::array_t<double, py::array::forcecast>::ensure(a), values_, base, initial_log_odds(), cells);
  }
  return true;
}

sensing::MetricMap KeptMap::metric_map() const {
  std::vector<float> cells;
  if (!read(cells)) {
    const py::array a = py::array::ensure(source_);
    std::string now = "no 2-D array";
    if (a && a.ndim() == 2) now = fmt::format("{} x {}", a.shape(0), a.shape(1));
    throw common::InputError(fmt::format("the kept map's shape is now {}, kept as {} x {} (keep_map it again)", now,
                                         spec_.cells_y, spec_.cells_x));
  }
  sensing::MetricMap map(spec_, model_);
  std::copy(cells.begin(), cells.end(), map.log_grid().log_odds.begin());
  return map;
}

std::string KeptMap::description() const {
  return fmt::format("{} x {} cells of {:g} m from ({:.2f}, {:.2f})", spec_.cells_x, spec_.cells_y, spec_.cell_m,
                     spec_.boundary.x_start_m, spec_.boundary.y_start_m);
}

void bind_kept_map(py::module_ &m) {
  py::class_<KeptMap>(m, "KeptMap", "A controller's metric map as the runner keeps it (maze_mapper.keep_map).")
      .def(py::init<py::object, std::optional<std::pair<double, double>>, std::optional<double>,
                    std::optional<mapping::SensorModel>, const std::string &>(),
           py::arg("map"), py::kw_only(), py::arg("origin") = py::none(), py::arg("cell_size_m") = py::none(),
           py::arg("model") = py::none(), py::arg("values") = "log_odds")
      .def_property_readonly("cells_x", [](const KeptMap &k) { return k.spec().cells_x; })
      .def_property_readonly("cells_y", [](const KeptMap &k) { return k.spec().cells_y; })
      .def_property_readonly("cell_size_m", [](const KeptMap &k) { return k.spec().cell_m; })
      .def_property_readonly("origin",
                             [](const KeptMap &k) {
                               return std::make_pair(k.spec().boundary.x_start_m, k.spec().boundary.y_start_m);
                             })
      .def_property_readonly(
          "log_odds",
          [](const KeptMap &k) {
            std::vector<float> cells;
            if (!k.read(cells)) k.metric_map();  // raises the error that says how the shape changed
            py::array_t<float> a({static_cast<py::ssize_t>(k.spec().cells_y), static_cast<py::ssize_t>(k.spec().cells_x)});
            std::copy(cells.begin(), cells.end(), a.mutable_data());
            return a;
          },
          "The map now as the runner reads it: log-odds, [j, i] (row j from the south), never observed at l(prior).")
      .def("__str__", &KeptMap::description);
}

}  // namespace maze_mapper_python
