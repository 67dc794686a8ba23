#pragma once
// The values inside an option's text that several commands read the same way: a list of
// numbers and a pose. Each throws common::InputError naming the option as the user typed it.
// The command line (app/cli/) and the course exercises (app/course/) both read them.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace app {

// "1, 1.5,0.8" -> {1, 1.5, 0.8}, blanks around each item allowed; throws common::InputError
// naming `option`: "--readings item 2 is not a number (got 'x')", and when count > 0 and the
// list has another length, "--cells needs 2 numbers (got 3)". Items may be infinite or NaN
// ("inf"): each option checks its own range.
std::vector<double> parse_number_list(std::string_view text, const std::string &option, std::size_t count = 0);

// A pose as every command spells it: X,Y,YAW in one word (no quoting), X and Y in metres, YAW
// in degrees counter-clockwise from east, or with its unit: 90deg, 1.5708rad. Both angles
// are given; yaw_deg is exactly as typed when YAW was degrees, yaw_rad when radians.
struct PoseArgument {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_deg = 0.0;
  double yaw_rad = 0.0;
};
// Throws common::InputError naming `option`: "--pose needs 3 numbers (got 2)", "--pose must
// be three finite numbers". A YAW in radians larger than 2 pi looks like degrees: a warning
// line saying so is added to `warnings`.
PoseArgument parse_pose(const std::string &text, const std::string &option, std::vector<std::string> &warnings);

}  // namespace app
