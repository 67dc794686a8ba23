#pragma once
// A read-only view of the map a controller keeps, as the run's observers see it (pictures,
// replay.html): square cells in metres over the floor, each read as a log-odds, drawn in the
// run's tones. The room's metric map, a Python controller's kept array or grid, and none
// (a controller that keeps no map: its run is drawn as the world and the path) are views.

#include <functional>
#include <vector>

#include "app/picture/map_picture.hpp"
#include "sensing/metric/map.hpp"

namespace app {

struct MapView {
  sensing::MetricGridSpec spec;    // cells_x * cells_y cells of cell_m; cells_x 0: no map
  float initial_log_odds = 0.0F;   // a cell never observed
  MapTones tones;
  // The map now: cell (i, j), j from the south, at j * cells_x + i, into `cells` (resized).
  // False, `cells` untouched, when the map can no longer be read on `spec`.
  std::function<bool(std::vector<float> &cells)> read;

  bool empty() const { return spec.cells_x == 0; }
  std::size_t size() const {
    return static_cast<std::size_t>(spec.cells_x) * static_cast<std::size_t>(spec.cells_y);
  }
};

// The view of a metric map (which must outlive it) in `tones`.
MapView map_view(const sensing::MetricMap &map, const MapTones &tones);

}  // namespace app
