// LidarSweep::last_pass_steps (all beams by binary search over the phase order) against its
// reference last_pass_step (one beam at a time), bit for bit, over every step of long runs and
// lidars of every shape: whole and partial fields of view, few and many beams, less than one,
// exactly one and several revolutions a step (where passes fall exactly on step boundaries).

#include <doctest/doctest.h>

#include <numbers>
#include <vector>

#include "maze/sim/lidar_sweep.hpp"

namespace {

maze::sim::LidarSpec lidar(int beams, double fov_rad) {
  maze::sim::LidarSpec s;
  s.name = "lidar";
  s.horizontal_resolution = beams;
  s.fov_rad = fov_rad;
  s.max_range_m = 3.0;
  s.frequency_hz = 12.0;  // a rotating head: its beams on fov/2 - i fov/N
  return s;
}

}  // namespace

TEST_CASE("LidarSweep: every beam's last pass, all beams at once, equals the one-beam reference") {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  const maze::sim::LidarSpec shapes[] = {lidar(360, kTurn), lidar(1, kTurn), lidar(7, kTurn), lidar(512, kTurn),
                                         lidar(270, 0.75 * kTurn), lidar(90, 1.0), lidar(361, kTurn)};
  // (frequency Hz, time step ms): r = 0.384 (HamBot), 0.32, 1 exactly, 0.5, 2.5, 1/3-ish, 0.01.
  const std::pair<double, int> timings[] = {{12.0, 32}, {10.0, 32}, {31.25, 32}, {15.625, 32},
                                            {39.0625, 64}, {10.0, 33}, {0.625, 16}};
  for (const maze::sim::LidarSpec &spec : shapes) {
    const maze::sim::LidarModel model(spec);
    for (const auto &timing : timings) {
      const double hz = timing.first;  // named, not bound: clang 14 cannot capture a binding
      const int ms = timing.second;
      const maze::sim::LidarSweep sweep(model, hz * ms / 1000.0);
      std::vector<std::int64_t> all(static_cast<std::size_t>(spec.horizontal_resolution));
      int mismatches = 0;
      for (std::int64_t steps = 0; steps <= 3000; ++steps) {
        sweep.last_pass_steps(steps, all);
        for (int i = 0; i < spec.horizontal_resolution; ++i) {
          if (all[static_cast<std::size_t>(i)] != sweep.last_pass_step(steps, i)) ++mismatches;
        }
      }
      CAPTURE(spec.horizontal_resolution);
      CAPTURE(hz);
      CAPTURE(ms);
      CHECK(mismatches == 0);
    }
  }
}

TEST_CASE("LidarSweep: the HamBot's head passes each beam once a revolution, in the step that sweeps it") {
  const maze::sim::LidarModel model(lidar(360, 2.0 * std::numbers::pi));
  const maze::sim::LidarSweep sweep(model, 12.0 * 32 / 1000.0);  // 0.384 revolutions a step
  // Beam 180 looks ahead: phase 0, passed at the very start, so 0 until a step has run... at
  // revolution 0 exactly, which no step sweeps ((s - 1) r, s r] excludes 0): next at 1.0,
  // in step 3 (0.768, 1.152].
  CHECK(sweep.last_pass_step(0, 180) == 0);
  CHECK(sweep.last_pass_step(2, 180) == 0);
  CHECK(sweep.last_pass_step(3, 180) == 3);
  CHECK(sweep.last_pass_step(5, 180) == 3);  // next pass at 2.0, in step 6 (1.92, 2.304]
  CHECK(sweep.last_pass_step(6, 180) == 6);
  // Beam 270 looks right: a quarter turn clockwise, phase 0.25, in step 1 (0, 0.384].
  CHECK(sweep.last_pass_step(1, 270) == 1);
  CHECK(sweep.last_pass_step(3, 270) == 1);
  CHECK(sweep.last_pass_step(4, 270) == 4);  // 1.25 in (1.152, 1.536]
}
