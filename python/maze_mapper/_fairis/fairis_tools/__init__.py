# The course's student package (fairis_tools), for controllers run by maze_mapper.run where the
# course's own is not on the path.
