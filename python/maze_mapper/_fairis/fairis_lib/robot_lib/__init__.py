# The course library's robot package, for controllers run by maze_mapper.run.
