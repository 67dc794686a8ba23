#pragma once
// The size rules every picture of a run follows, a maze's or a room's, so that a teacher can
// put them side by side and a projector shows their marks: map.png, truth.png, plan.png and
// the snapshots of `run`; map.png, wave.png, truth.png and the snapshots of `room`; truth.png
// and map.png of a Python controller's run (python3 -m maze_mapper.run --out); and
// replay.html's view.
//
//   text    one font on the page, at least kLeastFontPx and a kFontShareOfHeight-th of the
//           page's height (figure.hpp's shared_page)
//   marks   the start (a square: its side), the robot (a disc: its diameter), a goal (a frame:
//           its side) and a landmark (a disc: its diameter) at least min_mark_px(font), that
//           is kMarkOfFont of the page's font: at least 8.4 px and a 67th of the page's
//           height. A mark whose size in the world is larger is drawn at that size (a maze
//           cell's third for the start, a landmark's radius, the robot's body in a replay). A
//           maze's goal is a cell, not a point: its frame stays inside its cell, whatever the
//           page (a larger one would frame the cells beside it).
//   crop    a picture in metres of a world whose floor has no walls at its edge (the course's
//           empty 17 x 17 m floor) shows the box round the world's solids, landmarks, start,
//           goals and the robot's path, grown by crop_margin_m on each side and kept inside
//           the floor; a walled world shows its whole floor
//   replay  replay.html draws the same marks in screen pixels at any zoom, its view taken as
//           the page: a mark at least kMarkOfFont x max(kLeastFontPx, view height /
//           kFontShareOfHeight) px (the page reads these numbers from its data block)

namespace app {

inline constexpr double kLeastFontPx = 14.0;
inline constexpr double kFontShareOfHeight = 40.0;
inline constexpr double kMarkOfFont = 0.6;

// The least size of a mark (above) on a page whose font is font_px.
inline double min_mark_px(double font_px) { return kMarkOfFont * font_px; }

// The margin round a cropped picture's box (above): a tenth of the box's longer side, and
// at least half a metre (a robot's length and its turn).
inline double crop_margin_m(double box_longer_side_m) {
  const double tenth = box_longer_side_m / 10.0;
  return tenth > 0.5 ? tenth : 0.5;
}

}  // namespace app
