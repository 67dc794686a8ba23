#include "maze/sim/sensors.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#include <fmt/format.h>

#include "common/angles.hpp"
#include "common/error.hpp"

namespace maze::sim {

namespace {
std::uint64_t sensor_seed(std::uint64_t seed, int device, std::int64_t step) {
  const auto d = static_cast<std::uint64_t>(device) + 1;
  const auto s = static_cast<std::uint64_t>(step);
  return seed ^ (d * 0x9e3779b97f4a7c15ULL) ^ (s * 0xd1b54a32d192ed03ULL);
}

// ranges[k] = solids.cast_from(origin, dx[k], dy[k], reach_m): a maze casts the fan at once.
template <typename Solids>
void cast_beams(const Solids &solids, const typename Solids::CastOrigin &origin, std::span<const double> dx,
                std::span<const double> dy, double reach_m, std::span<double> ranges) {
  if constexpr (std::is_same_v<Solids, WallGrid>) {
    solids.cast_fan(origin, dx, dy, reach_m, ranges);
  } else {
    for (std::size_t k = 0; k < dx.size(); ++k) ranges[k] = solids.cast_from(origin, dx[k], dy[k], reach_m);
  }
}
void fixed_readings_baseline(const LidarSpec &lidar, const double *range_m, const double *cos_face,
                             const double *noise_m, float *out, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) out[k] = fixed_lidar_reading(lidar, range_m[k], cos_face[k], noise_m[k]);
}

#if defined(__x86_64__) || defined(__i386__)
// fixed_lidar_reading for each beam, the same values: the same IEEE operations in the same
// order (floor((planar + noise) / resolution + 0.5) x resolution / cos_face, no fused
// multiply-add), four beams to a 256-bit lane group, the range checks as masks: a block's
// divisions overlap and no beam's range check is a branch to mispredict.
[[gnu::target("avx2")]] void fixed_readings_avx2(const LidarSpec &lidar, const double *range_m, const double *cos_face,
                                                 const double *noise_m, float *out, std::size_t n) {
  std::size_t k = 0;
  if (lidar.resolution_m > 0.0) {
    const __m256d lo = _mm256_set1_pd(lidar.min_range_m), hi = _mm256_set1_pd(lidar.max_range_m);
    const __m256d resolution = _mm256_set1_pd(lidar.resolution_m), half = _mm256_set1_pd(0.5);
    const __m128 no_return = _mm_set1_ps(std::numeric_limits<float>::infinity());
    for (; k + 4 <= n; k += 4) {
      const __m256d c = _mm256_loadu_pd(cos_face + k);
      const __m256d planar = _mm256_mul_pd(_mm256_loadu_pd(range_m + k), c);
      const __m256d steps = _mm256_add_pd(_mm256_div_pd(_mm256_add_pd(planar, _mm256_loadu_pd(noise_m + k)), resolution), half);
      const __m256d floored = _mm256_round_pd(steps, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
      const __m256d reading = _mm256_div_pd(_mm256_mul_pd(floored, resolution), c);
      const __m256d in_range = _mm256_and_pd(
          _mm256_and_pd(_mm256_cmp_pd(planar, lo, _CMP_GE_OQ), _mm256_cmp_pd(planar, hi, _CMP_LT_OQ)),
          _mm256_and_pd(_mm256_cmp_pd(reading, lo, _CMP_GE_OQ), _mm256_cmp_pd(reading, hi, _CMP_LT_OQ)));
      // The four 64-bit masks as four 32-bit ones (their low halves), beside the four floats.
      const __m128 mask = _mm_shuffle_ps(_mm256_castps256_ps128(_mm256_castpd_ps(in_range)),
                                         _mm256_extractf128_ps(_mm256_castpd_ps(in_range), 1), _MM_SHUFFLE(2, 0, 2, 0));
      _mm_storeu_ps(out + k, _mm_blendv_ps(no_return, _mm256_cvtpd_ps(reading), mask));
    }
  }
  for (; k < n; ++k) out[k] = fixed_lidar_reading(lidar, range_m[k], cos_face[k], noise_m[k]);
}

#endif

void fixed_readings(const LidarSpec &lidar, std::span<const double> range_m, std::span<const double> cos_face,
                    std::span<const double> noise_m, std::span<float> out) {
#if defined(__x86_64__) || defined(__i386__)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) {
    fixed_readings_avx2(lidar, range_m.data(), cos_face.data(), noise_m.data(), out.data(), range_m.size());
    return;
  }
#endif
  fixed_readings_baseline(lidar, range_m.data(), cos_face.data(), noise_m.data(), out.data(), range_m.size());
}

}  // namespace

common::Rng sensor_rng(std::uint64_t seed, int device, std::int64_t step) {
  return common::Rng(sensor_seed(seed, device, step));
}

std::uint64_t beam_seed(std::uint64_t seed, int device, std::int64_t step, int beam) {
  const auto b = static_cast<std::uint64_t>(beam) + 1;
  return sensor_seed(seed ^ (b * 0xbf58476d1ce4e5b9ULL), device, step);
}

common::Rng beam_rng(std::uint64_t seed, int device, std::int64_t step, int beam) {
  return common::Rng(beam_seed(seed, device, step, beam));
}

void check_pose_free(const WallGrid &walls, const Pose &pose) {
  if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.yaw_rad)) {
    throw common::InputError("the pose must be finite numbers");
  }
  if (!walls.inside_maze(pose.x_m, pose.y_m)) {
    throw common::InputError(
        fmt::format("pose ({}, {}) is outside the maze", pose.x_m, pose.y_m));
  }
  if (walls.inside_wall(pose.x_m, pose.y_m)) {
    throw common::InputError(fmt::format("pose ({}, {}) is inside a wall", pose.x_m, pose.y_m));
  }
}

void check_pose_free(const SolidGeometry &solids, const Pose &pose) {
  if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.yaw_rad)) {
    throw common::InputError("the pose must be finite numbers");
  }
  if (!solids.inside_bounds(pose.x_m, pose.y_m)) {
    throw common::InputError(fmt::format("pose ({}, {}) is outside the arena", pose.x_m, pose.y_m));
  }
  if (solids.inside_solid(pose.x_m, pose.y_m)) {
    throw common::InputError(fmt::format("pose ({}, {}) is inside an obstacle", pose.x_m, pose.y_m));
  }
}

double beam_offset(const LidarSpec &lidar) { return lidar.frequency_hz > 0.0 ? 0.0 : 0.5; }

double beam_angle_rad(const LidarSpec &lidar, int i) {
  return lidar.fov_rad / 2.0 - (i + beam_offset(lidar)) * lidar.fov_rad / lidar.horizontal_resolution;
}

double face_cos(double beam_angle_rad) {
  const double quarter = std::numbers::pi / 2.0;
  return std::cos(beam_angle_rad - quarter * std::round(beam_angle_rad / quarter));
}

float rotating_lidar_reading(const LidarSpec &lidar, double range_m, double noise_m) {
  const double reading_m = quantised_m(range_m + noise_m, lidar.resolution_m);
  const bool in_range = reading_m >= lidar.min_range_m && reading_m <= lidar.max_range_m;
  return in_range ? static_cast<float>(reading_m) : std::numeric_limits<float>::infinity();
}

LidarModel::LidarModel(const LidarSpec &spec) : spec_(spec) {
  assert(spec.horizontal_resolution >= 1);
  for (int i = 0; i < spec.horizontal_resolution; ++i) {
    cos_.push_back(std::cos(beam_angle_rad(spec, i)));
    sin_.push_back(std::sin(beam_angle_rad(spec, i)));
    face_cos_.push_back(face_cos(beam_angle_rad(spec, i)));
    const double turn = -beam_angle_rad(spec, i) / (2.0 * std::numbers::pi);
    sweep_phase_.push_back(turn - std::floor(turn));
  }
}

float LidarModel::reading(int i, double range_m, double noise_m) const {
  if (spec_.frequency_hz > 0.0) return rotating_lidar_reading(spec_, range_m, noise_m);
  return fixed_lidar_reading(spec_, range_m, face_cos_[static_cast<std::size_t>(i)], noise_m);
}

template <typename Solids>
void LidarModel::range_image(const Solids &walls, double noise, const Pose &pose,
                             common::Rng &rng, std::span<float> out) const {
  assert(out.size() == cos_.size());
  const double sigma_m = noise * spec_.max_range_m;
  // Cast a little past max range so that noise (and rounding) can bring a far hit back
  // into range.
  const double reach_m = spec_.max_range_m + 6.0 * sigma_m + spec_.resolution_m;
  const double c = std::cos(pose.yaw_rad);
  const double s = std::sin(pose.yaw_rad);
  const typename Solids::CastOrigin origin = walls.cast_origin(pose.x_m, pose.y_m);
  // In blocks, each in passes of one kind of work (directions, casts, noise, readings): the
  // divisions of neighbouring beams then overlap instead of waiting on each beam's walk.
  constexpr std::size_t kBlock = 64;
  double dx[kBlock], dy[kBlock], range[kBlock], noise_m[kBlock];
  const bool fixed = !(spec_.frequency_hz > 0.0);
  for (std::size_t start = 0; start < cos_.size(); start += kBlock) {
    const std::size_t n = std::min(kBlock, cos_.size() - start);
    for (std::size_t k = 0; k < n; ++k) {
      dx[k] = c * cos_[start + k] - s * sin_[start + k];
      dy[k] = s * cos_[start + k] + c * sin_[start + k];
    }
    cast_beams(walls, origin, std::span<const double>(dx, n), std::span<const double>(dy, n), reach_m,
               std::span<double>(range, n));
    if (sigma_m > 0.0) {
      for (std::size_t k = 0; k < n; ++k) noise_m[k] = rng.normal(0.0, sigma_m);
    } else {
      std::fill_n(noise_m, n, 0.0);
    }
    if (fixed) {
      fixed_readings(spec_, std::span<const double>(range, n), std::span<const double>(face_cos_).subspan(start, n),
                     std::span<const double>(noise_m, n), out.subspan(start, n));
    } else {
      for (std::size_t k = 0; k < n; ++k) out[start + k] = rotating_lidar_reading(spec_, range[k], noise_m[k]);
    }
  }
}

template <typename Solids>
ViewpointIn<Solids> LidarModel::viewpoint(const Solids &walls, const Pose &pose) {
  return {walls.cast_origin(pose.x_m, pose.y_m), std::cos(pose.yaw_rad), std::sin(pose.yaw_rad)};
}

template <typename Solids>
float LidarModel::beam_range(const Solids &walls, double noise, const ViewpointIn<Solids> &from, int i,
                             std::uint64_t noise_seed) const {
  const auto b = static_cast<std::size_t>(i);
  assert(b < cos_.size());
  const double sigma_m = noise * spec_.max_range_m;
  const double reach_m = spec_.max_range_m + 6.0 * sigma_m + spec_.resolution_m;
  const double dx = from.cos_yaw * cos_[b] - from.sin_yaw * sin_[b];
  const double dy = from.sin_yaw * cos_[b] + from.cos_yaw * sin_[b];
  const double range = walls.cast_from(from.origin, dx, dy, reach_m);
  const double noise_m = sigma_m > 0.0 ? sigma_m * common::Rng::first_normal(noise_seed) : 0.0;
  return reading(i, range, noise_m);
}

// The lidar for both kinds of solids.
template void LidarModel::range_image<WallGrid>(const WallGrid &, double, const Pose &, common::Rng &,
                                                std::span<float>) const;
template void LidarModel::range_image<SolidGeometry>(const SolidGeometry &, double, const Pose &, common::Rng &,
                                                     std::span<float>) const;
template ViewpointIn<WallGrid> LidarModel::viewpoint<WallGrid>(const WallGrid &, const Pose &);
template ViewpointIn<SolidGeometry> LidarModel::viewpoint<SolidGeometry>(const SolidGeometry &, const Pose &);
template float LidarModel::beam_range<WallGrid>(const WallGrid &, double, const ViewpointIn<WallGrid> &, int,
                                                std::uint64_t) const;
template float LidarModel::beam_range<SolidGeometry>(const SolidGeometry &, double,
                                                     const ViewpointIn<SolidGeometry> &, int, std::uint64_t) const;

RayHit cast_hit(const SolidGeometry &solids, double x_m, double y_m, double angle_rad, double max_range_m) {
  RayHit hit{0.0, 0.0, 0.0};
  hit.distance_m = solids.cast_from(solids.cast_origin(x_m, y_m), std::cos(angle_rad), std::sin(angle_rad),
                                    max_range_m, &hit.normal_x, &hit.normal_y);
  return hit;
}

RayHit cast_hit(const WallGrid &walls, double x_m, double y_m, double angle_rad, double max_range_m) {
  const double dx = std::cos(angle_rad);
  const double dy = std::sin(angle_rad);
  const double d = walls.cast_direction(x_m, y_m, dx, dy, max_range_m);
  if (!std::isfinite(d)) return {d, 0.0, 0.0};
  // Every face turned to free space lies on a line k s +- t/2 (the drawing in wall_grid.hpp):
  // the hit point's distance from the nearest such line, across x and across y.
  const WallGrid::CastOrigin at = walls.cast_origin(x_m + d * dx, y_m + d * dy);
  const double s = walls.cell_size_m();
  const double h = walls.wall_thickness_m() / 2.0;
  const auto off_face = [&](double local_m) {
    return std::abs(std::abs(local_m - s * std::round(local_m / s)) - h);
  };
  constexpr double kOnFace_m = 1e-9;
  const double ex = off_face(at.local_x_m);
  const double ey = off_face(at.local_y_m);
  const bool on_x = ex <= kOnFace_m;
  const bool on_y = ey <= kOnFace_m;
  // On a box's edge (both faces): the face the ray meets more squarely.
  const bool x_face = on_x && on_y ? std::abs(dx) >= std::abs(dy) : (on_x || (!on_y && ex < ey));
  if (x_face) return {d, dx > 0.0 ? -1.0 : 1.0, 0.0};
  return {d, 0.0, dy > 0.0 ? -1.0 : 1.0};
}

double ray_offset_rad(const DistanceSensorSpec &sensor, int k) {
  assert(k >= 0 && k < sensor.rays);
  if (sensor.rays == 1) return 0.0;
  return -sensor.aperture_rad / 2.0 + k * sensor.aperture_rad / (sensor.rays - 1);
}

std::vector<double> ray_weights(const DistanceSensorSpec &sensor) {
  std::vector<double> w(static_cast<std::size_t>(sensor.rays), 1.0);
  double sum = 0.0;
  for (int k = 0; k < sensor.rays; ++k) {
    const double spread = sensor.aperture_rad * sensor.gaussian_width;
    const double t = spread > 0.0 ? ray_offset_rad(sensor, k) / spread : 0.0;
    w[static_cast<std::size_t>(k)] = std::exp(-t * t);
    sum += w[static_cast<std::size_t>(k)];
  }
  for (double &v : w) v /= sum;
  return w;
}

namespace {

template <typename Solids>
double sensor_distance_in(const Solids &walls, const DistanceSensorSpec &sensor, double body_radius_m,
                          const Pose &pose) {
  assert(sensor.rays >= 1 && !sensor.lookup_table.empty());
  const double direction = pose.yaw_rad + sensor.angle_rad;
  double ox = pose.x_m + body_radius_m * std::cos(direction);
  double oy = pose.y_m + body_radius_m * std::sin(direction);
  if (sensor.origin_m) {
    const auto &o = *sensor.origin_m;
    ox = pose.x_m + o[0] * std::cos(pose.yaw_rad) - o[1] * std::sin(pose.yaw_rad);
    oy = pose.y_m + o[0] * std::sin(pose.yaw_rad) + o[1] * std::cos(pose.yaw_rad);
  }
  const double range_m = sensor.lookup_table.back().distance_m;
  if (sensor.axial) {
    const double d = walls.cast(ox, oy, direction, range_m);
    return d < range_m ? d * std::cos(sensor.angle_rad) : range_m;
  }
  if (sensor.type == DistanceSensorType::sonar) {
    double nearest = range_m;
    for (int k = 0; k < sensor.rays; ++k) {
      const double a = direction + ray_offset_rad(sensor, k);
      const RayHit hit = cast_hit(walls, ox, oy, a, range_m);
      // cos(incidence) = -(ray . normal)
      const double cos_incidence = -(std::cos(a) * hit.normal_x + std::sin(a) * hit.normal_y);
      if (hit.distance_m < nearest && cos_incidence > std::cos(kSonarMaxIncidence_rad)) nearest = hit.distance_m;
    }
    return nearest;
  }
  const std::vector<double> weights = ray_weights(sensor);
  double distance = 0.0;
  for (int k = 0; k < sensor.rays; ++k) {
    const double d = walls.cast(ox, oy, direction + ray_offset_rad(sensor, k), range_m);
    distance += weights[static_cast<std::size_t>(k)] * std::min(d, range_m);
  }
  return distance;
}

template <typename Solids>
bool bumper_pressed_in(const Solids &walls, const BumperSpec &bumper, double body_radius_m, const Pose &pose) {
  for (const Contact &c : walls.contacts(pose.x_m, pose.y_m, body_radius_m + kContactTolerance_m)) {
    const double bearing = std::atan2(c.y_m - pose.y_m, c.x_m - pose.x_m) - pose.yaw_rad;
    if (std::abs(common::wrap_angle_rad(bearing - bumper.angle_rad)) <= bumper.half_arc_rad + 1e-12) {
      return true;
    }
  }
  return false;
}

}  // namespace

double sensor_distance_m(const WallGrid &walls, const DistanceSensorSpec &sensor, double body_radius_m,
                         const Pose &pose) {
  return sensor_distance_in(walls, sensor, body_radius_m, pose);
}

double sensor_distance_m(const SolidGeometry &solids, const DistanceSensorSpec &sensor, double body_radius_m,
                         const Pose &pose) {
  return sensor_distance_in(solids, sensor, body_radius_m, pose);
}

double lookup_reading(const std::vector<LookupRow> &table, double distance_m, bool noisy, common::Rng &rng) {
  const double value = lookup_value(table, distance_m);
  const double fraction = lookup_noise_fraction(table, distance_m);
  return noisy && fraction > 0.0 ? value + rng.normal(0.0, fraction * value) : value;
}

double distance_sensor_value(const WallGrid &walls, const DistanceSensorSpec &sensor,
                             double body_radius_m, const Pose &pose, bool noisy,
                             common::Rng &rng) {
  return lookup_reading(sensor.lookup_table, sensor_distance_m(walls, sensor, body_radius_m, pose), noisy, rng);
}

double distance_sensor_value(const SolidGeometry &solids, const DistanceSensorSpec &sensor,
                             double body_radius_m, const Pose &pose, bool noisy, common::Rng &rng) {
  return lookup_reading(sensor.lookup_table, sensor_distance_m(solids, sensor, body_radius_m, pose), noisy, rng);
}

bool bumper_pressed(const WallGrid &walls, const BumperSpec &bumper, double body_radius_m,
                    const Pose &pose) {
  return bumper_pressed_in(walls, bumper, body_radius_m, pose);
}

bool bumper_pressed(const SolidGeometry &solids, const BumperSpec &bumper, double body_radius_m,
                    const Pose &pose) {
  return bumper_pressed_in(solids, bumper, body_radius_m, pose);
}

}  // namespace maze::sim
