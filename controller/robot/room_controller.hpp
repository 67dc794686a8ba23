#pragma once
// The metric controller's former name, for the room replay page (app/room/room_replay.hpp)
// until it joins the one replay: include robot/metric_controller.hpp and use its names.

#include "robot/metric_controller.hpp"

namespace robot {
using RoomController = MetricController;
}  // namespace robot
