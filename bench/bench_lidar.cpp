// The embedded simulator's costs: one 360-beam lidar scan (target: well under 50 us in a
// 1024 x 1024 maze) and one simulation step, in random perfect mazes of 16 x 16 and
// 1024 x 1024 cells and in an open maze (long beams, the worst case for the cell walk).

#include <benchmark/benchmark.h>

#include <cstdint>
#include <numbers>
#include <vector>

#include <webots/Robot.hpp>

#include "common/random.hpp"
#include "driving_robot.hpp"
#include "maze/world/maze.hpp"
#include "maze/sim/profile.hpp"
#include "maze/sim/sensors.hpp"
#include "maze/sim/simulation.hpp"
#include "maze/sim/wall_grid.hpp"

namespace {

// A perfect maze carved by randomised depth-first search from (0, 0).
maze::Maze carved(int side, std::uint64_t seed) {
  maze::Maze m(side, side);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      for (const maze::Side s : maze::kSides) m.set_wall({x, y}, s, true);
    }
  }
  common::Rng rng(seed);
  std::vector<bool> seen(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), false);
  const auto at = [side](maze::Cell c) {
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(side) +
           static_cast<std::size_t>(c.x);
  };
  std::vector<maze::Cell> stack{{0, 0}};
  seen[0] = true;
  while (!stack.empty()) {
    const maze::Cell c = stack.back();
    maze::Side options[4];
    std::size_t n = 0;
    for (const maze::Side s : maze::kSides) {
      const maze::Cell next = maze::neighbour(c, s);
      if (m.contains(next) && !seen[at(next)]) options[n++] = s;
    }
    if (n == 0) {
      stack.pop_back();
      continue;
    }
    const maze::Side s = options[rng.below(n)];
    m.set_wall(c, s, false);
    const maze::Cell next = maze::neighbour(c, s);
    seen[at(next)] = true;
    stack.push_back(next);
  }
  return m;
}

// Cell centres with random headings, to spread the scans over the maze.
std::vector<maze::sim::Pose> poses(int side, std::uint64_t seed) {
  common::Rng rng(seed);
  std::vector<maze::sim::Pose> out;
  for (int i = 0; i < 256; ++i) {
    const auto x = static_cast<double>(rng.below(static_cast<std::uint64_t>(side)));
    const auto y = static_cast<double>(rng.below(static_cast<std::uint64_t>(side)));
    out.push_back({x + 0.5, y + 0.5, rng.uniform(-std::numbers::pi, std::numbers::pi)});
  }
  return out;
}

void scan(benchmark::State &state, const maze::Maze &m) {
  const maze::sim::WallGrid walls(m);
  // The 12 m lidar of docs/benchmarks.md's table, its whole image from one pose (as a fixed lidar).
  const maze::sim::LidarSpec &spec = maze::sim::find_profile("hambot-12m").lidars.front();
  const maze::sim::LidarModel lidar(spec);
  const double noise = state.range(1) != 0 ? spec.noise : 0.0;
  const std::vector<maze::sim::Pose> where = poses(m.width(), 5);
  std::vector<float> ranges(static_cast<std::size_t>(spec.horizontal_resolution));
  common::Rng rng(1);
  std::size_t i = 0;
  for (auto _ : state) {
    lidar.range_image(walls, noise, where[i++ % where.size()], rng, ranges);
    benchmark::DoNotOptimize(ranges.data());
    benchmark::ClobberMemory();
  }
}

void BM_Scan360_Carved(benchmark::State &state) {
  const maze::Maze m = carved(static_cast<int>(state.range(0)), 42);
  scan(state, m);
}
BENCHMARK(BM_Scan360_Carved)
    ->ArgNames({"side", "noise"})
    ->ArgsProduct({{16, 1024}, {1, 0}})
    ->Unit(benchmark::kMicrosecond);

void BM_Scan360_Open(benchmark::State &state) {
  const maze::Maze m(static_cast<int>(state.range(0)), static_cast<int>(state.range(0)));
  scan(state, m);
}
BENCHMARK(BM_Scan360_Open)
    ->ArgNames({"side", "noise"})
    ->ArgsProduct({{16, 1024}, {1, 0}})
    ->Unit(benchmark::kMicrosecond);

// A control step through the webots:: API: drive, step 32 ms, read the lidar.
void BM_StepAndRead_Carved(benchmark::State &state) {
  const maze::Maze m = carved(static_cast<int>(state.range(0)), 42);
  webots::embedded::Simulation sim(maze::world_of(m), maze::sim::default_profile(), {});
  bench::step_and_read(state, sim.robot());
}
BENCHMARK(BM_StepAndRead_Carved)->Arg(16)->Arg(1024)->Unit(benchmark::kMicrosecond);

// A step alone (sensors are lazy: no scan is computed).
void BM_StepOnly_Carved(benchmark::State &state) {
  const maze::Maze m = carved(static_cast<int>(state.range(0)), 42);
  webots::embedded::Simulation sim(maze::world_of(m), maze::sim::default_profile(), {});
  webots::Robot &robot = sim.robot();
  bench::start_driving(robot);
  for (auto _ : state) benchmark::DoNotOptimize(robot.step(bench::kStep_ms));
}
BENCHMARK(BM_StepOnly_Carved)->Arg(16)->Arg(1024)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
