#pragma once
// The summary keys that more than one kind of run or more than one renderer names (the maze
// run's report, the room run's, the mms report built on the maze run's, batch's columns and
// table, the pictures' captions): each spelled here once. docs/output.md says what each means.

#include <string_view>

namespace app::report_key {

inline constexpr std::string_view reachable = "reachable";          // cells reachable from the start
inline constexpr std::string_view coverage = "coverage";            // % of the reachable cells (free cells) seen
inline constexpr std::string_view wall_accuracy = "wall_accuracy";  // % of the cell sides learned right
inline constexpr std::string_view cell_accuracy = "cell_accuracy";  // % of a metric map's cells right
inline constexpr std::string_view path_length_m = "path_length_m";  // metres the robot's centre drove
inline constexpr std::string_view coverage_final_step = "coverage_final_step";  // the step coverage reached its final value

}  // namespace app::report_key
