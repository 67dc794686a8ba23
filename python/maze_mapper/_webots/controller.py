# `controller` for a controller run by maze_mapper.run: Webots' module name, maze_mapper's API.
from maze_mapper.controller import *  # noqa: F401,F403
from maze_mapper.controller import __getattr__  # noqa: F401
