#pragma once
// The metric map's former names, for the room replay page (app/room/room_replay.hpp) until it
// joins the one replay: include sensing/metric_map.hpp and use its names.

#include "sensing/metric_map.hpp"

namespace sensing {
using RoomMap = MetricMap;
using RoomBoundary = MetricBoundary;
}  // namespace sensing
