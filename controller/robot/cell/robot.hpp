#pragma once
// The robot a cell-by-cell controller drives: its devices (Drive, Senses), its grid and
// visits, where it is, and the few moves every cell controller makes - arrive (scan and do
// the set-up's arrival), turn to a heading, drive into the neighbouring cell - with the
// step and move reports. CellController asks a strategy which move to make next;
// CommandController takes them as commands from outside (an mms-protocol algorithm).

#include <cstdint>
#include <string>
#include <vector>

#include "explore/strategies.hpp"
#include "explore/visits.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"
#include "mapping/sensor_model.hpp"
#include "robot/arrival.hpp"
#include "robot/cell/controller.hpp"
#include "robot/control_loop.hpp"
#include "robot/drive.hpp"
#include "robot/options.hpp"
#include "robot/senses.hpp"

namespace webots {
class Robot;
}

namespace robot {

struct CellRobot {
  // Validates the options (common::InputError) and finds the devices (common::InputError
  // naming one the robot lacks). The robot must outlive this.
  CellRobot(webots::Robot &r, const ControllerOptions &o);
  CellRobot(const CellRobot &) = delete;
  CellRobot &operator=(const CellRobot &) = delete;

  // Enables the devices, takes the first step in the start cell and arrives there.
  Motion start();
  // One control step; the step before it is reported first (once its scans are done).
  Motion step(Action action);
  // Reports the last step; false when the step observer stops the run.
  bool flush_step();
  // Arrives in the robot's cell (scan, the set-up's arrival) and reports it.
  Motion arrive(bool new_cell);
  // Turns in place to heading h and records it on the cell.
  Motion turn_to(mapping::Heading h);
  // Drives along the heading into the neighbouring cell (no arrival).
  Motion drive_ahead();
  // The ending a motion that was not ok stands for; keeps the drive's failure as the message.
  EndReason ended(Motion s);

  webots::Robot &robot;
  ControllerOptions options;
  mapping::SensorModel model;
  float initial;
  mapping::OccupancyGrid grid;
  explore::Visits visits;
  WebotsChassis chassis;
  ControlLoop loop;  // every control step; its count is the run's steps
  Drive drive;
  Senses senses;
  explore::WallQuery walls;  // the side states the grid holds
  Arrival arrival;

  RunHooks hooks;
  StepReport pending;
  bool has_pending = false;
  mapping::Cell cell;  // where the robot is (the cell it left, while it moves)
  mapping::Heading heading = mapping::Heading::north;
  int moves = 0;
  std::vector<mapping::Cell> path;  // cells in order of arrival, start first
  std::string message;
};

}  // namespace robot
