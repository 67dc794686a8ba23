#pragma once
// The 1-D exercise's result as text and as a picture: a table, an ASCII plot of the belief
// against position (the plot a student would draw with matplotlib), and a standalone SVG.
// Pure functions: they return the text, the caller prints or writes it.

#include <span>
#include <string>

#include "app/course/demo_1d.hpp"

namespace app::course {

// One line a cell: position (cm), log-odds and belief to 4 decimals, and how many free and
// occupied updates the cell got, under a header line. Ends with a newline.
std::string demo_1d_table(std::span<const Demo1dCell> cells);

// Rows of the ASCII plot: belief 0, 0.05, ..., 1 (ticks labelled every 0.1); a point is drawn
// in the row nearest its belief.
inline constexpr int kPlotRows = 21;
// Columns of the plot area: the first cell is in column 0, the last in column kPlotColumns - 1.
inline constexpr int kPlotColumns = 61;

// Belief (y, 0 ... 1) against position (x, cm), one '*' a cell, x ticks at a 1-2-5 step.
// Cells must be non-empty and in increasing position. Ends with a newline.
std::string ascii_belief_plot(std::span<const Demo1dCell> cells);

// The same plot as a standalone SVG document (one <circle> a cell, joined by a polyline),
// titled `title` (escaped for XML). Ends with a newline.
std::string svg_belief_plot(std::span<const Demo1dCell> cells, const std::string &title);

// The x-axis tick step for positions 0 ... span_cm: the smallest of 1, 2, 5 x 10^k giving at
// most 10 intervals (200 -> 20). span_cm > 0.
double tick_step(double span_cm);

}  // namespace app::course
