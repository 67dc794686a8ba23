#pragma once
// The values inside an option's text that several commands read the same way: a list of
// numbers, a length with its unit and a pose. Each throws common::InputError naming the option as the user typed it.
// The command line (app/cli/) and the course exercises (app/course/) both read them.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace app {

// "1, 1.5,0.8" -> {1, 1.5, 0.8}, blanks around each item allowed; throws common::InputError
// naming `option`: "--readings item 2 is not a number (got 'x')", and when count > 0 and the
// list has another length, "--cells needs 2 numbers (got 3)". Items may be infinite or NaN
// ("inf"): each option checks its own range.
std::vector<double> parse_number_list(std::string_view text, const std::string &option, std::size_t count = 0);

// A length as typed: "0.25m" and "25cm" carry their unit, a bare "0.25" none (each option
// says what a bare number means). Nothing for any other text.
enum class LengthUnit { none, m, cm };
struct Length {
  double value = 0.0;
  LengthUnit unit = LengthUnit::none;
};
std::optional<Length> length_of(std::string_view text);
// The length in metres, a bare number read as `bare`; in centimetres likewise (a length typed
// in one unit comes back exactly as typed in that unit).
double metres(const Length &length, LengthUnit bare = LengthUnit::m);
double centimetres(const Length &length, LengthUnit bare = LengthUnit::cm);

// A pose as every command spells it: Xm,Ym,YAW in one word (no quoting), X and Y with their
// unit (m, or cm), YAW in degrees counter-clockwise from east, with its unit (90deg,
// 1.5708rad), or a heading letter N, E, S or W. Both angles are given; yaw_deg is exactly as
// typed when YAW was degrees, yaw_rad when radians. Where a start may leave YAW out
// (PoseYaw::optional), yaw_given says whether it was there.
struct PoseArgument {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_deg = 0.0;
  double yaw_rad = 0.0;
  bool yaw_given = true;
};
enum class PoseYaw { required, optional };
// Throws common::InputError naming `option`: "--pose needs 3 numbers (got 2)", "--pose must
// be three finite numbers", "--pose item 2 is not a number (got 'x')". Warning lines are added
// to `warnings`: X,Y without a unit (the old spelling, read as metres; it goes in the next
// release), and a YAW in radians larger than 2 pi (it looks like degrees).
PoseArgument parse_pose(const std::string &text, const std::string &option, std::vector<std::string> &warnings,
                        PoseYaw yaw = PoseYaw::required);

// The warning an old spelling gives (kept for one release): "warning: OLD is the old spelling;
// write NEW (the old one goes in the next release)".
std::string old_spelling_warning(const std::string &old_spelling, const std::string &new_spelling);

}  // namespace app
