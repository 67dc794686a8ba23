#pragma once
// A room run's map scored against the truth at the map's resolution, and the frontier's ending
// the truth settles.

#include <cstddef>

#include "app/run/metric/run.hpp"
#include "maze/world/truth_raster.hpp"
#include "sensing/metric/map.hpp"

namespace app {

// The thresholded map against the truth (every cell, the observed ones) and the reachable free
// cells observed, into `summary`. Returns the first reachable free cell never observed
// (map.size() when none).
std::size_t score_metric_map(const sensing::MetricMap &map, const maze::TruthRaster &truth, double threshold,
                           MetricRunSummary &summary);
// Frontier's ending checked against the truth (after score_metric_map): `done` or `incomplete`
// becomes `done` when every reachable free cell is observed, else `incomplete` (first_left the
// first never observed); its message the share observed, the controller's own words and the
// cells never observed going to summary.frontier's detail.
void settle_frontier_ending(const sensing::MetricMap &map, std::size_t first_left, MetricRunSummary &summary);

}  // namespace app
