#pragma once
// Robot profiles: which wheels and devices a simulated robot has, as data (docs/simulator.md, Robots).
// `--robot NAME` selects one; find_profile() says which names exist.
//
// Device names (the strings a controller passes to Robot::get*):
//
// | profile       | motors / encoders            | other devices                                |
// |---------------|------------------------------|----------------------------------------------|
// | hambot        | "left motor", "right motor", | Lidar "lidar" (360 beams, 2 pi, 0.05-12 m,   |
// |  (default)    | "left wheel encoder",        |   noise 0.000833, resolution 0.01 m, fixed); |
// |               | "right wheel encoder"        |   InertialUnit "imu"; GPS "gps"; no bumpers  |
// | hambot-2025   | as hambot                    | as hambot, last year's lidar: 0.07-3 m,      |
// |               |                              |   no resolution, rotating at 12 Hz           |
// | hambot-12m    | as hambot                    | as hambot-2025, the lidar reaching 12 m      |
// | bumper-depth  | as hambot                    | imu, gps; TouchSensor "bumper front",        |
// |               |                              |   "bumper left" (+45 deg), "bumper right";   |
// |               |                              |   DistanceSensor "depth0" ... "depth8" (+60  |
// |               |                              |   ... -60 deg in 15 deg steps, one ray, 4 m, |
// |               |                              |   type generic)                              |
// | ir-ring       | as hambot                    | imu, gps; DistanceSensor "ir0" ... "ir5"     |
// |               |                              |   (0, +45, +90, 180, -90, -45 deg; 1.5 m;    |
// |               |                              |   type infra-red, 3 rays over 0.03 rad)      |
// | ir-fan        | as hambot                    | imu, gps; DistanceSensor "ir0" ... "ir5"     |
// |               |                              |   (+75 ... -75 deg in 30 deg steps, left to  |
// |               |                              |   right: the IR lab's Figure 1; as ir-ring's)|
// | sonar-ring    | as hambot                    | imu, gps; DistanceSensor "so0" ... "so7"     |
// |               |                              |   (every 45 deg from 0 ccw; 5 m; type sonar, |
// |               |                              |   5 rays over 0.4 rad)                       |
// | micromouse    | as hambot                    | imu, gps; Lidar "lidar" (360 beams, 2 pi,    |
// |               |                              |   0.02-1 m, fixed)                           |
//
// Angles are relative to the robot's heading, counter-clockwise positive (+90 deg = left).
// Distance sensors sit on the body's rim and look outward; the lidar sits at the centre, on
// the HamBot profiles 0.13 m above the robot's origin (the course's HamBot.proto), on the
// micromouse at 0.02 m.
// A distance sensor's value is in metres of distance (its lookup table maps distance d to
// value d), so the controller reads metres as from the lidar.
//
// Profiles are data: app/run/profile_json.hpp prints one as JSON and reads one back
// (`maze_mapper robot NAME`, `--robot FILE.json`); validate_profile() is the one check.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace maze::sim {

struct LidarSpec {
  std::string name;
  int horizontal_resolution = 360;  // beams in the one layer
  double fov_rad = 0.0;
  double min_range_m = 0.0;
  double max_range_m = 0.0;
  double noise = 0.0;  // Gaussian sigma as a fraction of max_range_m (Webots' `noise`)
  // A rotating head's frequency (Webots' `type "rotating"`, `defaultFrequency`); 0: fixed.
  double frequency_hz = 0.0;
  // Webots' `resolution`: every range is rounded to the nearest multiple of it (ties away
  // from zero), after the noise; 0: not quantised (Webots' -1). docs/simulator.md says how.
  double resolution_m = 0.0;
  // The beam plane's height above the robot's origin (Webots: the Lidar's translation z);
  // a beam is blocked by a solid only where it passes below that solid's top.
  double height_m = 0.0;
  bool operator==(const LidarSpec &) const = default;
};

// One row of a Webots lookup table: at distance_m the sensor returns value, with Gaussian
// noise of standard deviation noise_fraction x value. Linear between rows; clamped outside.
struct LookupRow {
  double distance_m;
  double value;
  double noise_fraction;
  bool operator==(const LookupRow &) const = default;
};

// Webots' DistanceSensor `type` (docs/reference/distancesensor.md): how the rays' distances
// make one reading. generic and infra-red: the Gaussian-weighted mean of every ray's distance
// (a ray that hits nothing counts as the table's last distance); sonar: the nearest ray whose
// angle of incidence on the surface is below 22.5 deg (pi / 8), the others lost, the table's
// last distance when every ray is lost. Webots' fourth type, laser (one ray, nearest), is
// generic with one ray here.
enum class DistanceSensorType { generic, infra_red, sonar };
// "generic", "infra-red", "sonar" (Webots' spelling), and back; nothing for another text.
std::string_view to_string(DistanceSensorType type);
std::optional<DistanceSensorType> parse_distance_sensor_type(std::string_view text);

struct DistanceSensorSpec {
  std::string name;
  double angle_rad = 0.0;     // mounting direction relative to the heading
  double aperture_rad = 0.0;  // the cone the rays spread over
  int rays = 1;
  std::vector<LookupRow> lookup_table;  // increasing distance
  DistanceSensorType type = DistanceSensorType::generic;
  double gaussian_width = 1.0;  // Webots' gaussianWidth: the ray weights' spread (generic, infra-red)
  // Where the rays leave from: none, the body's rim along angle_rad; else this point in the
  // robot's frame (x forward, y left, m), as a depth camera's pixels share its lens.
  std::optional<std::array<double, 2>> origin_m = std::nullopt;
  // A depth camera's pixel: the value is the depth along the robot's heading (the distance
  // times cos angle_rad), not along the ray; nothing seen is still the table's last distance.
  bool axial = false;
  bool operator==(const DistanceSensorSpec &) const = default;
};

struct BumperSpec {
  std::string name;
  double angle_rad = 0.0;       // centre of the bumper's arc relative to the heading
  double half_arc_rad = 0.0;    // pressed by a contact within +- half_arc_rad of angle_rad
  bool operator==(const BumperSpec &) const = default;
};

// How the robot drives a straight in one leg (each straight of the speed run's known path,
// each mms moveForward): speeding up at acceleration_m_s2 to top_speed_m_s (capped by the
// motors) and slowing down to stop at its end (a trapezoidal speed profile), instead of
// stopping in every cell. The search drives cell by cell at the cruise speed either way.
struct SpeedRunProfile {
  double acceleration_m_s2 = 0.0;
  double top_speed_m_s = 0.0;
  bool operator==(const SpeedRunProfile &) const = default;
};

struct RobotProfile {
  std::string name;
  std::string description;
  double wheel_radius_m = 0.0;
  double axle_m = 0.0;  // distance between the wheels
  double body_radius_m = 0.0;
  double max_wheel_velocity_rad_s = 0.0;
  std::string left_motor, right_motor;
  std::string left_encoder, right_encoder;
  std::string imu, gps;  // empty: the robot has none
  std::vector<LidarSpec> lidars;
  std::vector<DistanceSensorSpec> distance_sensors;
  std::vector<BumperSpec> bumpers;
  std::optional<SpeedRunProfile> speed_run;  // none: straights are driven cell by cell
  bool operator==(const RobotProfile &) const = default;
};

// Every built-in profile, the default (hambot) first.
const std::vector<RobotProfile> &profiles();
const RobotProfile &default_profile();
// The profile called name; throws common::InputError naming the known profiles otherwise.
const RobotProfile &find_profile(std::string_view name);
// "hambot, hambot-2025, hambot-12m, bumper-depth, ir-ring, ir-fan, sonar-ring, micromouse"
std::string profile_names();

// Throws common::InputError naming the first bad field by its key path, e.g.
// "lidars[0].max_range_m must be greater than min_range_m (got 0.05 <= 0.07)". Checks: a
// name; positive finite wheel radius, axle, body radius and wheel speed; motors and encoders
// named; device names unique; lidars with 1 to 100000 beams, a field of view in (0, 2 pi],
// 0 <= min range < max range, noise >= 0, frequency >= 0 and resolution >= 0; distance sensors with at least
// one ray, an aperture in [0, pi], a positive Gaussian width, a lookup table of increasing
// distances; bumpers with a
// half arc in (0, pi]. Every angle finite.
void validate_profile(const RobotProfile &profile);

// The value of a lookup table at distance_m (linear between rows, clamped outside) and the
// noise fraction there. The table has at least one row.
double lookup_value(const std::vector<LookupRow> &table, double distance_m);
double lookup_noise_fraction(const std::vector<LookupRow> &table, double distance_m);

}  // namespace maze::sim
