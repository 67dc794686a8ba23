#include "app/report/truth_picture.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "app/picture/map_picture.hpp"
#include "app/picture/size_rules.hpp"

namespace app {
namespace {

std::size_t flat(const maze::Maze &m, maze::Cell c) {
  return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(m.width()) + static_cast<std::size_t>(c.x);
}

// Where the maze is drawn: cell (x, y)'s top-left corner is origin + side_px + (x, H - 1 - y)
// * cell_px, origin the map area's top-left corner.
struct TruthLayout {
  PointPx origin;
  double cell_px = 0;
  double side_px = 0;
  int height_cells = 0;
  double left(maze::Cell c) const { return origin.x + side_px + c.x * cell_px; }
  double top(maze::Cell c) const { return origin.y + side_px + (height_cells - 1 - c.y) * cell_px; }
};

// Each landmark a disc of its colour and the course's radius, ringed in black.
void draw_landmarks(Drawing &page, const TruthLayout &l, const maze::Maze &m, double least_mark_px) {
  const double px_per_m = l.cell_px / m.cell_size_m();
  for (const LandmarkMark &mark : landmark_marks(m)) {
    const PointPx at{l.origin.x + l.side_px + (mark.at.x_m - m.origin_x_m()) * px_per_m,
                     l.origin.y + l.side_px + (m.height() * m.cell_size_m() - (mark.at.y_m - m.origin_y_m())) * px_per_m};
    draw_landmark(page, mark, at, px_per_m, least_mark_px);
  }
}

Figure truth_frame(const TruthInput &in) {
  mapping::GridGeometry g;
  g.width_cells = in.truth->width();
  g.height_cells = in.truth->height();
  g.subcells = in.subcells;
  const int cell_px = in.subcells * map_scale(g);
  const int side_px = map_margin_px(g);
  Figure fig;
  fig.map_w_px = in.truth->width() * cell_px + 2 * side_px;
  fig.map_h_px = in.truth->height() * cell_px + 2 * side_px;
  fig.axes = Axes{in.truth->width(), in.truth->height(), static_cast<double>(cell_px), 0, 0, static_cast<double>(side_px)};
  return fig;
}

TruthLayout layout_of(const TruthInput &in, PointPx origin) {
  const Figure fig = truth_frame(in);
  TruthLayout l;
  l.origin = origin;
  l.cell_px = fig.axes->cell_px;
  l.side_px = fig.axes->offset_px;
  l.height_cells = in.truth->height();
  return l;
}

// The side as a bar centred on the cell's edge; `fraction` of its length, centred.
RectPx side_rect(const TruthLayout &l, maze::Cell c, maze::Side s, double fraction) {
  const double t = l.side_px;
  const double length = l.cell_px * fraction + (fraction < 1.0 ? 0 : t);
  const double inset = (l.cell_px + t - length) / 2;
  const double x0 = l.left(c) - t / 2;
  const double y0 = l.top(c) - t / 2;
  switch (s) {
    case maze::Side::north: return {x0 + inset, y0, length, t};
    case maze::Side::south: return {x0 + inset, y0 + l.cell_px, length, t};
    case maze::Side::west: return {x0, y0 + inset, t, length};
    case maze::Side::east: return {x0 + l.cell_px, y0 + inset, t, length};
  }
  return {};
}

// The rows y (first, last; south to north) of the cells whose sides may reach into the
// picture's rows [top_px, bottom_px): a side reaches half a side's thickness beyond its cell.
std::pair<int, int> cell_rows_in(const TruthLayout &l, double top_px, double bottom_px) {
  const double first_row_top = l.origin.y + l.side_px;
  const auto picture_row = [&](double y_px) { return static_cast<int>(std::floor((y_px - first_row_top) / l.cell_px)); };
  const int top_row = std::max(0, picture_row(top_px - l.side_px) - 1);
  const int bottom_row = std::min(l.height_cells - 1, picture_row(bottom_px + l.side_px) + 1);
  return {l.height_cells - 1 - bottom_row, l.height_cells - 1 - top_row};
}

// The walls of the cells never reachable from the start (each cell its own four sides).
Drawing::RectsInRows unscored_walls(const TruthLayout &l, const maze::Maze &m, const std::vector<bool> &reachable) {
  return [&l, &m, &reachable](double top_px, double bottom_px, const Drawing::RectSink &add) {
    const auto [first, last] = cell_rows_in(l, top_px, bottom_px);
    for (int y = first; y <= last; ++y) {
      for (int x = 0; x < m.width(); ++x) {
        const maze::Cell c{x, y};
        if (reachable[flat(m, c)]) continue;
        for (const maze::Side s : maze::kSides) {
          if (m.has_wall(c, s)) add(side_rect(l, c, s, 1.0));
        }
      }
    }
  };
}

// The scored sides of one verdict, as drawn: a right side only where it is a wall, an unseen
// opening as the middle half of its side.
Drawing::RectsInRows sides_judged(const TruthLayout &l, const TruthInput &in, const std::vector<bool> &reachable,
                                  SideVerdict verdict) {
  return [&l, &in, &reachable, verdict](double top_px, double bottom_px, const Drawing::RectSink &add) {
    const maze::Maze &m = *in.truth;
    const double length = verdict == SideVerdict::unseen_opening ? 0.5 : 1.0;
    const auto [first, last] = cell_rows_in(l, top_px, bottom_px);
    for (int y = first; y <= last; ++y) {
      for_each_scored_side_in_row(m, reachable, y, [&](maze::Cell c, maze::Side s) {
        const bool wall = m.has_wall(c, s);
        if (judge_side(wall, in.learned(c, s)) == verdict && (wall || verdict != SideVerdict::right)) {
          add(side_rect(l, c, s, length));
        }
      });
    }
  };
}

void draw_cells(Drawing &page, const TruthLayout &l, const TruthInput &in, const std::vector<bool> &reachable,
                double least_mark_px) {
  const maze::Maze &m = *in.truth;
  const auto cell_tone = [&](int x, int row) {
    const std::size_t i = flat(m, maze::Cell{x, m.height() - 1 - row});
    return !reachable[i] ? kUnreachableTone : (*in.visited)[i] ? kWhite : kUnvisitedTone;
  };
  page.blocks(cell_tone, m.width(), m.height(), {l.origin.x + l.side_px, l.origin.y + l.side_px}, l.cell_px, l.cell_px);
  page.fill_rects(unscored_walls(l, m, reachable), kUnscoredWallColour);
  draw_landmarks(page, l, m, least_mark_px);  // first: the goals and the start are drawn over them
  const double line = std::max(1.0, l.cell_px / 14);
  for (const maze::Cell goal : m.goals()) {
    const double inset = l.cell_px / 8 + line / 2;
    page.stroke_rect({l.left(goal) + inset, l.top(goal) + inset, l.cell_px - 2 * inset, l.cell_px - 2 * inset}, line,
                     kGoalColour);
  }
  const double side = std::max({2.0, l.cell_px / 3, least_mark_px});
  const maze::Cell start = m.start();
  page.fill_rect({l.left(start) + (l.cell_px - side) / 2, l.top(start) + (l.cell_px - side) / 2, side, side}, kStartColour);
}

void truth_legend(Figure &fig, const TruthInput &in, const TruthCounts &counts, const TruthLayout &l) {
  const MapScore score = counts.score();
  fig.lines.push_back(in.caption);
  fig.lines.push_back(fmt::format("wall_accuracy {:.2f}% ({}/{} sides)", score.wall_accuracy_percent(),
                                  score.sides_correct, score.sides));
  fig.lines.push_back(fmt::format("coverage {:.2f}% ({}/{} cells)", score.coverage_percent(),
                                  score.visited_reachable_cells, score.reachable_cells));
  fig.items = {{Swatch::line, kRightWallColour, "wall, mapped correctly"},
               {Swatch::line, kMissedColour, fmt::format("wall the map missed ({})", counts.missed)},
               {Swatch::line, kPhantomColour, fmt::format("wall the map invented ({})", counts.phantom)},
               {Swatch::line, kUnseenColour, fmt::format("opening never seen ({})", counts.unseen_opening)},
               {Swatch::box, kWhite, "cell visited"},
               {Swatch::box, kUnvisitedTone, "cell not visited"},
               {Swatch::box, kUnreachableTone, "cell unreachable"},
               {Swatch::line, kUnscoredWallColour, "wall, not scored"},
               {Swatch::square, kStartColour, "start"},
               {Swatch::frame, kGoalColour, "goal"}};
  for (LegendItem &item : landmark_items(landmark_marks(*in.truth))) fig.items.push_back(std::move(item));
  fig.px_per_m = l.cell_px / in.truth->cell_size_m();
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

namespace {

Rgb landmark_rgb(double red, double green, double blue) {
  const auto channel = [](double v) { return static_cast<unsigned char>(std::lround(255.0 * v)); };
  return Rgb{channel(red), channel(green), channel(blue)};
}

}  // namespace

std::vector<LandmarkMark> landmark_marks(const maze::Maze &truth) {
  std::vector<LandmarkMark> marks;
  for (const maze::Landmark &l : truth.landmarks()) {
    marks.push_back({mapping::Point{l.x_m, l.y_m}, landmark_rgb(l.red, l.green, l.blue), maze::kLandmarkRadius_m});
  }
  return marks;
}

std::vector<LandmarkMark> landmark_marks(const maze::Arena &geometry) {
  std::vector<LandmarkMark> marks;
  for (const maze::ArenaDisc &d : geometry.discs) {
    std::optional<Rgb> colour;
    if (d.landmark) colour = landmark_rgb(d.landmark->red, d.landmark->green, d.landmark->blue);
    marks.push_back({mapping::Point{d.centre_x_m, d.centre_y_m}, colour, d.radius_m});
  }
  return marks;
}

int truth_side_px(int cell_px) { return std::max(2, cell_px / 10); }  // map_margin_px's rule

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

PointPx truth_origin_px(const maze::Maze &truth, int subcells) {
  TruthInput in;
  in.truth = &truth;
  in.subcells = subcells;
  const TruthLayout l = layout_of(in, layout_figure(truth_frame(in)).map_origin);
  return {l.origin.x + l.side_px, l.origin.y + l.side_px};
}

Figure truth_figure(const TruthInput &in) {
  Figure fig = truth_frame(in);
  truth_legend(fig, in, count_verdicts(in), layout_of(in, {}));
  return fig;
}

Drawing truth_picture(const TruthInput &in, PictureFormat format, const std::optional<PageFrame> &page) {
  const maze::Maze &m = *in.truth;
  const std::vector<bool> reachable = m.reachable_from_start();
  const Figure fig = truth_figure(in);
  const FigureLayout layout = page ? layout_figure(fig, *page) : layout_figure(fig);
  const TruthLayout l = layout_of(in, layout.map_origin);
  Drawing drawing(layout.width, layout.height, format);
  draw_cells(drawing, l, in, reachable, app::min_mark_px(layout.font_px));
  drawing.fill_rects(sides_judged(l, in, reachable, SideVerdict::right), kRightWallColour);
  drawing.fill_rects(sides_judged(l, in, reachable, SideVerdict::missed), kMissedColour);
  drawing.fill_rects(sides_judged(l, in, reachable, SideVerdict::phantom), kPhantomColour);
  drawing.fill_rects(sides_judged(l, in, reachable, SideVerdict::unseen_opening), kUnseenColour);
  draw_figure(drawing, fig, layout);
  return drawing;
}

}  // namespace app
