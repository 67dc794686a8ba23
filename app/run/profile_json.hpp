#pragma once
// Robot profiles as JSON files (docs/simulator.md, Robots): `maze_mapper robot NAME` prints one, `--robot
// FILE.json` reads one back. A profile file states every field of maze::sim::RobotProfile,
// units in the key names, in this order:
//
//   {
//     "name": "hambot",
//     "description": "...",
//     "wheel_radius_m": 0.045, "axle_m": 0.184, "body_radius_m": 0.09,
//     "max_wheel_velocity_rad_s": 20.0,
//     "left_motor": "left motor", "right_motor": "right motor",
//     "left_encoder": "left wheel encoder", "right_encoder": "right wheel encoder",
//     "imu": "imu", "gps": "gps",                       ("" : the robot has none)
//     "lidars": [{"name", "horizontal_resolution", "fov_rad", "min_range_m", "max_range_m",
//                 "noise", "frequency_hz", "resolution_m" (0: not quantised)}],
//     "distance_sensors": [{"name", "angle_rad", "aperture_rad", "rays",
//                           "lookup_table": [{"distance_m", "value", "noise_fraction"}],
//                           "type" ("generic", "infra-red" or "sonar"), "gaussian_width"}],
//     "bumpers": [{"name", "angle_rad", "half_arc_rad"}]
//   }
//
// Every key is required and no other is accepted (a typo is an error, not a default).
// Doubles are printed in the shortest form that reads back to the same bits, so print ->
// edit -> load gives back exactly the profile printed.

#include <string>
#include <string_view>

#include "maze/sim/profile.hpp"

namespace app {

// The profile as JSON, two-space indented, ending with a newline.
std::string profile_to_json(const maze::sim::RobotProfile &profile);

// Reads and validates (maze::sim::validate_profile) a profile; `file` names the source in
// errors. Throws common::InputError: "FILE:LINE:COL: error: invalid JSON: ..." for malformed
// JSON, "FILE: error: lidars[0].max_range_m must be greater than min_range_m (got ...)" for a
// bad value, an unknown key, a missing one or a wrong type.
maze::sim::RobotProfile profile_from_json(std::string_view text, const std::string &file);

// Whether --robot's argument names a file: it contains '/' or ends in ".json".
bool names_a_profile_file(std::string_view robot);

// The profile --robot names: a file (read and validated as above; one that cannot be read is
// "error: cannot read FILE: REASON") or a built-in (maze::sim::find_profile).
maze::sim::RobotProfile resolve_robot(const std::string &robot);

}  // namespace app
