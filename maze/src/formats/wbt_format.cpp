#include "maze/formats/wbt_format.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include <fmt/format.h>

#include "common/angles.hpp"
#include "maze/sim/simulation.hpp"

namespace maze {

namespace {

constexpr std::string_view kProtoBase = "https://raw.githubusercontent.com/cyberbotics/webots/R2023b/projects/objects/";
constexpr double kWallHeightPerCell = 0.5;
constexpr double kFloorThickness_m = 0.01;
// Camera field of view (Webots' default Viewpoint, rad); the camera sits high enough to see
// the whole maze with a margin.
constexpr double kFieldOfView_rad = 0.785398;

double yaw_of(Side s) { return common::compass_yaw_rad(static_cast<int>(s)); }

// Numbers as Webots files show them: fixed, trailing zeros dropped.
std::string num(double v) {
  std::string s = fmt::format("{:.6f}", v);
  while (s.ends_with('0')) s.pop_back();
  if (s.ends_with('.')) s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

void header(std::string &out, const Maze &maze, std::string_view title) {
  const double w_m = maze.width() * maze.cell_size_m();
  const double h_m = maze.height() * maze.cell_size_m();
  const double cx = maze.origin_x_m() + w_m / 2;
  const double cy = maze.origin_y_m() + h_m / 2;
  const double height = 1.15 * std::max(w_m, h_m) / (2 * std::tan(kFieldOfView_rad / 2)) + 1.0;
  auto to = std::back_inserter(out);
  fmt::format_to(to, "#VRML_SIM R2023b utf8\n\n");
  fmt::format_to(to, "EXTERNPROTO \"{}backgrounds/protos/TexturedBackground.proto\"\n", kProtoBase);
  fmt::format_to(to, "EXTERNPROTO \"{}backgrounds/protos/TexturedBackgroundLight.proto\"\n\n", kProtoBase);
  const Cell s = maze.start();
  fmt::format_to(to, "# start: cell ({},{}) facing {}, x {} m, y {} m, yaw {} rad\n", s.x, s.y,
                 to_string(maze.start_heading()), num(maze.origin_x_m() + (s.x + 0.5) * maze.cell_size_m()),
                 num(maze.origin_y_m() + (s.y + 0.5) * maze.cell_size_m()), num(yaw_of(maze.start_heading())));
  fmt::format_to(to,
                 "WorldInfo {{\n  info [\n    \"maze_mapper world: {}x{} cells of {} m, walls {} m thick\"\n  ]\n"
                 "  title \"{}\"\n  basicTimeStep {}\n}}\n",
                 maze.width(), maze.height(), num(maze.cell_size_m()), num(maze.wall_thickness_m()), title,
                 wbt_basic_time_step_ms());
  // Looking straight down (-z) with north (+y) at the top of the screen.
  fmt::format_to(to, "Viewpoint {{\n  orientation -0.57735 0.57735 0.57735 2.0944\n  position {} {} {}\n}}\n",
                 num(cx), num(cy), num(height));
  fmt::format_to(to, "TexturedBackground {{\n}}\nTexturedBackgroundLight {{\n}}\n");
  fmt::format_to(to,
                 "Solid {{\n  translation {} {} {}\n  children [\n    Shape {{\n      appearance PBRAppearance {{\n"
                 "        baseColor 0.9 0.9 0.85\n        roughness 1\n        metalness 0\n      }}\n"
                 "      geometry DEF FLOOR_BOX Box {{\n        size {} {} {}\n      }}\n    }}\n  ]\n"
                 "  name \"floor\"\n  boundingObject USE FLOOR_BOX\n  locked TRUE\n}}\n",
                 num(cx), num(cy), num(-kFloorThickness_m / 2), num(w_m + maze.wall_thickness_m()),
                 num(h_m + maze.wall_thickness_m()), num(kFloorThickness_m));
}

void walls(std::string &out, const Maze &maze) {
  const double t = maze.wall_thickness_m();
  const double h = kWallHeightPerCell * maze.cell_size_m();
  int n = 0;
  for (const WallSegment &w : maze.wall_segments()) {
    ++n;
    const double dx = std::abs(w.x2_m - w.x1_m);
    const double dy = std::abs(w.y2_m - w.y1_m);
    const double size_x = dx > 0 ? dx + t : t;
    const double size_y = dy > 0 ? dy + t : t;
    fmt::format_to(std::back_inserter(out),
                   "Solid {{\n  translation {} {} {}\n  children [\n    Shape {{\n      appearance PBRAppearance {{\n"
                   "        baseColor 0.2 0.3 0.8\n        roughness 1\n        metalness 0\n      }}\n"
                   "      geometry DEF WALL_BOX_{} Box {{\n        size {} {} {}\n      }}\n    }}\n  ]\n"
                   "  name \"wall {}\"\n  boundingObject USE WALL_BOX_{}\n  locked TRUE\n}}\n",
                   num((w.x1_m + w.x2_m) / 2), num((w.y1_m + w.y2_m) / 2), num(h / 2), n, num(size_x), num(size_y),
                   num(h), n, n);
  }
}

// The course's landmarks: coloured cylinders standing on the floor, solid like the course's
// (a real Webots lidar and camera see them; the embedded simulator does not).
void landmarks(std::string &out, const Maze &maze) {
  int n = 0;
  for (const Landmark &l : maze.landmarks()) {
    ++n;
    fmt::format_to(std::back_inserter(out),
                   "Solid {{\n  translation {} {} {}\n  children [\n    Shape {{\n      appearance PBRAppearance {{\n"
                   "        baseColor {} {} {}\n        roughness 1\n        metalness 0\n      }}\n"
                   "      geometry DEF LANDMARK_{} Cylinder {{\n        height {}\n        radius {}\n      }}\n"
                   "    }}\n  ]\n  name \"landmark {}\"\n  recognitionColors [\n    {} {} {}\n  ]\n"
                   "  boundingObject USE LANDMARK_{}\n  locked TRUE\n}}\n",
                   num(l.x_m), num(l.y_m), num(l.height_m / 2), num(l.red), num(l.green), num(l.blue), n,
                   num(l.height_m), num(kLandmarkRadius_m), n, num(l.red), num(l.green), num(l.blue), n);
  }
}

void markers(std::string &out, const Maze &maze) {
  const double s = maze.cell_size_m();
  auto centre = [&](Cell c, double &x, double &y) {
    x = maze.origin_x_m() + (c.x + 0.5) * s;
    y = maze.origin_y_m() + (c.y + 0.5) * s;
  };
  double x = 0, y = 0;
  centre(maze.start(), x, y);
  // A flat bar along the start heading with a cross-bar at its front end, like a "T" on its
  // side; no boundingObject, so the robot drives over it.
  const std::string paint =
      "appearance PBRAppearance {\n            baseColor 0.1 0.8 0.1\n            roughness 1\n"
      "            metalness 0\n          }\n";
  fmt::format_to(std::back_inserter(out),
                 "DEF START Pose {{\n  translation {} {} 0.001\n  rotation 0 0 1 {}\n  children [\n"
                 "    Pose {{\n      children [\n        Shape {{\n          {}"
                 "          geometry Box {{\n            size {} {} 0.002\n          }}\n        }}\n      ]\n    }}\n"
                 "    Pose {{\n      translation {} 0 0\n      children [\n        Shape {{\n          {}"
                 "          geometry Box {{\n            size {} {} 0.002\n          }}\n        }}\n      ]\n    }}\n"
                 "  ]\n}}\n",
                 num(x), num(y), num(yaw_of(maze.start_heading())), paint, num(0.5 * s), num(0.1 * s),
                 num(0.25 * s), paint, num(0.1 * s), num(0.3 * s));
  for (const Cell g : maze.goals()) {
    centre(g, x, y);
    fmt::format_to(std::back_inserter(out),
                   "Pose {{\n  translation {} {} 0.001\n  children [\n    Shape {{\n"
                   "      appearance PBRAppearance {{\n        baseColor 0.9 0.1 0.1\n        roughness 1\n"
                   "        metalness 0\n      }}\n      geometry Box {{\n        size {} {} 0.002\n      }}\n    }}\n"
                   "  ]\n}}\n",
                   num(x), num(y), num(0.6 * s), num(0.6 * s));
  }
}


// A VRML string: '"' and '\' escaped.
std::string quoted(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c == '\n' ? ' ' : c;
  }
  return out + '"';
}

// The robot's body, in metres: the floor clearance and height of the body cylinder, scaled
// on the wheel so that any profile stands on its wheels and its two caster balls.
struct BodyShape {
  double bottom_m, height_m, caster_radius_m;
  double centre_m() const { return bottom_m + height_m / 2; }
  double top_m() const { return bottom_m + height_m; }
};

BodyShape body_shape(const sim::RobotProfile &p) {
  const double r = p.wheel_radius_m;
  return {0.3 * r, 1.4 * r, 0.15 * r};
}

void body(std::string &out, const sim::RobotProfile &p, const BodyShape &b) {
  fmt::format_to(std::back_inserter(out),
                 "    Pose {{\n      translation 0 0 {}\n      children [\n        Shape {{\n"
                 "          appearance PBRAppearance {{\n            baseColor 0.8 0.5 0.1\n            roughness 1\n"
                 "            metalness 0\n          }}\n          geometry DEF ROBOT_BODY Cylinder {{\n"
                 "            height {}\n            radius {}\n          }}\n        }}\n      ]\n    }}\n",
                 num(b.centre_m()), num(b.height_m), num(p.body_radius_m));
}

// A wheel: a hinge about the robot's y axis through the wheel's centre, its motor and encoder.
void wheel(std::string &out, const sim::RobotProfile &p, std::string_view side, double y_m,
           const std::string &motor, const std::string &encoder) {
  const double r = p.wheel_radius_m;
  fmt::format_to(std::back_inserter(out),
                 "    HingeJoint {{\n      jointParameters HingeJointParameters {{\n        axis 0 1 0\n"
                 "        anchor 0 {} {}\n      }}\n      device [\n        RotationalMotor {{\n          name {}\n"
                 "          maxVelocity {}\n        }}\n        PositionSensor {{\n          name {}\n        }}\n      ]\n"
                 "      endPoint Solid {{\n        translation 0 {} {}\n        rotation 1 0 0 1.570796\n"
                 "        children [\n          DEF {}_WHEEL Shape {{\n            appearance PBRAppearance {{\n"
                 "              baseColor 0.1 0.1 0.1\n              roughness 1\n              metalness 0\n            }}\n"
                 "            geometry Cylinder {{\n              height {}\n              radius {}\n            }}\n"
                 "          }}\n        ]\n        name \"{} wheel\"\n        boundingObject USE {}_WHEEL\n"
                 "        physics Physics {{\n          density -1\n          mass 0.05\n        }}\n      }}\n    }}\n",
                 num(y_m), num(r), quoted(motor), num(p.max_wheel_velocity_rad_s), quoted(encoder), num(y_m),
                 num(r), side == "left" ? "LEFT" : "RIGHT", num(0.2 * r), num(r), side,
                 side == "left" ? "LEFT" : "RIGHT");
}

// A free ball under the body at x_m, so the robot rests level on its two wheels.
void caster(std::string &out, std::string_view where, double x_m, const BodyShape &b) {
  const double rc = b.caster_radius_m;
  fmt::format_to(std::back_inserter(out),
                 "    BallJoint {{\n      jointParameters BallJointParameters {{\n        anchor {} 0 {}\n      }}\n"
                 "      endPoint Solid {{\n        translation {} 0 {}\n        children [\n"
                 "          DEF CASTER_{} Shape {{\n            geometry Sphere {{\n              radius {}\n            }}\n"
                 "          }}\n        ]\n        name \"caster {}\"\n        boundingObject USE CASTER_{}\n"
                 "        physics Physics {{\n          density -1\n          mass 0.01\n        }}\n      }}\n    }}\n",
                 num(x_m), num(rc), num(x_m), num(rc), where, num(rc), where, where);
}

// Webots' near clipping plane must not exceed minRange. A rotating head (frequency > 0) is
// Webots' type "rotating" at defaultFrequency, as the profile says. No resolution is
// Webots' -1.
void lidar(std::string &out, const sim::LidarSpec &l, double z_m) {
  const std::string type = l.frequency_hz > 0.0
                               ? fmt::format("      type \"rotating\"\n      defaultFrequency {}\n", num(l.frequency_hz))
                               : std::string("      type \"fixed\"\n");
  fmt::format_to(std::back_inserter(out),
                 "    Lidar {{\n      translation 0 0 {}\n      name {}\n      horizontalResolution {}\n"
                 "      fieldOfView {}\n      numberOfLayers 1\n      near {}\n      minRange {}\n      maxRange {}\n"
                 "{}      projection \"cylindrical\"\n      noise {}\n      resolution {}\n    }}\n",
                 num(z_m), quoted(l.name), l.horizontal_resolution, num(l.fov_rad),
                 num(std::min(0.01, l.min_range_m)), num(l.min_range_m), num(l.max_range_m), type, num(l.noise),
                 l.resolution_m > 0.0 ? num(l.resolution_m) : std::string("-1"));
}

// A distance sensor on the rim, looking out along its angle (a sensor looks along its x axis).
void distance_sensor(std::string &out, const sim::DistanceSensorSpec &d, double rim_m, double z_m) {
  std::string table;
  for (const sim::LookupRow &row : d.lookup_table) {
    table += fmt::format("        {} {} {}\n", num(row.distance_m), num(row.value), num(row.noise_fraction));
  }
  fmt::format_to(std::back_inserter(out),
                 "    DistanceSensor {{\n      translation {} {} {}\n      rotation 0 0 1 {}\n      name {}\n"
                 "      lookupTable [\n{}      ]\n      type {}\n      numberOfRays {}\n      aperture {}\n"
                 "      gaussianWidth {}\n    }}\n",
                 num(rim_m * std::cos(d.angle_rad)), num(rim_m * std::sin(d.angle_rad)), num(z_m), num(d.angle_rad),
                 quoted(d.name), table, quoted(std::string(sim::to_string(d.type))), d.rays, num(d.aperture_rad),
                 num(d.gaussian_width));
}

// A bumper: a thin box just outside the rim, as wide as the chord of its arc.
void bumper(std::string &out, const sim::BumperSpec &b, const sim::RobotProfile &p, const BodyShape &shape,
            int n) {
  const double thickness = 0.05 * p.body_radius_m;
  const double centre = p.body_radius_m + thickness / 2;
  const double width = 2 * p.body_radius_m * std::sin(b.half_arc_rad);
  fmt::format_to(std::back_inserter(out),
                 "    TouchSensor {{\n      translation {} {} {}\n      rotation 0 0 1 {}\n      children [\n"
                 "        Shape {{\n          geometry DEF BUMPER_{} Box {{\n            size {} {} {}\n          }}\n"
                 "        }}\n      ]\n      name {}\n      boundingObject USE BUMPER_{}\n      type \"bumper\"\n    }}\n",
                 num(centre * std::cos(b.angle_rad)), num(centre * std::sin(b.angle_rad)), num(shape.centre_m()),
                 num(b.angle_rad), n, num(thickness), num(width), num(0.5 * shape.height_m), quoted(b.name), n);
}

void devices(std::string &out, const sim::RobotProfile &p, const BodyShape &b) {
  wheel(out, p, "left", p.axle_m / 2, p.left_motor, p.left_encoder);
  wheel(out, p, "right", -p.axle_m / 2, p.right_motor, p.right_encoder);
  const double caster_x = p.body_radius_m - 2 * b.caster_radius_m;
  caster(out, "front", caster_x, b);
  caster(out, "back", -caster_x, b);
  for (const sim::LidarSpec &l : p.lidars) lidar(out, l, b.top_m() + 0.01);
  if (!p.imu.empty()) out += fmt::format("    InertialUnit {{\n      name {}\n    }}\n", quoted(p.imu));
  if (!p.gps.empty()) out += fmt::format("    GPS {{\n      name {}\n    }}\n", quoted(p.gps));
  for (const sim::DistanceSensorSpec &d : p.distance_sensors) distance_sensor(out, d, p.body_radius_m, b.centre_m());
  int n = 0;
  for (const sim::BumperSpec &bump : p.bumpers) bumper(out, bump, p, b, ++n);
}

void robot_node(std::string &out, const Maze &maze, const WbtRobot &robot) {
  const sim::RobotProfile &p = *robot.profile;
  const BodyShape b = body_shape(p);
  const Cell s = maze.start();
  fmt::format_to(std::back_inserter(out), "DEF ROBOT Robot {{\n  translation {} {} 0\n  rotation 0 0 1 {}\n  children [\n",
                 num(maze.origin_x_m() + (s.x + 0.5) * maze.cell_size_m()),
                 num(maze.origin_y_m() + (s.y + 0.5) * maze.cell_size_m()), num(yaw_of(maze.start_heading())));
  body(out, p, b);
  devices(out, p, b);
  fmt::format_to(std::back_inserter(out),
                 "  ]\n  name {}\n  model {}\n  boundingObject Pose {{\n    translation 0 0 {}\n"
                 "    children [\n      USE ROBOT_BODY\n    ]\n  }}\n  physics Physics {{\n    density -1\n    mass 1\n  }}\n"
                 "  controller {}\n  controllerArgs [\n",
                 quoted(p.name), quoted(p.name), num(b.centre_m()), quoted(robot.controller));
  for (const std::string &arg : robot.controller_args) out += fmt::format("    {}\n", quoted(arg));
  out += "  ]\n}\n";
}

}  // namespace

int wbt_basic_time_step_ms() { return sim::SimulationOptions{}.basic_time_step_ms; }

std::string write_wbt(const Maze &maze, std::string_view title, const WbtRobot &robot) {
  std::string safe_title(title);
  std::replace_if(safe_title.begin(), safe_title.end(), [](char c) { return c == '"' || c == '\\' || c == '\n'; }, '_');
  std::string out;
  header(out, maze, safe_title);
  walls(out, maze);
  landmarks(out, maze);
  markers(out, maze);
  if (robot.profile != nullptr) robot_node(out, maze, robot);
  return out;
}

}  // namespace maze
