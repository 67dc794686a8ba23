"""The course robot's class (FAIRIS-Lite's HamBot, fairis_lib/robot_lib/hambot.py) where the
course's library is not on the path: the same names, units and conventions on maze_mapper's
Supervisor, so a lab controller written against them runs here. Written from the course's
documented behaviour; the devices are the `hambot` profile's ("left motor", "right motor",
"left wheel encoder", "right wheel encoder", "lidar", "imu", "gps") and the course HamBot's
"camera" (recognition on) and "User Display".

    get_compass_reading()           bearing in whole degrees, 0 (or 360) east, 90 north,
                                    180 west, 270 south (the IMU's yaw, counter-clockwise)
    get_encoder_readings()          [left, right] wheel angles, rad
    get_left_motor_encoder_reading(), get_right_motor_encoder_reading()   one of them, rad
    get_lidar_range_image()         the lidar's 360 ranges, m (Webots' order: index 0 looks
                                    back, 90 left, 180 ahead, 270 right)
    set_left_motor_velocity(v), set_right_motor_velocity(v)   rad/s, held within the motors'
                                    maximum (a message says so unless suppress=True)
    go_forward(velocity=1), stop(), velocity_saturation(v, suppress=False)
    load_environment(maze_file)     builds the course's XML world with the supervisor: each
                                    <wall> an Obstacle box (the first four the boundary
                                    walls), each <landmark> a Landmark cylinder; keeps the
                                    <startPositions> and <goal>s
    move_to_start()                 teleports to one of the file's starts, drawn with Python's
                                    random (the runner seeds it: --seed)
    teleport_robot(x, y, z, theta)  sets the robot's translation and rotation, then steps once
    wheel_radius (0.045 m), axel_length (0.184 m), timestep (ms), max_motor_velocity (rad/s),
    experiment_supervisor (the Supervisor: here the robot itself)

Under maze_mapper.run, `from fairis_lib.robot_lib.hambot import HamBot` (the course's import)
imports this class when the course's own fairis_lib is not importable.
"""

import math
import random
import sys
import xml.etree.ElementTree as ElementTree

from .controller import Supervisor

WALL_HEIGHT_M = 0.5        # the course's Obstacle walls
WALL_WIDTH_M = 0.012       # a <wall> without width
LANDMARK_RADIUS_M = 0.25   # the course's Landmark cylinders


class StartingPosition:
    """A start pose of the world file: x, y (m), theta (rad)."""

    def __init__(self, x, y, theta):
        self.x, self.y, self.theta = x, y, theta


class Goal:
    def __init__(self, x, y, goal_id):
        self.x, self.y, self.goal_id = x, y, goal_id


def _attribute(element, name, default=None):
    text = element.get(name)
    if text is None:
        if default is None:
            raise ValueError(f"<{element.tag}> has no {name}")
        return default
    return float(text)


def wall_node(def_name, x1, y1, x2, y2, width):
    """The course's Obstacle node string for the wall from (x1, y1) to (x2, y2)."""
    length = math.hypot(x2 - x1, y2 - y1)
    theta = math.atan2(x1 - x2, y1 - y2)
    return (f"DEF {def_name} Obstacle {{ translation {(x1 + x2) / 2!r} {(y1 + y2) / 2!r} {WALL_HEIGHT_M / 2!r} "
            f"rotation 0 0 1 {theta!r} size {width!r} {length!r} {WALL_HEIGHT_M!r} }}")


def landmark_node(def_name, x, y, height, rgb):
    """The course's Landmark node string: an upright cylinder, recognised in its colour."""
    r, g, b = rgb
    return (f"DEF {def_name} Landmark {{ translation {x!r} {y!r} {height / 2!r} color {r!r} {g!r} {b!r} "
            f"recognitionColors [{r!r} {g!r} {b!r}] size {height!r} {LANDMARK_RADIUS_M!r} "
            f"{LANDMARK_RADIUS_M - 0.01!r} }}")


class HamBot(Supervisor):
    """The course robot on the embedded simulator (see the module's description)."""

    wheel_radius = 0.045  # m
    axel_length = 0.184  # m, between the wheels

    def __init__(self):
        super().__init__()
        self.experiment_supervisor = self
        self.display = self.getDevice("User Display")
        self.root_node = self.getRoot()
        self.children_field = self.root_node.getField("children")
        self.robot_node = self.getSelf()
        self.robot_translation_field = self.robot_node.getField("translation")
        self.robot_rotation_field = self.robot_node.getField("rotation")
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
        self.camera = self.getDevice("camera")
        self.camera.enable(self.timestep)
        self.camera.recognitionEnable(self.timestep)
        self.lidar = self.getDevice("lidar")
        self.lidar.enable(self.timestep)
        self.lidar.enablePointCloud()
        self.imu = self.getDevice("imu")
        self.imu.enable(self.timestep)
        self.gps = self.getDevice("gps")
        self.gps.enable(self.timestep)
        self.starting_locations = []
        self.goal_locations = []
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
        """Builds the world of the course's XML file (see the module's description)."""
        root = ElementTree.parse(maze_file).getroot()
        for index, wall in enumerate(root.findall("wall")):
            ends = [_attribute(wall, k) for k in ("x1", "y1", "x2", "y2")]
            name = f"Boundary_Wall{index}" if index <= 3 else f"Obstacle_{index - 4}"
            self.children_field.importMFNodeFromString(
                -1, wall_node(name, *ends, _attribute(wall, "width", WALL_WIDTH_M)))
        for index, landmark in enumerate(root.findall("landmark")):
            rgb = [_attribute(landmark, k) for k in ("red", "green", "blue")]
            self.children_field.importMFNodeFromString(
                -1, landmark_node(f"Landmark_{index}", _attribute(landmark, "x"), _attribute(landmark, "y"),
                                  _attribute(landmark, "height", 1.5), rgb))
        starts = root.find("startPositions")
        self.starting_locations = [
            StartingPosition(_attribute(p, "x"), _attribute(p, "y"), _attribute(p, "theta", math.pi / 2))
            for p in (starts.findall("pos") if starts is not None else [])]
        self.goal_locations = [Goal(_attribute(g, "x"), _attribute(g, "y"), int(_attribute(g, "id", 0)))
                               for g in root.findall("goal")]

    def teleport_robot(self, x=0.0, y=0.0, z=0.0, theta=math.pi / 3):
        self.robot_translation_field.setSFVec3f([x, y, z])
        self.robot_rotation_field.setSFRotation([0, 0, 1, theta])
        self.sensor_calibration()

    def move_to_start(self):
        """Teleports to one of the world file's starts, drawn as the course draws it."""
        if not self.starting_locations:
            raise RuntimeError("move_to_start: the world has no <startPositions> (call load_environment first)")
        self.starting_position = random.sample(self.starting_locations, 1)[0]
        self.teleport_robot(self.starting_position.x, self.starting_position.y, theta=self.starting_position.theta)
