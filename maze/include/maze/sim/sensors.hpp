#pragma once
// What the simulated sensors measure at a pose: pure functions of the walls, the sensor's
// spec and a random source. The embedded simulator's devices and `maze_mapper scan` use them.

#include <cstdint>
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

// The direction of lidar beam i relative to the heading: fov/2 - i fov/N (DESIGN §2), so with
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

// A distance sensor on the rim of a body of body_radius_m: its rays spread evenly over the
// aperture, each ray's distance (the table's last distance when nothing is nearer) weighted
// like Webots (exp(-(ray angle / aperture)^2)), the mean distance looked up in the table and
// Gaussian noise of sigma noise fraction x value added when noisy.
double distance_sensor_value(const WallGrid &walls, const DistanceSensorSpec &sensor,
                             double body_radius_m, const Pose &pose, bool noisy,
                             common::Rng &rng);

// Whether a bumper of a round body of body_radius_m touches a wall (a wall surface within
// contact_tolerance_m of the rim, in the bumper's arc).
inline constexpr double kContactTolerance_m = 1e-4;
bool bumper_pressed(const WallGrid &walls, const BumperSpec &bumper, double body_radius_m,
                    const Pose &pose);

}  // namespace maze::sim
