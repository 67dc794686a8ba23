"""Webots' Compass, Accelerometer, Gyro and LED over the embedded simulator, and the methods of
the simulator's own devices its native module leaves to Python (Motor.getTargetPosition, ...).

A robot gets a Compass, Accelerometer, Gyro or LED from the runner's `--device TYPE[:NAME]`
(repeatable; NAME defaults to Webots' default name of the node: compass, accelerometer, gyro,
led): no built-in robot carries one, as the course's HamBot does not. Each sits at the robot's
origin with the robot's axes (Webots' ENU world: x east, y north, z up; the robot's x ahead, y
left, z up) and reads, once enabled, what the simulated pose did over the last step:

  - Compass.getValues(): the north direction (world +y) in the robot's frame, a unit vector:
    [sin(yaw), cos(yaw), 0] for the yaw from east (facing north: [1, 0, 0]);
  - Gyro.getValues(): the angular velocity about x, y, z in rad/s: [0, 0, yaw rate];
  - Accelerometer.getValues(): the acceleration in m/s^2 in the robot's frame with gravity, as a
    real accelerometer: [0, 0, 9.81] at rest on the flat floor (Webots' default gravity), the
    body's own acceleration (the change of its velocity over the last two steps) added in x and
    y: ahead and sideways (centripetal in a turn), read in the frame of the middle pose;
  - LED.set(value) keeps value (Webots' int: 0 off, else a colour index or 0xRRGGBB) and get()
    reads it back.

A disabled sensor reads NaN, as the simulator's other sensors; a teleport or reset starts the
motion afresh (no jump is read as acceleration).
"""

import math
import sys

from . import _native
from . import scene as _scene

GRAVITY_M_S2 = 9.81  # Webots' WorldInfo.gravity default


class _Motion:
    """The robot's last poses at step ends: (time_s, x, y, yaw), the newest last, at most 3."""

    def __init__(self):
        self.poses = []

    def after_step(self, robot):
        if _scene.current is None:
            return
        before = robot._before  # the pose when the step began (after any teleport)
        if not self.poses or before is None or self.poses[-1][1:] != (before[0], before[1], before[3]):
            self.poses = [] if before is None else [(robot.getTime() - robot.getBasicTimeStep() / 1000.0,
                                                      before[0], before[1], before[3])]
        x, y, _, yaw = _scene.current.simulation.pose
        self.poses = (self.poses + [(robot.getTime(), x, y, yaw)])[-3:]

    def velocity(self, i):
        """(vx, vy, yaw rate) between poses[i - 1] and poses[i], world frame."""
        (t0, x0, y0, a0), (t1, x1, y1, a1) = self.poses[i - 1], self.poses[i]
        dt = t1 - t0
        if dt <= 0.0:
            return 0.0, 0.0, 0.0
        turn = math.atan2(math.sin(a1 - a0), math.cos(a1 - a0))
        return (x1 - x0) / dt, (y1 - y0) / dt, turn / dt

    def yaw(self):
        return self.poses[-1][3] if self.poses else _scene.current.simulation.pose[3]


motion = _Motion()


class _Device:
    """What every device answers: its name, and a model of "" (none is set here)."""

    NODE_TYPE = ""

    def __init__(self, name):
        self._name = name

    def getName(self):
        return self._name

    def getModel(self):
        return ""

    @property
    def name(self):
        return self._name


class _Sensor(_Device):
    """A device that reads after enable(sampling_period) (ms)."""

    def __init__(self, name):
        super().__init__(name)
        self._period_ms = 0

    def enable(self, sampling_period):
        self._period_ms = int(sampling_period)

    def disable(self):
        self._period_ms = 0

    def getSamplingPeriod(self):
        return self._period_ms

    sampling_period = property(getSamplingPeriod, enable)

    def getValues(self):
        if self._period_ms <= 0 or _scene.current is None:
            return [math.nan] * 3
        return self._read()

    @property
    def value(self):
        return self.getValues()

    def getLookupTable(self):
        return []  # no lookupTable: the values are the physical ones


class Compass(_Sensor):
    NODE_TYPE = "Compass"

    def _read(self):
        yaw = motion.yaw()
        return [math.sin(yaw), math.cos(yaw), 0.0]


class Gyro(_Sensor):
    NODE_TYPE = "Gyro"

    def _read(self):
        rate = motion.velocity(len(motion.poses) - 1)[2] if len(motion.poses) >= 2 else 0.0
        return [0.0, 0.0, rate]


class Accelerometer(_Sensor):
    NODE_TYPE = "Accelerometer"

    def _read(self):
        if len(motion.poses) < 3:
            return [0.0, 0.0, GRAVITY_M_S2]
        (vx0, vy0, _), (vx1, vy1, _) = motion.velocity(1), motion.velocity(2)
        dt = motion.poses[2][0] - motion.poses[1][0]
        ax, ay = (vx1 - vx0) / dt, (vy1 - vy0) / dt
        yaw = motion.poses[1][3]  # the change is the middle pose's: read in its frame
        c, s = math.cos(yaw), math.sin(yaw)
        return [c * ax + s * ay, -s * ax + c * ay, GRAVITY_M_S2]


class LED(_Device):
    """Webots' LED: set(value) kept, get() reads it back (0 at the start: off)."""

    NODE_TYPE = "LED"

    def __init__(self, name):
        super().__init__(name)
        self._value = 0

    def set(self, value):
        self._value = int(value)

    def get(self):
        return self._value

    value = property(get, set)


TYPES = {"compass": Compass, "accelerometer": Accelerometer, "gyro": Gyro, "led": LED}

# The runner's --device requests: (type, name) each.
requested = []


def parse_device_option(text):
    """(type, name) of a --device TYPE[:NAME]; ValueError with the message for a bad one."""
    kind, _, name = text.partition(":")
    if kind not in TYPES:
        raise ValueError(f"--device {text}: the type must be one of {', '.join(TYPES)}")
    if _ and not name:
        raise ValueError(f"--device {text}: the name after ':' is empty")
    return kind, name or kind


def extra_devices():
    """The devices --device asked for, by name."""
    return {name: TYPES[kind](name) for kind, name in requested}


# ---- the simulator's own devices: what Webots' Python API has and the native module not ----

_target_positions = {}  # motor name -> the position last set (rad; inf: velocity control)
_native_set_position = _native.Motor.setPosition


def _set_position(motor, position):
    _target_positions[motor.getName()] = float(position)
    _native_set_position(motor, position)


def _paired(device, offset):
    """The robot's motor and encoder are listed motors first: left, right, left, right."""
    from . import controller
    robot = controller.Robot.created
    names = robot._handle.device_names()
    index = names.index(device.getName())
    return robot.devices[names[index + offset]]


_native.Motor.setPosition = _set_position
_native.Motor.getTargetPosition = lambda motor: _target_positions.get(motor.getName(), 0.0)
_native.Motor.target_position = property(_native.Motor.getTargetPosition)
_native.Motor.getPositionSensor = lambda motor: _paired(motor, 2)
_native.Motor.position_sensor = property(_native.Motor.getPositionSensor)
_native.PositionSensor.getMotor = lambda encoder: _paired(encoder, -2)
_native.PositionSensor.motor = property(_native.PositionSensor.getMotor)


def forget_targets():
    """At a reset: the motors back at their initial position (0)."""
    _target_positions.clear()


LIDAR_VERTICAL_FOV_RAD = 0.2  # Webots' Lidar verticalFieldOfView default (no course lidar sets it)


def _set_frequency(lidar, frequency):
    """Webots' wb_lidar_set_frequency: the range check (its error line, nothing changes), then a
    rotating lidar's head turns at the new frequency from where it stands (getFrequency returns
    it); on a fixed lidar, which has no head to turn, a warning says the call changes nothing."""
    low, high = lidar.getMinFrequency(), lidar.getMaxFrequency()
    if not low <= frequency <= high:
        print(f"Error: wb_lidar_set_frequency() out of frequency range [{low:f}, {high:f}].", file=sys.stderr)
        return
    if not lidar.getFrequency() > 0.0:
        print(f"Warning: Lidar.setFrequency({frequency:g}): {lidar.getName()} is a fixed lidar: it has no head "
              "to turn, the call changes nothing", file=sys.stderr)
        return
    sys.stderr.flush()
    lidar._set_rotating_frequency(float(frequency))


_native.Lidar.getVerticalFov = lambda lidar: LIDAR_VERTICAL_FOV_RAD
_native.Lidar.vertical_fov = property(_native.Lidar.getVerticalFov)
_native.Lidar.setFrequency = _set_frequency

_native.GPS.LOCAL = 0  # Webots' WorldInfo.gpsCoordinateSystem "local" (the default) and "WGS84"
_native.GPS.WGS84 = 1
_native.GPS.getCoordinateSystem = lambda gps: _native.GPS.LOCAL
_native.GPS.coordinate_system = property(_native.GPS.getCoordinateSystem)


# ---- the course HamBot's camera (camera.py) ----

def _camera():
    from . import camera
    return camera


def _save_image(cam, filename, quality):
    """Webots' Camera.saveImage: the last image as a PNG file (.png); 0 when written, else -1
    after an error line. JPEG (.jpg, .jpeg) is not written here."""
    camera = _camera()
    extension = filename.rsplit(".", 1)[-1].lower() if "." in filename else ""
    if extension in ("jpg", "jpeg"):
        print(f"Error: Camera.saveImage(): {filename}: JPEG is not written by the embedded simulator: use a .png name",
              file=sys.stderr)
        return -1
    if extension != "png":
        print(f"Error: Camera.saveImage(): {filename}: the name must end in .png (or .jpg in Webots)", file=sys.stderr)
        return -1
    if not 1 <= quality <= 100:
        print(f"Error: Camera.saveImage(): 'quality' argument ({quality}) must be between 1 and 100.", file=sys.stderr)
        return -1
    image = cam.getImage()
    if image is None:
        print("Error: Camera.saveImage(): no image: enable the camera first", file=sys.stderr)
        return -1
    import numpy as np
    from ._png import write_png
    bgra = np.frombuffer(image, dtype=np.uint8).reshape(camera.HEIGHT_PX, camera.WIDTH_PX, 4)
    try:
        write_png(filename, np.ascontiguousarray(bgra[:, :, 2::-1]))
    except OSError as e:
        print(f"Error: Camera.saveImage(): cannot write {filename}: {e.strerror}", file=sys.stderr)
        return -1
    return 0


def _set_fov(cam, fov):
    """Webots' Camera.setFov: within [getMinFov(), getMaxFov()], which a camera without a Zoom
    node (the course HamBot's) has both at its fieldOfView."""
    lowest, highest = cam.getMinFov(), cam.getMaxFov()
    if not lowest <= fov <= highest:
        print(f"Error: wb_camera_set_fov() out of zoom range [{lowest:f}, {highest:f}].", file=sys.stderr)


def add_camera_methods():
    camera = _camera()
    camera.Camera.saveImage = _save_image
    camera.Camera.setFov = _set_fov
    camera.Camera.getMinFov = lambda cam: camera.FOV_RAD
    camera.Camera.getMaxFov = lambda cam: camera.FOV_RAD
    camera.Camera.fov = property(lambda cam: cam.getFov(), _set_fov)
