"""A Webots controller for the Python runner's soak (soak_python.sh): follows the wall on its
left with the lidar until the simulation ends (its step returns -1)."""

import math

from controller import Robot

robot = Robot()
step = int(robot.getBasicTimeStep())
lidar = robot.getDevice("lidar")
lidar.enable(step)
left, right = robot.getDevice("left motor"), robot.getDevice("right motor")
for motor in (left, right):
    motor.setPosition(math.inf)
    motor.setVelocity(0.0)
while robot.step(step) != -1:
    ranges = lidar.getRangeImage()
    if ranges is None:
        continue
    ahead, beside = min(ranges[170:191]), min(ranges[80:101])  # 180 looks ahead, 90 left
    if ahead < 0.3:
        speeds = (3.0, -3.0)  # a wall ahead: turn right on the spot
    elif beside > 0.6:
        speeds = (2.0, 5.0)  # the wall on the left ends: round its corner
    else:
        speeds = (5.0, 5.0)
    left.setVelocity(speeds[0])
    right.setVelocity(speeds[1])
