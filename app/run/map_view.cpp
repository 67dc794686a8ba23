#include "app/run/map_view.hpp"

namespace app {

MapView map_view(const sensing::MetricMap &map, const MapTones &tones) {
  MapView view;
  view.spec = map.spec();
  view.initial_log_odds = static_cast<float>(map.model().prior_log_odds());
  view.tones = tones;
  view.read = [&map](std::vector<float> &cells) {
    cells.resize(map.size());
    for (std::size_t n = 0; n < cells.size(); ++n) cells[n] = static_cast<float>(map.log_odds_at(n));
    return true;
  };
  return view;
}

}  // namespace app
