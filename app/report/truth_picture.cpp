#include "app/report/truth_picture.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "app/picture/map_picture.hpp"

namespace app {
namespace {

std::size_t flat(const maze::Maze &m, maze::Cell c) {
  return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(m.width()) + static_cast<std::size_t>(c.x);
}

// Where the maze is drawn: cell (x, y)'s top-left corner is origin + (x, H - 1 - y) * cell_px.
struct TruthLayout {
  int cell_px = 0;
  int side_px = 0;
  int height_cells = 0;
  int left(maze::Cell c) const { return side_px + c.x * cell_px; }
  int top(maze::Cell c) const { return side_px + (height_cells - 1 - c.y) * cell_px; }
};

// Each landmark a disc of its colour and the course's radius, ringed in black.
void draw_landmarks(Canvas &canvas, const TruthLayout &l, const maze::Maze &m) {
  const double px_per_m = l.cell_px / m.cell_size_m();
  for (const LandmarkMark &mark : landmark_marks(m)) {
    const int r = std::max(2, static_cast<int>(std::lround(mark.radius_m * px_per_m)));
    const int x = l.side_px + static_cast<int>(std::lround((mark.at.x_m - m.origin_x_m()) * px_per_m));
    const int y = l.side_px +
                  static_cast<int>(std::lround((m.height() * m.cell_size_m() - (mark.at.y_m - m.origin_y_m())) * px_per_m));
    canvas.disc(x, y, r + 1, Rgb{0, 0, 0});
    canvas.disc(x, y, r, mark.colour);
  }
}

TruthLayout layout_of(const TruthInput &in) {
  mapping::GridGeometry g;
  g.width_cells = in.truth->width();
  g.height_cells = in.truth->height();
  g.subcells = in.subcells;
  TruthLayout l;
  l.cell_px = in.subcells * map_scale(g);
  l.side_px = truth_side_px(l.cell_px);
  l.height_cells = in.truth->height();
  return l;
}

// The side drawn as a bar centred on the cell's edge; `fraction` of its length, centred.
void draw_side(Canvas &canvas, const TruthLayout &l, maze::Cell c, maze::Side s, Rgb colour, double fraction) {
  const int t = l.side_px;
  const int length = static_cast<int>(l.cell_px * fraction) + (fraction < 1.0 ? 0 : t);
  const int inset = (l.cell_px + t - length) / 2;
  const int x0 = l.left(c) - t / 2;
  const int y0 = l.top(c) - t / 2;
  switch (s) {
    case maze::Side::north: canvas.fill(x0 + inset, y0, length, t, colour); break;
    case maze::Side::south: canvas.fill(x0 + inset, y0 + l.cell_px, length, t, colour); break;
    case maze::Side::west: canvas.fill(x0, y0 + inset, t, length, colour); break;
    case maze::Side::east: canvas.fill(x0 + l.cell_px, y0 + inset, t, length, colour); break;
  }
}

void draw_cells(Canvas &canvas, const TruthLayout &l, const TruthInput &in, const std::vector<bool> &reachable) {
  const maze::Maze &m = *in.truth;
  for (int y = 0; y < m.height(); ++y) {
    for (int x = 0; x < m.width(); ++x) {
      const maze::Cell c{x, y};
      const Rgb tone = !reachable[flat(m, c)] ? kUnreachableTone
                       : (*in.visited)[flat(m, c)] ? Rgb{255, 255, 255} : kUnvisitedTone;
      canvas.fill(l.left(c), l.top(c), l.cell_px, l.cell_px, tone);
      if (!reachable[flat(m, c)]) {
        for (const maze::Side s : maze::kSides) {
          if (m.has_wall(c, s)) draw_side(canvas, l, c, s, kUnscoredWallColour, 1.0);
        }
      }
    }
  }
  draw_landmarks(canvas, l, m);  // first: the goals and the start are drawn over them
  for (const maze::Cell goal : m.goals()) {
    const int inset = l.cell_px / 8;
    canvas.frame(l.left(goal) + inset, l.top(goal) + inset, l.cell_px - 2 * inset, l.cell_px - 2 * inset,
                 std::max(1, l.cell_px / 14), kGoalColour);
  }
  const int side = std::max(1, l.cell_px / 3);
  const maze::Cell start = m.start();
  canvas.fill(l.left(start) + (l.cell_px - side) / 2, l.top(start) + (l.cell_px - side) / 2, side, side, kStartColour);
}

Legend truth_legend(const TruthInput &in, const TruthCounts &counts, const TruthLayout &l) {
  const MapScore score = counts.score();
  Legend legend;
  legend.lines.push_back(in.caption);
  legend.lines.push_back(fmt::format("wall_accuracy {:.2f}% ({}/{} sides)", score.wall_accuracy_percent(),
                                     score.sides_correct, score.sides));
  legend.lines.push_back(fmt::format("coverage {:.2f}% ({}/{} cells)", score.coverage_percent(),
                                     score.visited_reachable_cells, score.reachable_cells));
  legend.items = {{Swatch::line, kRightWallColour, "wall right"},
                  {Swatch::line, kMissedColour, fmt::format("missed ({})", counts.missed)},
                  {Swatch::line, kPhantomColour, fmt::format("phantom ({})", counts.phantom)},
                  {Swatch::line, kUnseenColour, fmt::format("unseen opening ({})", counts.unseen_opening)},
                  {Swatch::box, kUnvisitedTone, "not visited"},
                  {Swatch::box, kUnreachableTone, "unreachable"}};
  if (!in.truth->landmarks().empty()) legend.items.push_back({Swatch::disc, Rgb{0, 0, 0}, "landmark (its colour)"});
  legend.px_per_m = l.cell_px / in.truth->cell_size_m();
  return legend;
}

}  // namespace

MapScore TruthCounts::score() const {
  MapScore s;
  s.reachable_cells = reachable_cells;
  s.visited_reachable_cells = visited_reachable_cells;
  s.sides = right + missed + phantom + unseen_opening;
  s.sides_correct = right;
  return s;
}

std::vector<LandmarkMark> landmark_marks(const maze::Maze &truth) {
  const auto channel = [](double v) { return static_cast<unsigned char>(std::lround(255.0 * v)); };
  std::vector<LandmarkMark> marks;
  for (const maze::Landmark &l : truth.landmarks()) {
    marks.push_back({mapping::Point{l.x_m, l.y_m}, Rgb{channel(l.red), channel(l.green), channel(l.blue)},
                     maze::kLandmarkRadius_m});
  }
  return marks;
}

int truth_side_px(int cell_px) { return std::max(2, cell_px / 10); }

TruthCounts count_verdicts(const TruthInput &in) {
  const std::vector<bool> reachable = in.truth->reachable_from_start();
  TruthCounts counts;
  for (std::size_t i = 0; i < reachable.size(); ++i) {
    if (!reachable[i]) continue;
    ++counts.reachable_cells;
    if ((*in.visited)[i]) ++counts.visited_reachable_cells;
  }
  for_each_scored_side(*in.truth, reachable, [&](maze::Cell c, maze::Side s) {
    switch (judge_side(in.truth->has_wall(c, s), in.learned(c, s))) {
      case SideVerdict::right: ++counts.right; break;
      case SideVerdict::missed: ++counts.missed; break;
      case SideVerdict::phantom: ++counts.phantom; break;
      case SideVerdict::unseen_opening: ++counts.unseen_opening; break;
    }
  });
  return counts;
}

Canvas truth_picture(const TruthInput &in) {
  const maze::Maze &m = *in.truth;
  const TruthLayout l = layout_of(in);
  const std::vector<bool> reachable = m.reachable_from_start();
  const TruthCounts counts = count_verdicts(in);
  const int width = std::max(m.width() * l.cell_px + 2 * l.side_px, kMinPictureWidth);
  const int font = legend_font(width);
  const Legend legend = truth_legend(in, counts, l);
  const int map_height = m.height() * l.cell_px + 2 * l.side_px;
  Canvas canvas(width, map_height + legend_height(legend, width, font), Rgb{255, 255, 255});
  draw_cells(canvas, l, in, reachable);
  for_each_scored_side(m, reachable, [&](maze::Cell c, maze::Side s) {
    const bool wall = m.has_wall(c, s);
    switch (judge_side(wall, in.learned(c, s))) {
      case SideVerdict::right:
        if (wall) draw_side(canvas, l, c, s, kRightWallColour, 1.0);
        break;
      case SideVerdict::missed: draw_side(canvas, l, c, s, kMissedColour, 1.0); break;
      case SideVerdict::phantom: draw_side(canvas, l, c, s, kPhantomColour, 1.0); break;
      case SideVerdict::unseen_opening: draw_side(canvas, l, c, s, kUnseenColour, 0.5); break;
    }
  });
  draw_legend(canvas, map_height, legend, font);
  return canvas;
}

}  // namespace app
