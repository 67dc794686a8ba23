# The course library's package name, for controllers run by maze_mapper.run (see robot_lib/hambot.py).
