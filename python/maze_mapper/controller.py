"""Webots' Python controller API (the `controller` module of Webots R2023b and later) over
maze_mapper's embedded simulator: Robot, Supervisor, Keyboard and the devices Lidar, Motor,
PositionSensor, InertialUnit, GPS, DistanceSensor, TouchSensor, the course HamBot's Camera
(with recognition) and Display, and Compass, Accelerometer, Gyro and LED where the runner's
--device adds them (devices.py), with Webots' method names and semantics.

Under `python3 -m maze_mapper.run CONTROLLER.py [--world WORLD]`, `from controller import
Robot` (or Supervisor) imports this module, so a Webots controller that uses these runs
unchanged. Where it differs from Webots (docs/python.md, docs/course.md): a disabled sensor
reads NaN (a disabled lidar None); the Supervisor sees and edits the scene only as far as the
course's library does (scene.py, supervision.py); Motor.setAcceleration is kept, not modelled;
the keyboard is a script of timed keys or the terminal (keyboard.py).
"""

import math
import sys
import time

from . import _native
from . import devices as _devices
from . import keyboard as _keyboard
from . import scene as _scene
from . import supervision as _supervision
from .camera import Camera, CameraRecognitionObject, Display
from .devices import LED, Accelerometer, Compass, Gyro
from .keyboard import Keyboard
from .scene import Field, Node, SceneError

Device = _native.Device
Lidar = _native.Lidar
Motor = _native.Motor
PositionSensor = _native.PositionSensor
InertialUnit = _native.InertialUnit
GPS = _native.GPS
DistanceSensor = _native.DistanceSensor
TouchSensor = _native.TouchSensor

class RangeImage(list):
    """A lidar range image as Webots' Python API hands it: a list of floats (m; inf for no
    return), so item assignment, copy, json and every list operation work. `image.array` (and
    np.asarray(image)) is the float32 array the simulator filled, read-only, no copy: the
    image as read, whatever the list is changed to afterwards."""

    __slots__ = ("array",)

    def __init__(self, array):
        super().__init__(array.tolist())
        array.flags.writeable = False
        self.array = array

    def __array__(self, dtype=None, copy=None):
        return self.array if dtype is None else self.array.astype(dtype, copy=False)


def _get_range_image(lidar):
    """The range image (a RangeImage), or None when the lidar is disabled."""
    array = lidar._range_image()
    return None if array is None else RangeImage(array)


_native.Lidar.getRangeImage = _get_range_image
_native.Lidar.range_image = property(_get_range_image)


class LidarPoint:
    """One point of a lidar's point cloud (Webots' LidarPoint): x ahead, y left, z up in the
    lidar's frame (m), its layer and time (s since the scan began)."""

    __slots__ = ("x", "y", "z", "layer_id", "time")

    def __init__(self, x, y, z, layer_id, t):
        self.x, self.y, self.z, self.layer_id, self.time = x, y, z, layer_id, t

    def __repr__(self):
        return f"LidarPoint(x={self.x}, y={self.y}, z={self.z}, layer_id={self.layer_id}, time={self.time})"


_point_clouds_on = set()  # names of the lidars whose point cloud is enabled


def _beam_directions(lidar):
    """Each beam's (cos, sin) from the lidar's heading, in the range image's order."""
    n, fov = lidar.getHorizontalResolution(), lidar.getFov()
    offset = 0.0 if lidar.getFrequency() > 0.0 else 0.5
    angles = (fov / 2.0 - (i + offset) * fov / n for i in range(n))
    return [(math.cos(a), math.sin(a)) for a in angles]


def _layer_range_image(lidar, layer):
    if layer != 0:
        raise IndexError(f"layer {layer} of a lidar with {lidar.getNumberOfLayers()} layer")
    return lidar.getRangeImage()


def _layer_point_cloud(lidar, layer, data_type="list"):
    if lidar.getName() not in _point_clouds_on:
        print("Warning: Lidar.getPointCloud(): the point cloud is disabled: call enablePointCloud() first.",
              file=sys.stderr)
        return None
    ranges = _layer_range_image(lidar, layer)
    if ranges is None:
        return None
    points = [LidarPoint(r * c, r * s, 0.0, layer, 0.0) for r, (c, s) in zip(ranges, _beam_directions(lidar))]
    if data_type == "list":
        return points
    raise ValueError(f"data_type {data_type!r}: this simulator hands the point cloud as a 'list'")


_native.Lidar.enablePointCloud = lambda lidar: _point_clouds_on.add(lidar.getName())
_native.Lidar.disablePointCloud = lambda lidar: _point_clouds_on.discard(lidar.getName())
_native.Lidar.isPointCloudEnabled = lambda lidar: lidar.getName() in _point_clouds_on
_native.Lidar.getLayerRangeImage = _layer_range_image
_native.Lidar.getLayerPointCloud = _layer_point_cloud
_native.Lidar.getPointCloud = lambda lidar, data_type="list": _layer_point_cloud(lidar, 0, data_type)
_native.Lidar.getNumberOfPoints = lambda lidar: lidar.getHorizontalResolution() * lidar.getNumberOfLayers()
_native.Lidar.point_cloud = property(lambda lidar: lidar.getPointCloud())


def _gps_speed(gps):
    """The robot's speed over the last step, m/s (Webots' GPS.getSpeed); NaN when disabled."""
    robot = Robot.created
    if gps.getSamplingPeriod() <= 0 or robot is None or _scene.current is None or robot._before is None:
        return math.nan
    x0, y0, z0, _ = robot._before
    x1, y1, z1, _ = _scene.current.simulation.pose
    return math.sqrt((x1 - x0) ** 2 + (y1 - y0) ** 2 + (z1 - z0) ** 2) / (robot.getBasicTimeStep() / 1000.0)


def _gps_speed_vector(gps):
    robot = Robot.created
    if gps.getSamplingPeriod() <= 0 or robot is None or _scene.current is None or robot._before is None:
        return [math.nan] * 3
    dt = robot.getBasicTimeStep() / 1000.0
    return [(b - a) / dt for a, b in zip(robot._before[:3], _scene.current.simulation.pose[:3])]


_native.GPS.getSpeed = _gps_speed
_native.GPS.getSpeedVector = _gps_speed_vector
_native.GPS.speed = property(_gps_speed)
_native.GPS.speed_vector = property(_gps_speed_vector)


def _quaternion(imu):
    """[x, y, z, w] of the IMU's roll, pitch and yaw (Webots' InertialUnit.getQuaternion)."""
    roll, pitch, yaw = imu.getRollPitchYaw()
    cr, sr = math.cos(roll / 2.0), math.sin(roll / 2.0)
    cp, sp = math.cos(pitch / 2.0), math.sin(pitch / 2.0)
    cy, sy = math.cos(yaw / 2.0), math.sin(yaw / 2.0)
    return [sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy]


_native.InertialUnit.getQuaternion = _quaternion
_native.InertialUnit.quaternion = property(_quaternion)

_accelerations = {}  # motor name -> the acceleration set (rad/s^2; -1: none)


def _set_acceleration(motor, acceleration):
    """Webots' Motor.setAcceleration: kept and read back; the simulator's motors reach their
    velocity at once (not modelled)."""
    _accelerations[motor.getName()] = float(acceleration)


_native.Motor.setAcceleration = _set_acceleration
_native.Motor.getAcceleration = lambda motor: _accelerations.get(motor.getName(), -1.0)

__all__ = ["Robot", "Supervisor", "Node", "Field", "Device", "Lidar", "LidarPoint", "Motor", "PositionSensor",
           "InertialUnit", "GPS", "DistanceSensor", "TouchSensor", "Camera", "CameraRecognitionObject",
           "Display", "Keyboard", "Compass", "Accelerometer", "Gyro", "LED", "RangeImage", "SimulationEnded",
           "SceneError"]

_SUPPORTED = ("Robot", "Supervisor", "Keyboard", "Lidar", "Motor", "PositionSensor", "InertialUnit", "GPS",
              "DistanceSensor", "TouchSensor", "Camera", "Display", "Compass", "Accelerometer", "Gyro", "LED")
_devices.add_camera_methods()

# The wall-clock time (time.perf_counter()) after which the runner ends the simulation (its
# --wall-limit), or None; and whether a step has ended it so.
wall_deadline = None
wall_limit_reached = False


class SimulationEnded(SystemExit):
    """Raised by a step after the one that returned -1: Webots ends a controller that goes on
    stepping once the simulation is over."""


class Robot:
    """The robot this controller runs (Webots' Robot). Only one per controller process."""

    EVENT_QUIT = -1
    EVENT_NO_EVENT = 0
    created = None

    def __init__(self):
        if Robot.created is not None:
            print("Error: only one Robot instance can be created per controller process.",
                  file=sys.stderr)
            return
        self._handle = _native.RobotHandle()
        Robot.created = self
        self._ended = False
        self._before = None  # the pose before the last step (GPS speed)
        self.distance_m = 0.0  # the path the body has moved along, teleports left out
        self.devices = {name: self._handle.device(name) for name in self._handle.device_names()}
        if self._handle.getName().startswith("hambot"):
            # The course HamBot's camera and displays (camera.py): "User Display", and the
            # "Place Cell Display" the course's earlier HamBot library opens.
            self.devices["camera"] = Camera("camera")
            self.devices["User Display"] = Display("User Display")
            self.devices["Place Cell Display"] = Display("Place Cell Display", 800, 800)
        self.devices.update(_devices.extra_devices())  # the runner's --device
        self._names = list(self.devices)
        self._keyboard = Keyboard(0)  # disabled until enable(), as Webots' robot's keyboard
        if _scene.current is not None:  # where the goals of the controller's own world are found
            _scene.current.goal.namespace = vars(sys.modules["__main__"])

    # ---- time ----

    def step(self, time_step=None):
        """Advances the simulation by time_step ms (default: the basic time step); returns -1
        once the simulation has ended (the runner's time limit), else 0."""
        if time_step is None:
            time_step = int(self._handle.getBasicTimeStep())
        if self._ended:
            raise SimulationEnded(0)
        if wall_deadline is not None and time.perf_counter() > wall_deadline:
            global wall_limit_reached
            wall_limit_reached = True
            _scene.current.simulation.request_stop()
        if _scene.current is not None:
            self._record_path(_scene.current)
        result = self._handle.step(time_step)
        if result == -1:
            self._ended = True
        elif _scene.current is not None and _scene.current.reset_requested:
            _scene.current.reset()
            _devices.forget_targets()
        self._step_s = time_step / 1000.0  # the last step's duration (Node.getVelocity)
        if _devices.requested:  # a Compass, Gyro, Accelerometer or LED from --device
            _devices.motion.after_step(self)
        if _keyboard.state.period_ms > 0:
            _keyboard.state.sample(self.getTime() * 1000.0)
        return result

    def _record_path(self, scene):
        """Keeps the pose before this step and adds the last step's move to distance_m."""
        pose = scene.simulation.pose
        if self._before is not None and not scene.teleported:
            self.distance_m += math.hypot(pose[0] - self._before[0], pose[1] - self._before[1])
        scene.teleported = False
        self._before = pose

    def getBasicTimeStep(self):
        return self._handle.getBasicTimeStep()

    def getTime(self):
        return self._handle.getTime()

    def getName(self):
        return self._handle.getName()

    @property
    def basic_time_step(self):
        return self._handle.getBasicTimeStep()

    @property
    def time(self):
        return self._handle.getTime()

    @property
    def name(self):
        return self._handle.getName()

    # ---- devices ----

    def getDevice(self, name):
        """The device called name, or None, after Webots' message on stderr, when the robot has
        none by that name."""
        device = self.devices.get(name)
        if device is None:
            print(f'Device "{name}" was not found on robot "{self.getName()}"', file=sys.stderr)
        return device

    def getKeyboard(self):
        """The robot's keyboard (Webots' Keyboard; keyboard.py): enable(ms), then getKey()."""
        return self._keyboard

    @property
    def keyboard(self):
        return self._keyboard

    def getNumberOfDevices(self):
        return len(self._names)

    def getDeviceByIndex(self, index):
        return self.devices[self._names[index]]

    @property
    def number_of_devices(self):
        return len(self._names)

    def _deprecated(self, what, name):
        print(f"DEPRECATION: Robot.{what} is deprecated, please use Robot.getDevice instead.",
              file=sys.stderr)
        return self.getDevice(name)

    def getLidar(self, name):
        return self._deprecated("getLidar", name)

    def getMotor(self, name):
        return self._deprecated("getMotor", name)

    def getPositionSensor(self, name):
        return self._deprecated("getPositionSensor", name)

    def getInertialUnit(self, name):
        return self._deprecated("getInertialUnit", name)

    def getGPS(self, name):
        return self._deprecated("getGPS", name)

    def getDistanceSensor(self, name):
        return self._deprecated("getDistanceSensor", name)

    def getTouchSensor(self, name):
        return self._deprecated("getTouchSensor", name)

    def getCompass(self, name):
        return self._deprecated("getCompass", name)

    def getAccelerometer(self, name):
        return self._deprecated("getAccelerometer", name)

    def getGyro(self, name):
        return self._deprecated("getGyro", name)

    def getLED(self, name):
        return self._deprecated("getLED", name)


class Supervisor(Robot):
    """The robot as a Webots supervisor (the course's HamBot is one): the scene tree as far as
    the course's library uses it (scene.py): getRoot, getSelf, getFromDef, getFromId,
    importing Obstacle and Landmark nodes, the robot's translation and rotation (a teleport),
    simulationReset; and setLabel, exportImage, worldReload, getSelected, getFromDevice
    (supervision.py)."""

    SIMULATION_MODE_PAUSE = 0
    SIMULATION_MODE_REAL_TIME = 1
    SIMULATION_MODE_FAST = 2

    def __init__(self):
        super().__init__()
        self._mode = Supervisor.SIMULATION_MODE_FAST

    @staticmethod
    def _scene():
        if _scene.current is None:
            raise RuntimeError("no scene: run the controller with python3 -m maze_mapper.run CONTROLLER.py")
        return _scene.current

    def getRoot(self):
        return self._scene().root

    def getSelf(self):
        return self._scene().robot

    def getFromDef(self, name):
        return self._scene().from_def(name)

    def getFromId(self, node_id):
        return self._scene().from_id(node_id)

    def simulationReset(self):
        """Webots' reset from a supervisor, at the end of the next step: the imported nodes
        removed, the robot at its start with its motors and encoders at 0, the simulated time
        back at 0 (getTime()); the controller goes on (scene.Scene.reset)."""
        self._scene().reset_requested = True

    def simulationResetPhysics(self):
        """The body has no momentum here: nothing to reset."""

    def simulationGetMode(self):
        return self._mode

    def simulationSetMode(self, mode):
        self._mode = mode

    def simulationQuit(self, status):
        """The next step returns -1, as when Webots quits."""
        self._scene().simulation.request_stop()


# setLabel, exportImage, worldReload, getSelected, getFromDevice (supervision.py).
_supervision.add_supervisor_methods(Supervisor)


def __getattr__(name):
    # `from controller import Supervisor` (or Camera, Keyboard, ...): say what exists here.
    if name.startswith("_"):
        raise AttributeError(name)
    raise ImportError(
        f"maze_mapper's controller module has no {name}: the embedded simulator offers "
        f"{', '.join(_SUPPORTED)} (docs/python.md)")
