# `from fairis_lib.robot_lib.hambot import HamBot` in a controller run by maze_mapper.run: the
# course robot's helpers over the embedded simulator (maze_mapper/hambot.py).
from maze_mapper.hambot import HamBot  # noqa: F401
