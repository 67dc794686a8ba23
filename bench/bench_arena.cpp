// The simulator's costs in an arena: one 360-beam lidar scan in a 20 x 20 m arena of 40 (and
// 400) random rectangles, through the bucket grid (SolidGeometry::cast_from) and, for
// comparison, by testing every obstacle (cast_brute_force); and one control step.

#include <benchmark/benchmark.h>

#include <cstdint>
#include <numbers>
#include <vector>


#include "common/random.hpp"
#include "driving_robot.hpp"
#include "maze/generate/solids_generator.hpp"
#include "maze/sim/solid_geometry.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/sim/simulation.hpp"

namespace {

maze::Arena arena(int obstacles, bool rotated) {
  maze::ArenaGeneration g;
  g.seed = 20;
  g.width_m = 20;
  g.height_m = 20;
  g.obstacles = obstacles;
  g.rotated = rotated;
  return maze::generate_arena(g);
}

// Free points with random headings, to spread the scans over the arena.
std::vector<maze::sim::Pose> poses(const maze::sim::SolidGeometry &g) {
  common::Rng rng(5);
  std::vector<maze::sim::Pose> out;
  while (out.size() < 256) {
    const double x = rng.uniform(0.2, 19.8);
    const double y = rng.uniform(0.2, 19.8);
    if (!g.inside_solid(x, y)) out.push_back({x, y, rng.uniform(-std::numbers::pi, std::numbers::pi)});
  }
  return out;
}

// The 12 m lidar of bench_lidar's table (docs/benchmarks.md).
const maze::sim::LidarSpec &lidar_spec() { return maze::sim::find_profile("hambot-12m").lidars.front(); }

void BM_Scan360_Arena(benchmark::State &state) {
  const maze::sim::SolidGeometry g(arena(static_cast<int>(state.range(0)), state.range(1) != 0));
  const maze::sim::LidarModel lidar(lidar_spec());
  const std::vector<maze::sim::Pose> where = poses(g);
  std::vector<float> ranges(static_cast<std::size_t>(lidar_spec().horizontal_resolution));
  common::Rng rng(1);
  std::size_t i = 0;
  for (auto _ : state) {
    lidar.range_image(g, lidar_spec().noise, where[i++ % where.size()], rng, ranges);
    benchmark::DoNotOptimize(ranges.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_Scan360_Arena)
    ->ArgNames({"obstacles", "rotated"})
    ->ArgsProduct({{40, 400}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

// The same 360 beams, each tested against every obstacle.
void BM_Scan360_Arena_BruteForce(benchmark::State &state) {
  const maze::sim::SolidGeometry g(arena(static_cast<int>(state.range(0)), state.range(1) != 0));
  const std::vector<maze::sim::Pose> where = poses(g);
  std::vector<double> ranges(360);
  std::size_t i = 0;
  for (auto _ : state) {
    const maze::sim::Pose &p = where[i++ % where.size()];
    for (int b = 0; b < 360; ++b) {
      const double a = p.yaw_rad + b * std::numbers::pi / 180.0;
      ranges[static_cast<std::size_t>(b)] = g.cast_brute_force(p.x_m, p.y_m, std::cos(a), std::sin(a), 12.0);
    }
    benchmark::DoNotOptimize(ranges.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_Scan360_Arena_BruteForce)
    ->ArgNames({"obstacles", "rotated"})
    ->ArgsProduct({{40, 400}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

// A control step through the webots:: API in the 40-obstacle arena: drive, step, read.
void BM_StepAndRead_Arena(benchmark::State &state) {
  webots::embedded::Simulation sim(maze::world_of(arena(40, true)), maze::sim::default_profile(), {});
  bench::step_and_read(state, sim.robot());
}
BENCHMARK(BM_StepAndRead_Arena)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
