#pragma once
// The benchmarks' robot under way: its lidar on at the 32 ms step, both wheels turning at
// 5 rad/s, so that each step moves it and a read scans from a new pose.

#include <limits>

#include <benchmark/benchmark.h>
#include <webots/Lidar.hpp>
#include <webots/Motor.hpp>
#include <webots/Robot.hpp>

namespace bench {

constexpr int kStep_ms = 32;

// Sets `robot` moving; returns its lidar.
inline webots::Lidar &start_driving(webots::Robot &robot) {
  webots::Lidar *lidar = robot.getLidar("lidar");
  lidar->enable(kStep_ms);
  for (const char *name : {"left motor", "right motor"}) {
    robot.getMotor(name)->setPosition(std::numeric_limits<double>::infinity());
    robot.getMotor(name)->setVelocity(5.0);
  }
  return *lidar;
}

// The timed loop of a control step: step, then read the range image.
inline void step_and_read(benchmark::State &state, webots::Robot &robot) {
  const webots::Lidar &lidar = start_driving(robot);
  for (auto _ : state) {
    robot.step(kStep_ms);
    benchmark::DoNotOptimize(lidar.getRangeImage());
  }
}

}  // namespace bench
