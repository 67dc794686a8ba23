#pragma once
// What the simulated sensors measure at a pose: pure functions of the walls, the sensor's
// spec and a random source. The embedded simulator's devices and `maze_mapper scan` use them.

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "common/random.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/solid_geometry.hpp"
#include "maze/sim/wall_grid.hpp"

namespace maze::sim {

// A robot pose in the world frame: x east, y north (m), yaw 0 east, counter-clockwise (rad).
struct Pose {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;
};

// The random stream of a device's reading at a step: readings depend on (seed, device,
// step) only, not on when or how often they are read.
common::Rng sensor_rng(std::uint64_t seed, int device, std::int64_t step);
// The random stream of one beam of a rotating lidar measured at a step: (seed, device, step,
// beam) only, so a beam keeps its reading until the head sweeps it again.
common::Rng beam_rng(std::uint64_t seed, int device, std::int64_t step, int beam);
// The seed beam_rng seeds its generator with.
std::uint64_t beam_seed(std::uint64_t seed, int device, std::int64_t step, int beam);

// Throws common::InputError when the point is outside the maze or inside a wall.
void check_pose_free(const WallGrid &walls, const Pose &pose);
// Likewise in an arena: outside the boundary or inside an obstacle.
void check_pose_free(const SolidGeometry &solids, const Pose &pose);

// Every function below that takes the solids takes a WallGrid (a maze) or a SolidGeometry
// (any other world's solids): the same code, compiled for each (sensors.cpp instantiates both), so a maze's
// ray never pays for a choice between them.

// The direction of lidar beam i relative to the heading, as Webots points it: a rotating
// lidar's at fov/2 - i fov/N, a fixed lidar's half a beam in, fov/2 - (i + 1/2) fov/N (the
// centre of pixel i of the camera Webots renders it with; docs/simulator.md). Either way,
// with 360 beams over 2 pi, index 0 looks back, 90 left, 180 ahead, 270 right.
double beam_angle_rad(const LidarSpec &lidar, int i);
// 0 (rotating) or 0.5 (fixed): beam_angle_rad's offset, in beams.
double beam_offset(const LidarSpec &lidar);

// Webots renders a fixed lidar with cameras facing every quarter turn (ahead, left, back,
// right) and measures depth along the facing camera's axis: the cosine of a beam's angle
// from the nearest of those axes, in [cos(pi/4), 1].
double face_cos(double beam_angle_rad);
// range_m rounded to the nearest multiple of resolution_m, halves up (Webots'
// depth_resolution shader: floor(r / resolution + 0.5) x resolution); unchanged when
// resolution_m is not positive.
inline double quantised_m(double range_m, double resolution_m) {
  if (!(resolution_m > 0.0)) return range_m;
  return std::floor(range_m / resolution_m + 0.5) * resolution_m;
}
// What a fixed Webots lidar returns for a beam whose wall is range_m away, cos_face its
// face_cos, noise_m its Gaussian draw: the depth along the face's axis, range_m x cos_face,
// is +infinity outside [min range, max range); else noise is added to it, it is quantised,
// divided by cos_face back to a range along the beam, and that is +infinity outside
// [min range, max range) again.
inline float fixed_lidar_reading(const LidarSpec &lidar, double range_m, double cos_face, double noise_m) {
  constexpr float kNoReturn = std::numeric_limits<float>::infinity();
  const double planar_m = range_m * cos_face;
  if (!(planar_m >= lidar.min_range_m) || planar_m >= lidar.max_range_m) return kNoReturn;
  const double reading_m = quantised_m(planar_m + noise_m, lidar.resolution_m) / cos_face;
  if (!(reading_m >= lidar.min_range_m) || reading_m >= lidar.max_range_m) return kNoReturn;
  return static_cast<float>(reading_m);
}
// A rotating lidar's: range_m plus noise_m, quantised, +infinity outside [min, max].
float rotating_lidar_reading(const LidarSpec &lidar, double range_m, double noise_m);

// Where beams are cast from: a pose's cast origin and heading, computed once per pose.
template <typename Solids>
struct ViewpointIn {
  typename Solids::CastOrigin origin;
  double cos_yaw;
  double sin_yaw;
};

// A lidar with its beam directions computed once.
class LidarModel {
 public:
  explicit LidarModel(const LidarSpec &spec);
  const LidarSpec &spec() const { return spec_; }

  // The range image at pose, in out (spec.horizontal_resolution values, m): each beam's
  // distance to the first wall with Gaussian noise of sigma noise x max range, as
  // fixed_lidar_reading or rotating_lidar_reading make it a reading. One normal variate is
  // drawn per beam, in index order, whether or not the beam returns; noise 0 draws none.
  template <typename Solids>
  void range_image(const Solids &walls, double noise, const Pose &pose, common::Rng &rng,
                   std::span<float> out) const;
  using Viewpoint = ViewpointIn<WallGrid>;
  template <typename Solids>
  static ViewpointIn<Solids> viewpoint(const Solids &walls, const Pose &pose);
  // Beam i alone from a viewpoint, as range_image measures it, its noise the first normal
  // variate of Rng(noise_seed) (beam_seed).
  template <typename Solids>
  float beam_range(const Solids &walls, double noise, const ViewpointIn<Solids> &from, int i,
                   std::uint64_t noise_seed) const;
  // Where a rotating head passes beam i: revolutions clockwise from ahead, in [0, 1).
  double sweep_phase(int i) const { return sweep_phase_[static_cast<std::size_t>(i)]; }

 private:
  // Beam i's reading of a wall range_m away with noise_m of noise, as the lidar's type makes it.
  float reading(int i, double range_m, double noise_m) const;

  LidarSpec spec_;
  std::vector<double> cos_, sin_;  // of beam_angle_rad(spec_, i)
  std::vector<double> face_cos_;   // face_cos(beam_angle_rad(spec_, i))
  std::vector<double> sweep_phase_;
};

// Where a ray from (x, y) along angle_rad first meets a wall: the distance (WallGrid::cast's,
// +infinity beyond max_range_m) and the outward unit normal of the face it meets, (+-1, 0)
// or (0, +-1) since walls are axis-aligned boxes; (0, 0) when nothing is hit. A ray that
// meets a box exactly on its edge (two faces at once) takes the face it meets more squarely.
struct RayHit {
  double distance_m;
  double normal_x, normal_y;
};
RayHit cast_hit(const WallGrid &walls, double x_m, double y_m, double angle_rad, double max_range_m);
// In an arena: the normal of the face met (any direction: obstacles may be rotated; the
// boundary's inward normal).
RayHit cast_hit(const SolidGeometry &solids, double x_m, double y_m, double angle_rad, double max_range_m);

// A sonar ray whose angle of incidence on the surface is pi / 8 or more never returns
// (Webots: "outside the reflexion cone of aperture 45 degrees").
inline constexpr double kSonarMaxIncidence_rad = std::numbers::pi / 8.0;

// Distance sensors as Webots computes them (docs/reference/distancesensor.md), in a flat
// world. Ray k of n points at ray_offset_rad(k) from the sensor's axis: the rays spread
// evenly over the aperture in the floor's plane, -a/2 ... +a/2 (one ray: on the axis).
// Webots lays rays of a 3-D cone out in rings round the axis; in a world of vertical walls
// only their spread across the plane matters, and this keeps Webots' left/right symmetry.
double ray_offset_rad(const DistanceSensorSpec &sensor, int k);
// The generic and infra-red types' ray weights, Webots' Gaussian: v_k = exp(-(t_k / (a g))^2),
// t_k the ray's angle from the axis, a the aperture, g the Gaussian width, normalised to
// sum to 1 (one ray, or aperture 0: equal weights).
std::vector<double> ray_weights(const DistanceSensorSpec &sensor);
// The distance the sensor measures, before its lookup table, from the rim of a body of
// body_radius_m at pose, every ray cast to the table's last distance (its range), a ray that
// hits nothing counting as that range. generic, infra-red: sum of weight x ray distance
// (infra-red's colour factor is 1: our walls are one colour). sonar: the nearest ray among
// those whose incidence is below kSonarMaxIncidence_rad; the range when every ray is lost.
double sensor_distance_m(const WallGrid &walls, const DistanceSensorSpec &sensor, double body_radius_m,
                         const Pose &pose);
double sensor_distance_m(const SolidGeometry &solids, const DistanceSensorSpec &sensor, double body_radius_m,
                         const Pose &pose);
// The lookup table's response at distance_m (lookup_value) and, when noisy, plus Gaussian
// noise of standard deviation noise fraction x value (Webots: v (1 + noise N(0, 1))); one
// normal variate drawn from rng only when noisy and the noise fraction there is not 0.
double lookup_reading(const std::vector<LookupRow> &table, double distance_m, bool noisy, common::Rng &rng);
// lookup_reading(table, sensor_distance_m(...)): what the device's getValue() returns.
double distance_sensor_value(const WallGrid &walls, const DistanceSensorSpec &sensor,
                             double body_radius_m, const Pose &pose, bool noisy,
                             common::Rng &rng);
double distance_sensor_value(const SolidGeometry &solids, const DistanceSensorSpec &sensor,
                             double body_radius_m, const Pose &pose, bool noisy, common::Rng &rng);

// Whether a bumper of a round body of body_radius_m touches a wall (a wall surface within
// contact_tolerance_m of the rim, in the bumper's arc).
inline constexpr double kContactTolerance_m = 1e-4;
bool bumper_pressed(const WallGrid &walls, const BumperSpec &bumper, double body_radius_m,
                    const Pose &pose);
bool bumper_pressed(const SolidGeometry &solids, const BumperSpec &bumper, double body_radius_m,
                    const Pose &pose);

}  // namespace maze::sim
