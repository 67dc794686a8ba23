#pragma once
// What a run prints as it goes, one block per MoveReport (after the start scan and after
// every move into a cell), the same in `maze_mapper run` and in a Webots console:
//
//   step 412  cell (2,3)  heading N  visited 7/16
//   <the map, render::render_map>
//   cell (2,3) log-odds, north row first:       only when the cell is new
//   <its K x K matrix, render::format_cell_matrix>
//   <an empty line>
//
// With style.color the robot is drawn at its cell's centre as its heading's arrow.

#include <ostream>

#include "render/ascii_map.hpp"
#include "robot/cell_controller.hpp"

namespace robot {

class ProgressPrinter {
 public:
  // out must outlive the printer; total_cells is W x H (for "visited N/total").
  ProgressPrinter(std::ostream &out, const render::MapStyle &style, int total_cells)
      : out_(out), style_(style), total_cells_(total_cells) {}

  void operator()(const MoveReport &report) const;

 private:
  std::ostream &out_;
  render::MapStyle style_;
  int total_cells_;
};

}  // namespace robot
