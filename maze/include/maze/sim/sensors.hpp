#pragma once
// What the simulated sensors measure at a pose: pure functions of the walls, the sensor's
// spec and a random source. The embedded simulator's devices and `maze_mapper scan` use them.

#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "common/random.hpp"
#include "maze/sim/profile.hpp"
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

// The direction of lidar beam i relative to the heading: fov/2 - i fov/N (ARCHITECTURE.md, Conventions), so with
// 360 beams over 2 pi index 0 looks back, 90 left, 180 ahead, 270 right.
double beam_angle_rad(const LidarSpec &lidar, int i);

// A lidar with its beam directions computed once.
class LidarModel {
 public:
  explicit LidarModel(const LidarSpec &spec);
  const LidarSpec &spec() const { return spec_; }

  // The range image at pose, in out (spec.horizontal_resolution values, m): the distance to
  // the first wall plus Gaussian noise of sigma noise x max range, +infinity when that is
  // outside [min range, max range]. One normal variate is drawn per beam, in index order,
  // whether or not the beam returns; noise 0 draws none.
  void range_image(const WallGrid &walls, double noise, const Pose &pose, common::Rng &rng,
                   std::span<float> out) const;
  // Where beams are cast from: a pose's cast origin and heading, computed once per pose.
  struct Viewpoint {
    WallGrid::CastOrigin origin;
    double cos_yaw;
    double sin_yaw;
  };
  static Viewpoint viewpoint(const WallGrid &walls, const Pose &pose);
  // Beam i alone from a viewpoint, as range_image measures it, its noise the first normal
  // variate of Rng(noise_seed) (beam_seed).
  float beam_range(const WallGrid &walls, double noise, const Viewpoint &from, int i,
                   std::uint64_t noise_seed) const;
  // Where a rotating head passes beam i: revolutions clockwise from ahead, in [0, 1).
  double sweep_phase(int i) const { return sweep_phase_[static_cast<std::size_t>(i)]; }

 private:
  LidarSpec spec_;
  std::vector<double> cos_, sin_;  // of beam_angle_rad(spec_, i)
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
// The lookup table's response at distance_m (lookup_value) and, when noisy, plus Gaussian
// noise of standard deviation noise fraction x value (Webots: v (1 + noise N(0, 1))); one
// normal variate drawn from rng only when noisy and the noise fraction there is not 0.
double lookup_reading(const std::vector<LookupRow> &table, double distance_m, bool noisy, common::Rng &rng);
// lookup_reading(table, sensor_distance_m(...)): what the device's getValue() returns.
double distance_sensor_value(const WallGrid &walls, const DistanceSensorSpec &sensor,
                             double body_radius_m, const Pose &pose, bool noisy,
                             common::Rng &rng);

// Whether a bumper of a round body of body_radius_m touches a wall (a wall surface within
// contact_tolerance_m of the rim, in the bumper's arc).
inline constexpr double kContactTolerance_m = 1e-4;
bool bumper_pressed(const WallGrid &walls, const BumperSpec &bumper, double body_radius_m,
                    const Pose &pose);

}  // namespace maze::sim
