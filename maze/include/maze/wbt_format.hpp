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
//
// World frame as in the maze: x east, y north, z up, metres. Each wall run is as long as the
// run plus the wall thickness (so corners close), as thick as the wall, and half a cell high.
// The start pose is also written as a comment: `# start: cell (0,0) facing north, x y yaw`.

#include <string>
#include <string_view>

#include "maze/maze.hpp"

namespace maze {

// `title` goes into WorldInfo (e.g. the world's file name).
std::string write_wbt(const Maze &maze, std::string_view title);

}  // namespace maze
