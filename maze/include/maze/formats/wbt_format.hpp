#pragma once
// A Webots world (.wbt, R2023b syntax) of a maze, to open in Webots as it is:
//
//     #VRML_SIM R2023b utf8
//     EXTERNPROTO ".../TexturedBackground.proto"        the protos used, by URL
//     WorldInfo { ... }  Viewpoint { ... }              camera above the maze, north up
//     TexturedBackground { }  TexturedBackgroundLight { }
//     Solid { ... name "floor" }                        a thin box under the whole maze
//     Solid { translation X Y Z ... name "wall 1" }     one Solid per wall run (a Box shape
//     ...                                               and the same Box as boundingObject)
//     DEF START Pose { ... }                            start marker (a green "T" pointing the
//     Pose { ... }                                      start heading), goal markers (red
//                                                       tiles); no boundingObject
//     DEF ROBOT Robot { ... }                           when a robot is given (below)
//
// WorldInfo's basicTimeStep is the embedded simulator's (maze::sim::SimulationOptions,
// 32 ms), the step the controller runs at (it steps by Robot::getBasicTimeStep()).
//
// The robot is made of Webots' standard nodes only (no PROTO), its devices named as the
// profile names them, standing at the start cell's centre facing the start heading
// (translation X Y 0, rotation 0 0 1 YAW); robot frame x forward, y left, z up:
//
//     Robot { translation rotation  children [
//       Pose { Shape Cylinder }                 the body: profile body radius, on the floor's
//                                               clearance; also its boundingObject, with
//                                               physics (1 kg)
//       HingeJoint { axis 0 1 0  device [ RotationalMotor PositionSensor ]  endPoint Solid }
//                                               left wheel at y = +axle/2, right at -axle/2,
//                                               wheel radius, motor maxVelocity from the profile
//       BallJoint { endPoint Solid }            a caster ball in front and one behind
//       Lidar { ... }                           each profile lidar on top of the body: resolution,
//                                               fieldOfView, minRange, maxRange, noise; one layer
//       InertialUnit { }  GPS { }               when the profile has them
//       DistanceSensor { lookupTable ... }      on the rim at their angle, one per profile sensor
//       TouchSensor { type "bumper" ... }       a box on the rim over each bumper's arc
//     ]  controller "NAME"  controllerArgs [ "--size=4x4" ... ] }
// World frame as in the maze: x east, y north, z up, metres. Each wall run is as long as the
// run plus the wall thickness (so corners close), as thick as the wall, and half a cell high.
// The start pose is also written as a comment: `# start: cell (0,0) facing north, x y yaw`.

#include <string>
#include <string_view>
#include <vector>

#include "maze/world/maze.hpp"
#include "maze/sim/profile.hpp"

namespace maze {

// The robot a world carries.
struct WbtRobot {
  const sim::RobotProfile *profile = nullptr;  // nullptr: the maze alone, no robot
  std::string controller = "maze_mapper_controller";  // controllers/<name>/<name>
  std::vector<std::string> controller_args;    // the Robot's controllerArgs, one string each
};

// The basic time step the world is written with (ms): the embedded simulator's.
int wbt_basic_time_step_ms();

// `title` goes into WorldInfo (e.g. the world's file name). Strings are written with '"' and
// '\\' escaped.
std::string write_wbt(const Maze &maze, std::string_view title, const WbtRobot &robot = {});

}  // namespace maze
