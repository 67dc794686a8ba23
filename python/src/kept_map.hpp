#pragma once
// The metric map a Python controller hands the runner (maze_mapper.keep_map): a grid of
// square cells in metres over the floor, the counterpart of a maze's kept 4D grid, drawn as
// map.png and in replay.html by `python3 -m maze_mapper.run --out` on an arena.
//
//   a NumPy 2-D array  map[j, i]: row j from the south, column i from the west (an array
//                      whose row 0 is the northern row is array[::-1]); cell (i, j) covers
//                      [x0 + i cell, x0 + (i + 1) cell) x [y0 + j cell, ...), (x0, y0) its
//                      `origin`, the map's south-west corner. Its values log-odds in the
//                      model's base (the course's mapping lab's), or probabilities
//                      (values "probability": l = log_b(p / (1 - p))). A value that is NaN
//                      (or, for probabilities, outside 0 ... 1, as ROS's -1) is never observed,
//                      as is one equal to the model's l(prior); log-odds beyond +-kMaxShownLogOdds
//                      (a probability of 0 or 1) are drawn as +-kMaxShownLogOdds.
//   an OccupancyGrid   its sub-cells as the cells (cell_size_m / K a side), its origin and model.
//
// The runner keeps the object, not a copy: the map is read when a replay frame is due and
// when the run ends, as the controller has it then.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/picture/map_picture.hpp"
#include "app/run/map_view.hpp"
#include "bindings.hpp"
#include "mapping/sensor_model.hpp"
#include "sensing/metric/map.hpp"

namespace maze_mapper_python {

inline constexpr double kMaxShownLogOdds = 100.0;

enum class MapValues { log_odds, probability };

class KeptMap {
 public:
  // Checks the map and its extent; throws common::InputError with a line that says what is
  // wrong (not a 2-D array of numbers, no origin or cell size for an array, ...).
  KeptMap(py::object source, std::optional<std::pair<double, double>> origin, std::optional<double> cell_size_m,
          std::optional<mapping::SensorModel> model, const std::string &values);

  const sensing::MetricGridSpec &spec() const { return spec_; }
  const mapping::SensorModel &model() const { return model_; }
  std::size_t size() const { return static_cast<std::size_t>(spec_.cells_x) * static_cast<std::size_t>(spec_.cells_y); }
  float initial_log_odds() const { return static_cast<float>(model_.prior_log_odds()); }
  // map.png's tones: never observed at l(prior), graded by the model's increments.
  app::MapTones tones() const;

  // The map now as log-odds, cell (i, j) at j * cells_x + i, into `cells` (resized). False,
  // `cells` untouched, when the array's shape is no longer the one kept.
  bool read(std::vector<float> &cells) const;
  // The view the run's pictures and replay read (app/run/map_view.hpp); this map must outlive it.
  app::MapView view() const;
  // The same as a MetricMap on `model()` (which must outlive it); throws common::InputError
  // when the array's shape changed since it was kept.
  sensing::MetricMap metric_map() const;

  // "80 x 60 cells of 0.05 m from (-2.00, -1.50)"
  std::string description() const;

 private:
  py::object source_;
  bool is_grid_ = false;  // an OccupancyGrid, else an array
  MapValues values_ = MapValues::log_odds;
  mapping::SensorModel model_;
  sensing::MetricGridSpec spec_;
};

void bind_kept_map(py::module_ &m);

}  // namespace maze_mapper_python
