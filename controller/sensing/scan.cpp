#include "sensing/scan.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "common/angles.hpp"

namespace sensing {

double LidarScan::beam_angle_rad(int i) const {
  return fov_rad / 2.0 - (i + beam_offset) * fov_rad / beam_count();
}

std::optional<float> LidarScan::median_range(int centre, double half_window_rad) const {
  const std::optional<Medians> m = medians(centre, half_window_rad);
  if (!m) return std::nullopt;
  return m->lower;
}

std::optional<LidarScan::Medians> LidarScan::medians(int centre, double half_window_rad) const {
  const int n = beam_count();
  assert(centre >= 0 && centre < n);
  const double step = fov_rad / n;
  const bool full_circle = fov_rad >= 2.0 * std::numbers::pi - 1e-9;
  const int reach = std::min(static_cast<int>(half_window_rad / step), (n - 1) / 2);
  if (reach < 0) return std::nullopt;  // no beam in the window
  // The window's valid readings in beam order, in a buffer on the stack unless the window
  // is wide (beams much closer than the window).
  const auto window = static_cast<std::size_t>(2 * reach + 1);
  std::array<float, kMedianSmallWindow> small;
  std::vector<float> wide;
  if (window > small.size()) wide.resize(window);
  const std::span<float> buffer = window > small.size() ? std::span<float>(wide) : std::span<float>(small);
  std::size_t count = 0;
  std::size_t returns = 0;
  for (int offset = -reach; offset <= reach; ++offset) {
    int i = centre + offset;
    if (full_circle) {
      if (i < 0) {
        i += n;
      } else if (i >= n) {
        i -= n;
      }
    }
    if (i < 0 || i >= n) continue;
    const float r = ranges[static_cast<std::size_t>(i)];
    const ReadingKind k = kind_of(r);
    if (k == ReadingKind::invalid) continue;
    if (k == ReadingKind::hit) ++returns;
    buffer[count++] = k == ReadingKind::no_return ? std::numeric_limits<float>::infinity() : r;
  }
  if (count == 0) return std::nullopt;
  std::span<float> valid = buffer.first(count);
  if (returns >= 2) {
    // Stable, as the order decides which of two equal readings (+0 and -0) is returned.
    const auto end = std::remove_if(valid.begin(), valid.end(), [](float v) { return !std::isfinite(v); });
    valid = valid.first(static_cast<std::size_t>(end - valid.begin()));
  }
  const auto middle = valid.begin() + static_cast<std::ptrdiff_t>((valid.size() - 1) / 2);
  std::nth_element(valid.begin(), middle, valid.end());
  const float upper = valid.size() % 2 == 1 ? *middle : *std::min_element(middle + 1, valid.end());
  return Medians{*middle, upper};
}

bool LidarScan::lone_no_return(int i) const {
  const int n = beam_count();
  if (kind(i) != ReadingKind::no_return || n < 3) return false;
  const bool full_circle = fov_rad >= 2.0 * std::numbers::pi - 1e-9;
  if (!full_circle && (i < 2 || i > n - 3)) return false;
  const auto hit = [&](int j) { return kind(((j % n) + n) % n) == ReadingKind::hit; };
  return (hit(i - 1) || hit(i - 2)) && (hit(i + 1) || hit(i + 2));
}

std::optional<int> LidarScan::beam_towards(double world_angle_rad) const {
  const int n = beam_count();
  if (n == 0 || !(fov_rad > 0.0)) return std::nullopt;
  const double relative = common::wrap_angle_rad(world_angle_rad - yaw_rad);
  const double step = fov_rad / n;
  const long nearest = std::lround((fov_rad / 2.0 - relative) / step - beam_offset);
  const bool full_circle = fov_rad >= 2.0 * std::numbers::pi - 1e-9;
  if (full_circle) return static_cast<int>(((nearest % n) + n) % n);
  if (nearest < 0 || nearest >= n) return std::nullopt;
  return static_cast<int>(nearest);
}

}  // namespace sensing
