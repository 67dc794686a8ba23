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
// With style.color the robot is drawn at its cell's centre as its heading's arrow. With a view
// (a terminal smaller than the map), only the part around the robot is drawn, the status
// line says which part ("  view 120,48 of 768x768"), and a block is printed at most every
// min_interval of wall-clock time (the blocks between are skipped: a terminal shows the last
// one anyway), so that printing costs less than the run.

#include <chrono>
#include <optional>
#include <ostream>

#include "render/ascii_map.hpp"
#include "robot/cell/controller.hpp"

namespace robot {

class ProgressPrinter {
 public:
  // At most this many sub-cell rows and columns of the map a block.
  struct View {
    int rows = 0;
    int cols = 0;
    std::chrono::milliseconds min_interval{0};
  };

  // out must outlive the printer; total_cells is W x H (for "visited N/total"); no view: the
  // whole map every block.
  ProgressPrinter(std::ostream &out, const render::MapStyle &style, int total_cells,
                  std::optional<View> view = std::nullopt)
      : out_(out), style_(style), total_cells_(total_cells), view_(view) {}

  void operator()(const MoveReport &report);

 private:
  std::ostream &out_;
  render::MapStyle style_;
  int total_cells_;
  std::optional<View> view_;
  std::chrono::steady_clock::time_point next_block_{};
};

}  // namespace robot
