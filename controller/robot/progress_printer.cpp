#include "robot/progress_printer.hpp"

#include <string>

#include <fmt/format.h>

namespace robot {

void ProgressPrinter::operator()(const MoveReport &report) {
  if (view_ && view_->min_interval.count() > 0) {
    const auto now = std::chrono::steady_clock::now();
    if (now < next_block_) return;
    next_block_ = now + view_->min_interval;
  }
  std::string text = render::format_status(static_cast<long>(report.step), report.cell, report.heading,
                                           report.visits->count(), total_cells_);
  render::MapStyle style = style_;
  const int k = report.grid->k();
  const mapping::SubCell centre = mapping::to_global(report.cell, {k / 2, k / 2}, k);
  if (style.color) style.robot = render::RobotMark{centre, render::arrow(report.heading, style.ascii)};
  const int map_rows = report.grid->height() * k;
  const int map_cols = report.grid->width() * k;
  if (view_ && (view_->rows < map_rows || view_->cols < map_cols)) {
    const render::MapWindow w = render::window_around(*report.grid, centre, view_->rows, view_->cols);
    text += fmt::format("  view {},{} of {}x{}\n", w.first_col, w.first_row, map_cols, map_rows);
    render::render_window(text, *report.grid, *report.visits, style, w);
  } else {
    text += '\n';
    text += render::render_map(*report.grid, *report.visits, style);
  }
  if (report.new_cell) {
    text += fmt::format("cell ({},{}) log-odds, north row first:\n", report.cell.x, report.cell.y);
    text += render::format_cell_matrix(*report.grid, report.cell);
  }
  text += '\n';
  out_ << text;
}

}  // namespace robot
