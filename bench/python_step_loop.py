"""How fast a Python controller's robot.step() loop runs on the embedded simulator: a Webots
controller that times itself (docs/benchmarks.md quotes its numbers).

    python3 -m maze_mapper.run bench/python_step_loop.py --world worlds/lab4x4.txt --max-steps 1000000

Three loops of control steps (32 ms each), the robot turning in place in its start cell:
  step        robot.step() alone
  pose        robot.step() and what a lab loop reads every step: GPS, IMU, both encoders
  lidar       robot.step() and the whole 360-beam range image every step, as a NumPy array
  map         the same with a metric map kept (maze_mapper.keep_map: 340 x 340 cells of 0.05 m,
              a NumPy array the runner reads for the replay every 58 steps under --out)
Each prints its control steps a second (the best of three rounds).
"""

import math
import sys
import time

from controller import Robot

ROUNDS = 3


def timed(label, steps, body):
    best = 0.0
    for _ in range(ROUNDS):
        started = time.perf_counter()
        body(steps)
        best = max(best, steps / (time.perf_counter() - started))
    print(f"{label:<6} {best:>10,.0f} steps/s  ({steps} steps, best of {ROUNDS})")


def main():
    robot = Robot()
    ts = int(robot.getBasicTimeStep())
    left, right = robot.getDevice("left motor"), robot.getDevice("right motor")
    for motor, v in ((left, -2.0), (right, 2.0)):
        motor.setPosition(math.inf)
        motor.setVelocity(v)
    gps, imu, lidar = robot.getDevice("gps"), robot.getDevice("imu"), robot.getDevice("lidar")
    encoders = [robot.getDevice("left wheel encoder"), robot.getDevice("right wheel encoder")]
    for sensor in (gps, imu, lidar, *encoders):
        sensor.enable(ts)

    def bare(n):
        for _ in range(n):
            robot.step(ts)

    def pose(n):
        for _ in range(n):
            robot.step(ts)
            gps.getValues()
            imu.getRollPitchYaw()
            encoders[0].getValue()
            encoders[1].getValue()

    def ranges(n):
        for _ in range(n):
            robot.step(ts)
            lidar.getRangeImage()

    timed("step", 100_000, bare)
    timed("pose", 50_000, pose)
    timed("lidar", 20_000, ranges)
    import maze_mapper
    import numpy as np
    grid = np.zeros((340, 340))
    grid[::7, ::5] = 0.85  # observed cells: the replay records them
    maze_mapper.keep_map(grid, origin=(-8.5, -8.5), cell_size_m=0.05)
    timed("map", 20_000, ranges)
    return 0


if __name__ == "__main__":
    sys.exit(main())
