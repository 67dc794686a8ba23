"""Webots' Python controller API (the `controller` module of Webots R2023b and later) over
maze_mapper's embedded simulator: Robot and the devices Lidar, Motor, PositionSensor,
InertialUnit, GPS, DistanceSensor and TouchSensor, with Webots' method names and semantics.

Under `python3 -m maze_mapper.run CONTROLLER.py --world WORLD`, `from controller import Robot`
imports this module, so a Webots controller that uses only these devices runs unchanged.
Where it differs from Webots (docs/python.md): Lidar.getRangeImage() returns a RangeImage,
which behaves as Webots' list of floats without making a Python float of every beam until one
is asked for (np.asarray(image) is the float32 array itself); a disabled sensor reads NaN (a
disabled lidar None); and there is no Supervisor, Camera, Display, Keyboard or point cloud:
the controller sees the devices, never the maze.
"""

import sys
from collections.abc import Sequence

from . import _native

Device = _native.Device
Lidar = _native.Lidar
Motor = _native.Motor
PositionSensor = _native.PositionSensor
InertialUnit = _native.InertialUnit
GPS = _native.GPS
DistanceSensor = _native.DistanceSensor
TouchSensor = _native.TouchSensor

class RangeImage(Sequence):
    """A lidar range image as Webots' Python API hands it, a list of floats (m; inf for no
    return), kept as one float32 array: indexing gives a float, slicing a list, `+` joins as
    lists do, iteration, len, min, index and count work as on a list, and np.asarray(image)
    (or image.array) is the array itself, read-only, no copy."""

    __slots__ = ("_array",)

    def __init__(self, array):
        self._array = array
        array.flags.writeable = False

    @property
    def array(self):
        return self._array

    def __len__(self):
        return self._array.shape[0]

    def __getitem__(self, index):
        if isinstance(index, slice):
            return self._array[index].tolist()
        return float(self._array[index])

    def __iter__(self):
        return iter(self._array.tolist())

    def __add__(self, other):
        return self._array.tolist() + list(other)

    def __radd__(self, other):
        return list(other) + self._array.tolist()

    def __eq__(self, other):
        if isinstance(other, (list, tuple, RangeImage)):
            return self._array.tolist() == list(other)
        return NotImplemented

    __hash__ = None

    def __array__(self, dtype=None, copy=None):
        return self._array if dtype is None else self._array.astype(dtype, copy=False)

    def __repr__(self):
        return repr(self._array.tolist())


def _get_range_image(lidar):
    """The range image (a RangeImage), or None when the lidar is disabled."""
    array = lidar._range_image()
    return None if array is None else RangeImage(array)


_native.Lidar.getRangeImage = _get_range_image
_native.Lidar.range_image = property(_get_range_image)

__all__ = ["Robot", "Device", "Lidar", "Motor", "PositionSensor", "InertialUnit", "GPS",
           "DistanceSensor", "TouchSensor", "RangeImage", "SimulationEnded"]

_SUPPORTED = ("Robot", "Lidar", "Motor", "PositionSensor", "InertialUnit", "GPS",
              "DistanceSensor", "TouchSensor")


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
        self.devices = {name: self._handle.device(name) for name in self._handle.device_names()}
        self._names = list(self.devices)

    # ---- time ----

    def step(self, time_step=None):
        """Advances the simulation by time_step ms (default: the basic time step); returns -1
        once the simulation has ended (the runner's time limit), else 0."""
        if time_step is None:
            time_step = int(self._handle.getBasicTimeStep())
        if self._ended:
            raise SimulationEnded(0)
        result = self._handle.step(time_step)
        if result == -1:
            self._ended = True
        return result

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


def __getattr__(name):
    # `from controller import Supervisor` (or Camera, Keyboard, ...): say what exists here.
    if name.startswith("_"):
        raise AttributeError(name)
    raise ImportError(
        f"maze_mapper's controller module has no {name}: the embedded simulator offers "
        f"{', '.join(_SUPPORTED)} (docs/python.md)")
