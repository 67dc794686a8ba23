#pragma once
// The pictures and the replay of a Python controller's run drawn in metres (python3 -m
// maze_mapper.run --out): on an arena, and on a maze whose controller kept no cell grid.
//
//   truth.png    the world (its solids, boundary and landmarks), the robot's path, the start,
//                the goals and the robot: no score, for the runner knows no map to score; on an
//                open floor cropped to what stands and moved on it (shown_part)
//   map.png      the metric map the controller kept (maze_mapper.keep_map), drawn as `room
//                --out` draws its map.png (app/picture/metric/map_pictures.hpp), with the path
//   replay.html  the one replay page (app/report/replay.hpp) in metres: every pose of
//                trace.csv, the kept map's frames (app/report/map_frames.hpp); without a kept
//                map the world's walls and the path over a grid never observed, on shown_part

#include <string>
#include <utility>
#include <vector>

#include "app/report/map_frames.hpp"
#include "app/report/replay.hpp"
#include "kept_map.hpp"
#include "maze/world/world.hpp"
#include "pose_trace.hpp"

namespace maze_mapper_python {

// What the pictures and the replay show besides the map and the path.
struct MetresRunMarks {
  const maze::World *world = nullptr;
  double body_radius_m = 0.0;
  std::vector<std::pair<std::string, std::string>> summary;  // the printed summary's lines
};

// The part of the world a picture of the run shows (app/picture/size_rules.hpp's crop): a
// walled world whole; on an open floor (the course's empty 17 x 17 m floor, a course world
// whose walls stand on it) the box round its solids, landmarks, goals, the start and the path
// from `visits`, grown by crop_margin_m, within the floor.
maze::Arena shown_part(const maze::Arena &arena, const std::vector<PoseTrace::Visit> &visits);

// truth.png: the world's shown_part, its solids and landmarks, the path from `visits`, the
// start, the goals and the robot (its body of body_radius_m) where it ended.
std::string world_truth_png(const maze::World &world, const std::vector<PoseTrace::Visit> &visits, double body_radius_m);

// map.png of the kept map, with the path from `visits`.
std::string kept_map_png(const KeptMap &kept, const std::vector<PoseTrace::Visit> &visits, const MetresRunMarks &marks);

// replay.html's input: the frames recorded (a pose a trace row), the world's marks.
app::ReplayInput metres_replay_input(const app::MapFrames &frames, const KeptMap *kept,
                                     const std::vector<PoseTrace::Visit> &visits, const MetresRunMarks &marks);

}  // namespace maze_mapper_python
