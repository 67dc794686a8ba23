#pragma once
// map.png (and the snapshots): the learned grid as a picture a projector survives, north up,
// each sub-cell a square of map_scale() pixels, a legend strip under it.
//
//   tone     never observed: a blue-grey mid tone, kUnknownTone, whatever the prior
//            occupied (log-odds above 0, or at least --threshold): dark, 70 after one
//            occupied update down to 0 after four or more
//            free (observed, not occupied): light, 215 after one free update up to 255
//            after four or more
//            So one p_occ update already reads as a wall, and the three tones stay apart
//            for every model (the increments are the set-up's own, see MapTones).
//   marks    the path (cell centres in order of arrival) in red, the start a green square,
//            the end (where the robot stopped) a blue disc, each goal cell a gold frame; a
//            planned path (plan.png) through its sub-cells' centres in magenta; each landmark
//            a disc of its colour ringed in black
//   legend   the caption ("model cell, K 3", and a note such as a snapshot's step), what
//            each tone and mark means, and a scale bar in metres
// Written with libpng (app/picture/picture.hpp).

#include <optional>
#include <string>
#include <vector>

#include "app/picture/picture.hpp"
#include "mapping/grid_types.hpp"
#include "mapping/occupancy_grid.hpp"

namespace app {

inline constexpr Rgb kUnknownTone{150, 160, 190};
inline constexpr Rgb kPathColour{220, 30, 30};
inline constexpr Rgb kStartColour{20, 170, 40};
inline constexpr Rgb kEndColour{30, 90, 220};
inline constexpr Rgb kGoalColour{240, 170, 0};
inline constexpr Rgb kPlannedColour{200, 0, 200};

// What the tones are measured against, in the grid's log-odds.
struct MapTones {
  float initial_log_odds = 0.0f;        // l(prior): never observed
  std::optional<float> threshold;       // --threshold: occupied when >= this (default > 0)
  double occupied_increment = 0.4055;   // one occupied update of the set-up, > 0
  double free_increment = -0.8473;      // one free update of the set-up, < 0
};

Rgb tone(float log_odds, const MapTones &tones);

// A landmark of the world (maze::Landmark), where it stands in the world frame (m), its
// colour and radius.
struct LandmarkMark {
  mapping::Point at;
  Rgb colour;
  double radius_m = 0.0;
};

struct MapMarks {
  std::vector<mapping::Cell> path;   // cells in order of arrival, start first (may be empty)
  std::vector<mapping::Cell> goals;
  std::vector<mapping::SubCell> planned;  // a planned path (plan.png), sub-cell centres, in magenta
  std::vector<LandmarkMark> landmarks;    // discs of their colour, ringed in black
};

// Pixels a sub-cell: ceil(100 / K), so a cell is at least 100 px, lowered for big mazes so
// that the map stays within 4096 px a side where it can (never below 1).
int map_scale(const mapping::GridGeometry &geometry);

// The picture: the map at the top-left, at least kMinPictureWidth wide, the legend under it.
// `caption` is the legend's first line.
Canvas map_picture(const mapping::OccupancyGrid &grid, const MapTones &tones, const MapMarks &marks,
                   const std::string &caption);

// The pixel centre of a cell in a picture drawn at map_scale(geometry).
struct PixelPoint {
  int x = 0;
  int y = 0;
};
PixelPoint cell_centre_px(const mapping::GridGeometry &geometry, mapping::Cell c);

}  // namespace app
