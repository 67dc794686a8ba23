#pragma once
// truth.png: the true maze with what the run learned of it (only the composition root holds
// both). North up, each cell a square of K * map_scale() pixels inside a margin of one side's
// thickness, the same map area as map.png's (map_margin_px):
//
//   cell     visited: white; reachable but never visited: shaded kUnvisitedTone;
//            unreachable from the start: kUnreachableTone
//   side     each side wall_accuracy scores (app/run/evaluation.hpp), by its verdict, and
//            the legend's words for it:
//              right wall      kRightWallColour (black), "wall, mapped correctly"
//              right opening   nothing drawn
//              missed          kMissedColour (red), "wall the map missed": a true wall the map lacks
//              phantom         kPhantomColour (magenta), "wall the map invented"
//              unseen opening  kUnseenColour (blue-grey), the middle half of the side only,
//                              "opening never seen"
//            the walls of unreachable cells, not scored, in kUnscoredWallColour
//   marks    the start a green square, the goals gold frames (app/picture/map_picture.hpp), each
//            landmark a disc of its colour ringed in black, as wide as the course's cylinder
//   axes     cell indices (x, y)
//   legend   the caption ("truth: maze8x8.txt, model cell, K 3"), "wall_accuracy 97.50%
//            (156/160 sides)" and "coverage 93.75% (15/16 cells)", the numbers of the summary,
//            then the colours with the counts ("wall the map missed (2)", ...) and a scale bar
//            in metres.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/run/evaluation.hpp"
#include "app/picture/map_picture.hpp"
#include "app/picture/drawing.hpp"
#include "maze/world/geometry.hpp"
#include "maze/world/maze.hpp"

namespace app {

inline constexpr Rgb kUnvisitedTone{200, 200, 200};
inline constexpr Rgb kUnreachableTone{120, 120, 120};
inline constexpr Rgb kRightWallColour{20, 20, 20};
inline constexpr Rgb kMissedColour{220, 30, 30};
inline constexpr Rgb kPhantomColour{200, 0, 200};
inline constexpr Rgb kUnseenColour{90, 110, 170};
inline constexpr Rgb kUnscoredWallColour{160, 160, 160};

struct TruthCounts {
  std::size_t right = 0;
  std::size_t missed = 0;
  std::size_t phantom = 0;
  std::size_t unseen_opening = 0;
  std::size_t reachable_cells = 0;
  std::size_t visited_reachable_cells = 0;

  // The same numbers as the summary's score (right = sides_correct).
  MapScore score() const;
};

struct TruthInput {
  const maze::Maze *truth = nullptr;
  const std::vector<bool> *visited = nullptr;  // [y * W + x]
  std::function<LearnedSide(maze::Cell, maze::Side)> learned;
  int subcells = 3;                            // K, for the scale of map.png
  std::string caption;                         // the legend's first line
};

TruthCounts count_verdicts(const TruthInput &input);

// The side's thickness and the margin, in pixels, for a cell `cell_px` wide.
int truth_side_px(int cell_px);

// The figure truth_picture draws: its map area (map.png's, app/picture/map_picture.hpp), axes
// and legend (for shared_page).
Figure truth_figure(const TruthInput &input);
// The picture on its own page, or on `page` (shared with the run's other pictures).
Drawing truth_picture(const TruthInput &input, PictureFormat format = PictureFormat::png,
                      const std::optional<PageFrame> &page = std::nullopt);
// Where cell (0, H - 1)'s top-left corner is in the picture of `truth` at K `subcells`.
PointPx truth_origin_px(const maze::Maze &truth, int subcells);

// The maze's landmarks as the pictures mark them.
std::vector<LandmarkMark> landmark_marks(const maze::Maze &truth);
// A geometry's cylinders: a landmark's in its colour, a supervisor's cylinder without one.
std::vector<LandmarkMark> landmark_marks(const maze::Arena &geometry);

}  // namespace app
