#include "maze/generate/solids_generator.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "common/error.hpp"
#include "common/random.hpp"

namespace maze {

namespace {
constexpr std::uint64_t kArenaSalt = 0x6172656e61ULL;  // "arena"
constexpr int kTries = 100;
}  // namespace

Arena generate_arena(const ArenaGeneration &g) {
  if (!(g.width_m >= 1.0 && g.height_m >= 1.0 && g.width_m <= kMaxArenaSide_m && g.height_m <= kMaxArenaSide_m)) {
    throw common::InputError(
        fmt::format("a generated arena is 1 to {} m a side (got {} x {} m)", kMaxArenaSide_m, g.width_m, g.height_m));
  }
  if (g.obstacles < 0 || static_cast<std::size_t>(g.obstacles) > kMaxObstacles) {
    throw common::InputError(fmt::format("a generated arena has 0 to {} obstacles (got {})", kMaxObstacles, g.obstacles));
  }
  const bool sides_ok = g.min_side_m > 0.0 && g.min_side_m <= g.max_side_m && std::isfinite(g.max_side_m);
  if (!sides_ok || !(g.clearance_m >= 0.0)) {
    throw common::InputError(fmt::format("obstacle sides need 0 < min <= max (got {} and {} m)", g.min_side_m,
                                         g.max_side_m));
  }
  Arena a;
  a.name = fmt::format("generated arena (seed {})", g.seed);
  a.x_max_m = g.width_m;
  a.y_max_m = g.height_m;
  a.starts.push_back({0.5, 0.5, 0.0});
  a.goals.push_back({g.width_m - 0.5, g.height_m - 0.5});
  common::Rng rng(g.seed ^ kArenaSalt);
  for (int i = 0; i < g.obstacles; ++i) {
    for (int attempt = 0; attempt < kTries; ++attempt) {
      const double cx = rng.uniform(0.0, g.width_m);
      const double cy = rng.uniform(0.0, g.height_m);
      const double length = rng.uniform(g.min_side_m, g.max_side_m);
      const double width = rng.uniform(g.min_side_m, g.max_side_m);
      const double angle = g.rotated ? rng.uniform(0.0, std::numbers::pi) : 0.0;
      const Obstacle o = g.rotated ? Obstacle::oriented(cx, cy, length / 2.0, width / 2.0, angle)
                                   : Obstacle::from_box(cx - length / 2.0, cy - width / 2.0, cx + length / 2.0,
                                                        cy + width / 2.0);
      const bool clear = o.distance_m(a.starts[0].x_m, a.starts[0].y_m) > g.clearance_m &&
                         o.distance_m(a.goals[0].x_m, a.goals[0].y_m) > g.clearance_m;
      if (clear) {
        a.obstacles.push_back(o);
        break;
      }
    }
  }
  validate_arena(a, 0.0);
  return a;
}

}  // namespace maze
