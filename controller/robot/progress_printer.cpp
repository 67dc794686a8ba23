#include "robot/progress_printer.hpp"

#include <string>

#include <fmt/format.h>

namespace robot {

void ProgressPrinter::operator()(const MoveReport &report) const {
  std::string text = render::format_status(static_cast<long>(report.step), report.cell, report.heading,
                                           report.visits->count(), total_cells_);
  text += '\n';
  render::MapStyle style = style_;
  if (style.color) {
    const int k = report.grid->k();
    style.robot = render::RobotMark{mapping::to_global(report.cell, {k / 2, k / 2}, k),
                                    render::arrow(report.heading, style.ascii)};
  }
  text += render::render_map(*report.grid, *report.visits, style);
  if (report.new_cell) {
    text += fmt::format("cell ({},{}) log-odds, north row first:\n", report.cell.x, report.cell.y);
    text += render::format_cell_matrix(*report.grid, report.cell);
  }
  text += '\n';
  out_ << text;
}

}  // namespace robot
