"""The course robot's helper methods (FAIRIS-Lite's HamBot class, fairis_lib/robot_lib/hambot.py)
on maze_mapper's Robot: the same names, units and conventions, so a lab controller written
against them runs here. Written from the course's documented behaviour; the devices are the
`hambot` profile's ("left motor", "right motor", "left wheel encoder", "right wheel encoder",
"lidar", "imu", "gps").

    get_compass_reading()           bearing in whole degrees, 0 (or 360) east, 90 north,
                                    180 west, 270 south (the IMU's yaw, counter-clockwise)
    get_encoder_readings()          [left, right] wheel angles, rad
    get_left_motor_encoder_reading(), get_right_motor_encoder_reading()   one of them, rad
    get_lidar_range_image()         the lidar's 360 ranges, m (Webots' order: index 0 looks
                                    back, 90 left, 180 ahead, 270 right)
    set_left_motor_velocity(v), set_right_motor_velocity(v)   rad/s, held within the motors'
                                    maximum (a message says so unless suppress=True)
    go_forward(velocity=1), stop(), velocity_saturation(v, suppress=False)
    wheel_radius (0.045 m), axel_length (0.184 m), timestep (ms), max_motor_velocity (rad/s)

The course's supervisor functions change nothing here, as the controller never sees or moves
the maze: load_environment(maze_file) says on stderr that the runner's --world is the maze,
move_to_start() leaves the robot where the runner placed it (the world's start), and
teleport_robot() raises NotImplementedError. No camera or display.

Under maze_mapper.run, `from fairis_lib.robot_lib.hambot import HamBot` (the course's import)
imports this class.
"""

import math
import sys

from .controller import Robot


class HamBot(Robot):
    """The course robot on the embedded simulator (see the module's description)."""

    wheel_radius = 0.045  # m
    axel_length = 0.184  # m, between the wheels

    def __init__(self):
        super().__init__()
        self.timestep = int(self.getBasicTimeStep())
        self.left_motor = self.getDevice("left motor")
        self.right_motor = self.getDevice("right motor")
        self.all_motors = [self.left_motor, self.right_motor]
        self.max_motor_velocity = self.left_motor.getMaxVelocity()
        for motor in self.all_motors:
            motor.setPosition(math.inf)
            motor.setVelocity(0.0)
        self.left_encoder = self.getDevice("left wheel encoder")
        self.right_encoder = self.getDevice("right wheel encoder")
        self.all_encoders = [self.left_encoder, self.right_encoder]
        for sensor in self.all_encoders:
            sensor.enable(self.timestep)
        self.lidar = self.getDevice("lidar")
        self.lidar.enable(self.timestep)
        self.imu = self.getDevice("imu")
        self.imu.enable(self.timestep)
        self.gps = self.getDevice("gps")
        self.gps.enable(self.timestep)
        self.sensor_calibration()

    def sensor_calibration(self):
        """One time step, so that every sensor has a reading."""
        self.step(self.timestep)

    def get_compass_reading(self):
        bearing = math.degrees(self.imu.getRollPitchYaw()[2])
        if bearing < 0.0:
            bearing += 360.0
        return round(bearing)

    def get_encoder_readings(self):
        return [sensor.getValue() for sensor in self.all_encoders]

    def get_left_motor_encoder_reading(self):
        return self.left_encoder.getValue()

    def get_right_motor_encoder_reading(self):
        return self.right_encoder.getValue()

    def get_lidar_range_image(self):
        return self.lidar.getRangeImage()

    def velocity_saturation(self, motor_velocity, suppress=False):
        """motor_velocity held within +- max_motor_velocity (rad/s)."""
        limit = self.max_motor_velocity
        held = max(-limit, min(limit, motor_velocity))
        if held != motor_velocity and not suppress:
            print(f"motor velocity {motor_velocity} is beyond the maximum: set to {held}",
                  file=sys.stderr)
        return held

    def set_left_motor_velocity(self, velocity, suppress=False):
        self.left_motor.setVelocity(self.velocity_saturation(velocity, suppress=suppress))

    def set_right_motor_velocity(self, velocity, suppress=False):
        self.right_motor.setVelocity(self.velocity_saturation(velocity, suppress=suppress))

    def stop(self):
        for motor in self.all_motors:
            motor.setVelocity(0.0)

    def go_forward(self, velocity=1):
        for motor in self.all_motors:
            motor.setVelocity(self.velocity_saturation(velocity))

    def load_environment(self, maze_file):
        print(f"warning: load_environment({maze_file!r}) changes nothing: the maze is the runner's --world",
              file=sys.stderr)

    def move_to_start(self):
        """The robot already stands at the world's start, where the runner placed it."""

    def teleport_robot(self, x=0.0, y=0.0, z=0.0, theta=math.pi / 3):
        raise NotImplementedError("teleport_robot needs a Webots supervisor: a controller here cannot move "
                                  "the robot by hand")
