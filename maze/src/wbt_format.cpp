#include "maze/wbt_format.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include <fmt/format.h>

namespace maze {

namespace {

constexpr std::string_view kProtoBase = "https://raw.githubusercontent.com/cyberbotics/webots/R2023b/projects/objects/";
constexpr double kWallHeightPerCell = 0.5;
constexpr double kFloorThickness_m = 0.01;
// Camera field of view (Webots' default Viewpoint, rad); the camera sits high enough to see
// the whole maze with a margin.
constexpr double kFieldOfView_rad = 0.785398;

double yaw_of(Side s) {
  switch (s) {
    case Side::north: return std::numbers::pi / 2;
    case Side::east: return 0.0;
    case Side::south: return -std::numbers::pi / 2;
    case Side::west: return std::numbers::pi;
  }
  return 0.0;
}

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
                 "  title \"{}\"\n  basicTimeStep 16\n}}\n",
                 maze.width(), maze.height(), num(maze.cell_size_m()), num(maze.wall_thickness_m()), title);
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

}  // namespace

std::string write_wbt(const Maze &maze, std::string_view title) {
  std::string safe_title(title);
  std::replace_if(safe_title.begin(), safe_title.end(), [](char c) { return c == '"' || c == '\\' || c == '\n'; }, '_');
  std::string out;
  header(out, maze, safe_title);
  walls(out, maze);
  markers(out, maze);
  return out;
}

}  // namespace maze
