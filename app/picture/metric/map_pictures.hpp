#pragma once
// The room run's pictures (app/picture's drawing and page layout, as the maze's map.png and
// map-log's pictures), north up, one block a map cell, the axes in metres, every picture of a
// run on one page size (metric_page). On each: the world's boundary, solid all round, as a
// black wall outside it (a band round the grid: plain_grid_picture.hpp), and the world's
// landmarks as discs of their colour (neutral grey where the world does not give it), ringed
// in black, under the other marks.
//
//   map    the log-odds in map.png's tones (occupied dark, free light, graded by the
//          set-up's own increments; never observed blue-grey), the trajectory in red from the
//          start (green square) to the robot (blue disc), the last plan in magenta, each goal
//          a yellow frame; a colour bar of the tones and a scale bar.
//   wave   the wavefront's numbers as the labs grade them, drawn: blocked cells (1, the
//          obstacles grown) dark grey, the goal (2) yellow, each cell the wave reached in a
//          tone from light (near the goal) to deep blue (the farthest), cells it never
//          reached (0) white; the path and the robot over it.
//   truth  the map scored against the truth at the map's resolution, as the summary's
//          cell_accuracy and coverage count it (their percentages in the legend): occupied
//          cells learned right near-black, missed (mapped free) red, phantoms (occupied on
//          the map, free in truth) magenta, free cells white where reachable and light grey
//          where not, cells never observed blue-grey; the trajectory, start, goals and robot
//          over it.
// The marks (start, robot, goals, landmarks) follow app/picture/size_rules.hpp: at least
// min_mark_px of the page's font, larger where a map cell is.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/picture/drawing.hpp"
#include "app/picture/map_picture.hpp"
#include "app/picture/plain_grid_picture.hpp"
#include "maze/world/truth_raster.hpp"
#include "mapping/grid_types.hpp"
#include "robot/metric/controller.hpp"
#include "sensing/metric/map.hpp"

namespace app {

// What both pictures mark besides the controller's own state.
struct MetricPictureMarks {
  mapping::Point start;
  std::vector<mapping::Point> goals;  // the world's goal points and the run's --goal, each a frame
  std::optional<PlainGridBounds> boundary;  // the world's boundary (solid all round), within the map's extent
  std::vector<LandmarkMark> landmarks;
  std::string caption;  // the legend's first line: the world, the strategy, the set-up
  std::string when;     // the second line of the map's and the wave's: "step 50, 1.6 s" (may be empty)
};

// The map tones of a room run: the map's prior and the set-up's increments, --threshold.
MapTones metric_map_tones(const sensing::MetricMap &map, const sensing::MarkProbabilities &p, double threshold);

// Where the robot has been and stands on a map picture: its trajectory after the start
// (marks.start), its last plan (cells of the map by flat index, empty for none), its pose.
// The spans must outlive the call.
struct MetricRobotMarks {
  std::span<const mapping::Point> trajectory;
  std::span<const std::size_t> plan;
  mapping::Point position;
  double yaw_rad = 0.0;
  // Trajectory indices (ascending) a supervisor set the robot down on: no line drawn to them.
  std::span<const std::size_t> placed = {};
};

// The map as the controller holds it now: tones, trajectory, last plan, start, goal, robot.
std::string metric_map_picture(const robot::MetricController &c, const MapTones &tones, const MetricPictureMarks &marks,
                             PictureFormat format = PictureFormat::png);
// The same picture of any map on the room's grid (a Python controller's kept map).
std::string metric_map_picture(const sensing::MetricMap &map, const MetricRobotMarks &robot, const MapTones &tones,
                             const MetricPictureMarks &marks, PictureFormat format = PictureFormat::png);

// The wave the controller planned on last (non-empty), with the path and the robot.
std::string metric_wave_picture(const robot::MetricController &c, const MetricPictureMarks &marks,
                              PictureFormat format = PictureFormat::png);

// What the truth picture's legend prints: the summary's scores, as it words them.
struct MetricTruthScores {
  std::string cell_accuracy;  // "89.13% (1337 of 1500 cells right; ...)"
  std::string coverage;       // "98.56% (1229 of 1247 reachable free cells observed)"
};

// The map scored against `truth` (the same grid), cells at or above `threshold` occupied.
std::string metric_truth_picture(const robot::MetricController &c, const maze::TruthRaster &truth, double threshold,
                               const MetricPictureMarks &marks, const MetricTruthScores &scores,
                               PictureFormat format = PictureFormat::png);

// The page every picture of a room run on this map is drawn on (map, wave, truth, their
// snapshots): one size, one font and one scale, so that they can be flipped between.
PageFrame metric_page(const sensing::MetricMap &map, const MetricPictureMarks &marks);

// The tone of a wave number (plan/metric/wavefront.hpp's): `top` the largest in the wave.
Rgb wave_tone(std::int32_t value, std::int32_t top);

}  // namespace app
